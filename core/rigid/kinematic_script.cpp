#include "rigid/kinematic_script.h"

#include <algorithm>
#include <cassert>

namespace weft {

namespace {

RigidPose poseOf(const PoseKey& key) { return {key.translate, rotationFromDegrees(key.rotateDeg)}; }

RigidPose keyframePose(const KeyframeMotion& motion, double time) {
  const std::vector<PoseKey>& keys = motion.keys;
  assert(!keys.empty());
  if (time <= keys.front().time) return poseOf(keys.front());
  if (time >= keys.back().time) return poseOf(keys.back());
  // The first key after `time`; the one before it exists since time > keys.front().time.
  const auto after =
      std::upper_bound(keys.begin(), keys.end(), time, [](double t, const PoseKey& key) { return t < key.time; });
  const PoseKey& a = *(after - 1);
  const PoseKey& b = *after;
  assert(b.time > a.time);
  const double s = (time - a.time) / (b.time - a.time);
  const RigidPose from = poseOf(a), to = poseOf(b);
  RigidPose pose;
  pose.position = (1.0 - s) * from.position + s * to.position;
  // Eigen's slerp already picks the shorter arc (it flips the sign of one quaternion when their
  // dot product is negative); kinematic_script_test pins that behaviour.
  pose.orientation = from.orientation.slerp(s, to.orientation).normalized();
  return pose;
}

RigidPose constantVelocityPose(const ConstantVelocityMotion& motion, double time) {
  RigidPose pose;
  pose.position = motion.translate + motion.linearVelocity * time;
  const Vec3 omega = motion.angularVelocityDeg * (kPi / 180.0);  // rad/s
  const double speed = omega.norm();
  const Eigen::Quaterniond start = rotationFromDegrees(motion.rotateDeg);
  pose.orientation =
      speed == 0.0 ? start : (Eigen::Quaterniond(Eigen::AngleAxisd(speed * time, omega / speed)) * start).normalized();
  return pose;
}

}  // namespace

RigidPose poseAt(const KinematicScript& script, double time) {
  if (const auto* keys = std::get_if<KeyframeMotion>(&script)) return keyframePose(*keys, time);
  return constantVelocityPose(std::get<ConstantVelocityMotion>(script), time);
}

PoseChange motionBetween(const KinematicScript& script, double t0, double t1) {
  assert(t1 > t0);
  return {poseAt(script, t0), poseAt(script, t1), t1 - t0};
}

}  // namespace weft
