#pragma once
// What the mouse does in the editor's viewport, besides the orbit camera: grab a cloth vertex and
// drag it (a spring to the cursor, so a user can tear cloth by hand), drag a kinematic tool, tag
// a tool's vertex or edge sharp, throw a ball from the camera. No ImGui and no GL: it turns mouse
// positions (window pixels) into rays and calls the World's interaction API, so tests drive it.
//
// Left press on a cloth grabs its nearest vertex; on a kinematic tool with Alt held, drags the
// tool; in tag mode, toggles the tool's feature under the cursor (tag_picking.h: the one
// highlighted before the click, an edge when the cursor is on its segment). A press on nothing
// leaves the mouse to the orbit camera. With a tear strength brush set (setPaintBrush), a left
// drag that starts on a cloth paints that cloth's strength instead of grabbing it (one stroke, one
// undo step); a press on nothing still orbits.
#include <optional>

#include "editor/editor_session.h"
#include "editor/sharp_tag_edits.h"
#include "editor/strength_painting.h"
#include "editor/tag_picking.h"
#include "orbit_camera.h"
#include "window_input.h"

namespace weft::editor {

struct ViewportSettings {
  double grabStiffness = 60.0;         // N/m: the cloth follows a gentle drag and tears under a long one
  double ballSpeed = 12.0;             // m/s, thrown along the view ray
  double ballRadius = 0.08;            // m
  double ballMass = 1.0;               // kg
  double tagTolerancePixels = 8.0;     // how near a vertex or edge a click must be to tag it
};

// The modifier keys held during a frame.
struct ViewportKeys {
  bool alt = false;    // Alt + drag moves a kinematic tool
  bool shift = false;  // in tag mode, Shift + drag draws a box that tags every edge inside
};

// A screen rectangle being dragged out, pixels in the viewport.
struct DragBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Where a left drag would paint now, for the app to draw as a circle: the cursor (viewport
// pixels) and the brush's radius in pixels there. The radius is the brush's material radius at the
// cursor's depth, taken at rest scale (a stretched cloth paints a little less wide on screen).
struct BrushOutline {
  double x = 0, y = 0;
  double radiusPixels = 0;
};

class ViewportInteraction {
 public:
  explicit ViewportInteraction(ViewportSettings settings = {}) : settings_(settings) {}

  // Handles a frame's mouse state in a viewport of width x height pixels. Returns true when the
  // mouse is taken (grabbing, dragging a tool, tagging): the orbit camera must not use it.
  // `tagMode`: clicks on a tool toggle sharp tags in `tags` (the document of that tool's tags).
  bool update(EditorSession& session, const ui::OrbitCamera& camera, const ui::MouseState& mouse, ViewportKeys keys,
              int width, int height, ToolTagEditor* tags = nullptr);

  // Throws a ball from the eye through the point (x, y) of the viewport.
  void throwBall(EditorSession& session, const ui::OrbitCamera& camera, double x, double y, int width, int height) const;

  bool grabbing() const { return mode_ == Mode::Grab || mode_ == Mode::Paint; }
  // The brush a left drag on a cloth paints with (not owned; none: the drag grabs).
  void setPaintBrush(const StrengthBrush* brush) { paintBrush_ = brush; }
  bool painting() const { return mode_ == Mode::Paint; }
  // With a brush set and the cursor over a cloth (or painting): the brush's outline.
  const std::optional<BrushOutline>& brushOutline() const { return brushOutline_; }
  // In tag mode: the tool's feature a click would toggle now (drawn highlighted), if any.
  const std::optional<TagTarget>& hovered() const { return hovered_; }
  // The box being dragged in tag mode (Shift + drag), for the app to draw.
  std::optional<DragBox> box() const { return mode_ == Mode::Box ? std::optional<DragBox>(box_) : std::nullopt; }

 private:
  enum class Mode { Idle, Grab, DragTool, Orbit, Box, Paint };
  // Dabs from the last material point painted to `to`, a quarter of the radius apart.
  void paintTo(EditorSession& session, const Vec2& to);
  // Where the cursor's ray meets the plane through `anchor` facing the camera.
  static Vec3 onDragPlane(const ui::OrbitCamera& camera, const Vec3& anchor, const Vec3& origin, const Vec3& dir);

  ViewportSettings settings_;
  Mode mode_ = Mode::Idle;
  bool wasDown_ = false;
  Vec3 anchor_ = Vec3::Zero();     // grabbed point or tool point under the cursor at the press
  Vec3 toolOffset_ = Vec3::Zero(); // tool position minus anchor
  int tool_ = -1;
  std::optional<TagTarget> hovered_;
  DragBox box_;
  const StrengthBrush* paintBrush_ = nullptr;
  int paintCloth_ = -1;
  Vec2 lastDab_ = Vec2::Zero();
  std::optional<BrushOutline> brushOutline_;
};

}  // namespace weft::editor
