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
  // The rotation taking start to end in the world frame. Eigen's AngleAxis takes its angle in
  // [0, pi] whatever the quaternion's sign, so this is the shortest turn (kinematic_script_test).
  const Eigen::AngleAxisd axisAngle((end.orientation * start.orientation.conjugate()).normalized());
  return axisAngle.axis() * (axisAngle.angle() / duration);
}

}  // namespace weft
