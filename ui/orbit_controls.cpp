#include "orbit_controls.h"

#include <algorithm>
#include <cmath>

namespace weft::ui {
namespace {
constexpr double kPi = 3.14159265358979323846;

// The camera's screen-right and screen-up directions in the world, built as OrbitCamera::view()
// builds them but kept in double (view() is float, too coarse for small pans far away).
void screenAxes(const OrbitCamera& camera, Vec3& outSide, Vec3& outUp) {
  const Vec3 forward = (camera.target - camera.eye()).normalized();
  Vec3 up(0, 1, 0);
  if (std::abs(forward.dot(up)) > 0.999) up = Vec3(0, 0, -1);  // looking straight down or up
  outSide = forward.cross(up).normalized();
  outUp = outSide.cross(forward);
}

}  // namespace

void orbitBy(OrbitCamera& camera, double dx, double dy, const OrbitControlSettings& settings) {
  // Dragging right turns the scene right, so the eye goes left (yaw decreases); dragging down
  // pulls the scene's near side down, so the eye rises (pitch increases).
  camera.yawDeg = std::remainder(camera.yawDeg - dx * settings.degreesPerPixel, 360.0);
  camera.pitchDeg = std::clamp(camera.pitchDeg + dy * settings.degreesPerPixel, -settings.maxPitchDeg,
                               settings.maxPitchDeg);
}

void panBy(OrbitCamera& camera, double dx, double dy, double viewportHeight) {
  if (viewportHeight <= 0.0) return;
  Vec3 side, up;
  screenAxes(camera, side, up);
  const double metresPerUnit = 2.0 * camera.distance * std::tan(camera.fovYDeg * kPi / 360.0) / viewportHeight;
  // The scene moves with the cursor, so the target moves against it (window y points down).
  camera.target += metresPerUnit * (-dx * side + dy * up);
}

void zoomBy(OrbitCamera& camera, double clicks, const OrbitControlSettings& settings) {
  camera.distance = std::max(settings.minDistance, camera.distance * std::pow(settings.zoomPerClick, clicks));
  // The near plane follows, so zooming in does not cut into the cloth; the far plane only grows.
  camera.nearPlane = std::max(1e-4, 0.01 * camera.distance);
  camera.farPlane = std::max(camera.farPlane, 50.0 * camera.distance);
}

void OrbitControls::update(OrbitCamera& camera, const MouseState& mouse, double viewportHeight) {
  if (previous_) {
    const double dx = mouse.x - previous_->x;
    const double dy = mouse.y - previous_->y;
    if (mouse.left && previous_->left) {
      orbitBy(camera, dx, dy, settings_);
    } else if ((mouse.right && previous_->right) || (mouse.middle && previous_->middle)) {
      panBy(camera, dx, dy, viewportHeight);
    }
  }
  if (mouse.scrollY != 0.0) zoomBy(camera, mouse.scrollY, settings_);
  previous_ = mouse;
}

}  // namespace weft::ui
