#pragma once
// Draws a RenderView with OpenGL 3.3 core: cloths shaded on both sides with a procedural woven
// texture that follows weft and warp, torn edges red and cut edges green on top, obstacles grey
// with their sharp edges and vertices red, and the ground as a light plane with a grid.
// Needs a current GL context (HeadlessGlContext, or later the editor's window).
#include <array>
#include <memory>

#include "orbit_camera.h"
#include "render_view.h"

namespace weft::ui {

struct RenderSettings {
  std::array<float, 3> background{0.93f, 0.94f, 0.96f};  // RGB of the empty image
  std::array<float, 3> lightDirection{0.35f, 0.8f, 0.5f}; // towards the light (world, normalized when used)
  float lineWidth = 2.0f;       // px: torn, cut and sharp edges
  bool markTornAndCutEdges = true;  // false: a tear shows only as the hole it opens (the user study's clips)
};

class SceneRenderer {
 public:
  explicit SceneRenderer(const RenderSettings& settings = RenderSettings{});  // compiles the shaders
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  RenderSettings& settings() { return settings_; }

  // Clears the bound framebuffer (viewport width x height) and draws the view.
  void draw(const RenderView& view, const OrbitCamera& camera, int width, int height);

 private:
  struct Gl;
  RenderSettings settings_;
  std::unique_ptr<Gl> gl_;
};

}  // namespace weft::ui
