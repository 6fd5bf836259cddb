#pragma once
// Where a rigid body is, and how it moved over a step. A pose maps a body-frame point x to the
// world point R x + p, with R the orientation and p the position of the body-frame origin.
#include <Eigen/Geometry>

#include "util/types.h"

namespace weft {

struct RigidPose {
  Vec3 position = Vec3::Zero();                                     // m, world position of the body-frame origin
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // unit; body frame -> world

  Vec3 toWorld(const Vec3& bodyPoint) const { return orientation * bodyPoint + position; }
  Vec3 toBody(const Vec3& worldPoint) const { return orientation.conjugate() * (worldPoint - position); }
};

// Rotation about world x, then y, then z by the given angles (degrees): the convention of the
// cloth Placement (scene.h), so a tool and a cloth are placed alike.
Eigen::Quaterniond rotationFromDegrees(const Vec3& rotateDeg);

// How a body moved from pose `start` to pose `end` over `duration` seconds, as contact sees it:
// every body-frame point x travels in a straight line from start.toWorld(x) to end.toWorld(x) at
// constant speed (the per-vertex linear motion that continuous collision detection assumes).
struct PoseChange {
  RigidPose start;
  RigidPose end;
  double duration = 1.0;  // s, > 0

  // The velocity of the body point that is at `worldPointAtStart` at the start: its displacement
  // over the step divided by the duration. This is the obstacle velocity to use in a contact
  // response, consistent with the straight-line paths collision detection assumed.
  Vec3 pointVelocity(const Vec3& worldPointAtStart) const;
  // The rigid-body description of the same motion: the body-frame origin's velocity and the
  // constant angular velocity (rad/s, world) that turns start.orientation into end.orientation.
  // linearVelocity() + angularVelocity() x (y - start.position) differs from pointVelocity(y) by
  // O(|ω|² duration |y - start.position|): an arc versus its chord.
  Vec3 linearVelocity() const;
  Vec3 angularVelocity() const;
};

}  // namespace weft
