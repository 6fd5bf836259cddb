#pragma once
// The part of the editor's window the scene is drawn in: between the left column of panels and
// the right one, above the status bar, so that the panels do not hide the cloth. The panels can
// still be moved over it.
#include "orbit_camera.h"
#include "render_view.h"
#include "scene_renderer.h"

namespace weft::editor {

// The window's layout: a menu bar along the top, panels in a column on each side, a status bar
// along the bottom (pixels).
inline constexpr int kPanelMargin = 8;
inline constexpr int kLeftColumnWidth = 316;   // left panels 300 wide, with margins
inline constexpr int kRightColumnWidth = 476;  // right panels 460 wide, with margins
inline constexpr int kStatusBarHeight = 24;
inline constexpr int kMenuBarHeight = 19;  // the main menu bar along the top (ImGui's default font)

struct ViewportRect {
  int x = 0, y = 0;           // top-left corner, pixels from the window's top-left
  int width = 1, height = 1;  // pixels
  double aspect() const { return static_cast<double>(width) / height; }
  bool contains(double px, double py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

// The scene's rectangle in a display of the given size (falls back to the whole display when
// the window is too narrow for the columns).
ViewportRect sceneViewport(int displayWidth, int displayHeight);

// F: a camera looking the way `current` looks, framing the selected obstacle (`obstacle` >= 0)
// or else the cloths and obstacles as they are now (the view's action box).
ui::OrbitCamera frameSelection(const ui::RenderView& view, int obstacle, const ui::OrbitCamera& current, double aspect);

// Clears the bound framebuffer (displayWidth x displayHeight) to the background and draws the
// view into `rect` only.
void drawSceneViewport(ui::SceneRenderer& renderer, const ui::RenderView& view, const ui::OrbitCamera& camera,
                       const ViewportRect& rect, int displayWidth, int displayHeight);

}  // namespace weft::editor
