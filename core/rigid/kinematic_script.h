#pragma once
// Scripted motion of a kinematic obstacle or tool. Two kinds:
//  - keyframes: poses at given times, translation interpolated linearly and rotation by slerp
//    between neighbouring keys, held before the first key and after the last;
//  - constant velocity: a start pose at t = 0 moved by a constant linear velocity and turned at a
//    constant angular velocity about the body-frame origin (defined for any t, also t < 0).
// A script moves the body-frame origin: for a tool modelled around its grip, the grip; for a body
// recentred at its centre of mass, the centre of mass.
#include <variant>
#include <vector>

#include "rigid/rigid_pose.h"
#include "util/types.h"

namespace weft {

struct PoseKey {
  double time = 0.0;              // s
  Vec3 translate = Vec3::Zero();  // m, world position of the body-frame origin
  Vec3 rotateDeg = Vec3::Zero();  // rotation about world x, then y, then z (degrees), as the cloth Placement
};

// Keys in strictly increasing time, at least one. Slerp takes the short way between neighbouring
// keys: a turn of 180 degrees or more between two keys needs a key in between.
struct KeyframeMotion {
  std::vector<PoseKey> keys;
};

struct ConstantVelocityMotion {
  Vec3 translate = Vec3::Zero();           // m, position of the body-frame origin at t = 0
  Vec3 rotateDeg = Vec3::Zero();           // orientation at t = 0, as PoseKey::rotateDeg
  Vec3 linearVelocity = Vec3::Zero();      // m/s
  Vec3 angularVelocityDeg = Vec3::Zero();  // deg/s, world frame: a rotation about this axis at |ω| deg/s
};

using KinematicScript = std::variant<KeyframeMotion, ConstantVelocityMotion>;

RigidPose poseAt(const KinematicScript& script, double time);

// The motion over [t0, t1] (t1 > t0) as contact uses it: each body-frame point moves in a straight
// line from its position at t0 to its position at t1 (see PoseChange).
PoseChange motionBetween(const KinematicScript& script, double t0, double t1);

}  // namespace weft
