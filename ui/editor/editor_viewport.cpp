#include "editor_viewport.h"

#include <GL/gl.h>

#include <algorithm>

namespace weft::editor {

ViewportRect sceneViewport(int displayWidth, int displayHeight) {
  ViewportRect rect{kLeftColumnWidth, kMenuBarHeight, displayWidth - kLeftColumnWidth - kRightColumnWidth,
                    displayHeight - kMenuBarHeight - kStatusBarHeight};
  if (rect.width < 200 || rect.height < 100) rect = ViewportRect{0, 0, std::max(displayWidth, 1), std::max(displayHeight, 1)};
  return rect;
}

ui::OrbitCamera frameSelection(const ui::RenderView& view, int obstacle, const ui::OrbitCamera& current, double aspect) {
  Vec3 lo = Vec3::Constant(1e30), hi = Vec3::Constant(-1e30);
  if (obstacle >= 0 && obstacle < static_cast<int>(view.obstacles.size()) &&
      !view.obstacles[static_cast<std::size_t>(obstacle)].vertices.empty()) {
    for (const Vec3& v : view.obstacles[static_cast<std::size_t>(obstacle)].vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  } else {
    ui::actionBox(view, lo, hi);
  }
  ui::OrbitCamera framed = ui::frameBox(lo, hi, aspect, current.yawDeg, current.pitchDeg);
  framed.fovYDeg = current.fovYDeg;
  return framed;
}

void drawSceneViewport(ui::SceneRenderer& renderer, const ui::RenderView& view, const ui::OrbitCamera& camera,
                       const ViewportRect& rect, int displayWidth, int displayHeight) {
  const auto& background = renderer.settings().background;
  glViewport(0, 0, displayWidth, displayHeight);
  glClearColor(background[0], background[1], background[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // GL counts rows from the bottom.
  const int bottom = displayHeight - (rect.y + rect.height);
  glViewport(rect.x, bottom, rect.width, rect.height);
  glScissor(rect.x, bottom, rect.width, rect.height);
  glEnable(GL_SCISSOR_TEST);
  renderer.draw(view, camera, rect.width, rect.height);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, displayWidth, displayHeight);
}

}  // namespace weft::editor
