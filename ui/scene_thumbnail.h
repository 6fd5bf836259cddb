#pragma once
// A small picture of a scene as it starts (t = 0), drawn by the same renderer and camera as
// `weft run --png`'s first frame: what the editor's scene browser shows beside each scene.
// Needs a current GL context (the editor's window, or HeadlessGlContext).
#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "scene_renderer.h"

namespace weft::ui {

// Builds the scene's world (which may throw what World's constructor throws), frames it with the
// scene's output camera for a width x height image and returns its pixels, RGBA8, rows top-down.
// Leaves the draw framebuffer unbound (the caller binds its own).
std::vector<std::uint8_t> renderSceneThumbnail(const Scene& scene, SceneRenderer& renderer, int width, int height);

}  // namespace weft::ui
