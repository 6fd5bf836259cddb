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
