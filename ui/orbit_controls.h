#pragma once
// Mouse to orbit camera, as a 3D viewer's users expect it: left drag orbits around the target,
// right or middle drag pans the target in the view plane, the wheel zooms. No GL and no window:
// it reads plain MouseState, so tests drive it with made-up drags.
#include <optional>

#include "orbit_camera.h"
#include "window_input.h"

namespace weft::ui {

struct OrbitControlSettings {
  double degreesPerPixel = 0.3;  // orbit: yaw and pitch change per pixel dragged
  double zoomPerClick = 0.9;     // distance multiplied by this per wheel click towards the scene
  double maxPitchDeg = 89.0;     // |pitch| limit: at 90 the view direction would meet world up
  double minDistance = 1e-3;     // m: zoom never brings the eye closer to the target than this
};

// The changes themselves, usable without a mouse (keyboard shortcuts, scripted cameras).
// Drag amounts are in the mouse's units (window coordinates, y down).
void orbitBy(OrbitCamera& camera, double dx, double dy, const OrbitControlSettings& settings);
// Moves the target so that the scene follows the cursor: a drag across the whole viewport height
// moves it by the height the view spans at the target's depth.
void panBy(OrbitCamera& camera, double dx, double dy, double viewportHeight);
void zoomBy(OrbitCamera& camera, double clicks, const OrbitControlSettings& settings);

class OrbitControls {
 public:
  explicit OrbitControls(const OrbitControlSettings& settings = OrbitControlSettings{}) : settings_(settings) {}

  // Applies what the mouse did since the previous call. `viewportHeight` is the window's height
  // in the mouse's units. A drag counts from the second poll a button is held, so pressing a
  // button never jumps the camera.
  void update(OrbitCamera& camera, const MouseState& mouse, double viewportHeight);

 private:
  OrbitControlSettings settings_;
  std::optional<MouseState> previous_;
};

}  // namespace weft::ui
