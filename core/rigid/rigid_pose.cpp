#include "rigid/rigid_pose.h"

#include <cassert>

namespace weft {

Eigen::Quaterniond rotationFromDegrees(const Vec3& rotateDeg) {
  using Eigen::AngleAxisd;
  // Applied right to left: x first, then y, then z (the same product as the cloth placement).
  return Eigen::Quaterniond(AngleAxisd(degToRad(rotateDeg.z()), Vec3::UnitZ()) *
                            AngleAxisd(degToRad(rotateDeg.y()), Vec3::UnitY()) *
                            AngleAxisd(degToRad(rotateDeg.x()), Vec3::UnitX()));
}

Vec3 PoseChange::pointVelocity(const Vec3& worldPointAtStart) const {
  assert(duration > 0.0);
  return (end.toWorld(start.toBody(worldPointAtStart)) - worldPointAtStart) / duration;
}

Vec3 PoseChange::linearVelocity() const {
  assert(duration > 0.0);
  return (end.position - start.position) / duration;
}

Vec3 PoseChange::angularVelocity() const {
  assert(duration > 0.0);
  // The rotation taking start to end in the world frame, by its shortest angle.
  Eigen::Quaterniond turn = end.orientation * start.orientation.conjugate();
  if (turn.w() < 0.0) turn.coeffs() = -turn.coeffs();
  const Eigen::AngleAxisd axisAngle(turn.normalized());
  return axisAngle.axis() * (axisAngle.angle() / duration);
}

}  // namespace weft
