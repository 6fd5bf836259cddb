#include "scene_thumbnail.h"

#include "offscreen_framebuffer.h"
#include "render_view.h"
#include "sim/world.h"

namespace weft::ui {

std::vector<std::uint8_t> renderSceneThumbnail(const Scene& scene, SceneRenderer& renderer, int width, int height) {
  const World world(scene);
  const RenderView view = renderViewOf(world);
  const OrbitCamera camera = defaultCamera(view, scene.output.camera, static_cast<double>(width) / height);
  const OffscreenFramebuffer framebuffer(width, height, 4);
  framebuffer.bind();
  renderer.draw(view, camera, width, height);
  return framebuffer.readPixels();
}

}  // namespace weft::ui
