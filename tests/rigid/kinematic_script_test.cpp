// Kinematic scripts (keyframes, constant velocity), the rotation convention, and the step motion
// contact uses.
#include "rigid/kinematic_script.h"

#include <cmath>

#include <gtest/gtest.h>

namespace weft {
namespace {

using Eigen::AngleAxisd;
using Eigen::Quaterniond;

void expectVecNear(const Vec3& actual, const Vec3& expected, double tolerance) {
  EXPECT_LE((actual - expected).norm(), tolerance)
      << "actual " << actual.transpose() << ", expected " << expected.transpose();
}

void expectRotationNear(const Quaterniond& actual, const Quaterniond& expected, double tolerance) {
  EXPECT_LE(actual.angularDistance(expected), tolerance)
      << "actual " << actual.coeffs().transpose() << ", expected " << expected.coeffs().transpose();
}

Quaterniond aboutZ(double degrees) { return Quaterniond(AngleAxisd(degToRad(degrees), Vec3::UnitZ())); }

// The cloth Placement's convention: about world x first, then y, then z.
TEST(KinematicScript, RotationFromDegreesTurnsAboutXThenYThenZ) {
  // y --(90 about x)--> z --(90 about y)--> x --(90 about z)--> y
  expectVecNear(rotationFromDegrees(Vec3(90, 0, 0)) * Vec3::UnitY(), Vec3::UnitZ(), 1e-15);
  expectVecNear(rotationFromDegrees(Vec3(90, 90, 0)) * Vec3::UnitY(), Vec3::UnitX(), 1e-15);
  expectVecNear(rotationFromDegrees(Vec3(90, 90, 90)) * Vec3::UnitY(), Vec3::UnitY(), 1e-15);
  // The other order would give a different answer.
  expectVecNear(rotationFromDegrees(Vec3(90, 90, 0)) * Vec3::UnitZ(), -Vec3::UnitY(), 1e-15);
}

TEST(KinematicScript, KeyframesInterpolateLinearlyAndBySlerp) {
  const KinematicScript script = KeyframeMotion{{{1.0, Vec3(0, 0, 0), Vec3(0, 0, 0)},
                                                 {3.0, Vec3(2, 4, -2), Vec3(0, 0, 90)},
                                                 {4.0, Vec3(2, 4, 0), Vec3(0, 0, 90)}}};
  const RigidPose mid = poseAt(script, 2.0);
  expectVecNear(mid.position, Vec3(1, 2, -1), 1e-15);
  expectRotationNear(mid.orientation, aboutZ(45), 1e-15);
  const RigidPose quarter = poseAt(script, 1.5);
  expectVecNear(quarter.position, Vec3(0.5, 1, -0.5), 1e-15);
  expectRotationNear(quarter.orientation, aboutZ(22.5), 1e-15);  // slerp: constant angular speed
  expectVecNear(poseAt(script, 3.5).position, Vec3(2, 4, -1), 1e-15);
  // Exactly at a key.
  expectVecNear(poseAt(script, 3.0).position, Vec3(2, 4, -2), 0.0);
}

TEST(KinematicScript, KeyframesAreHeldBeforeTheFirstAndAfterTheLast) {
  const KinematicScript script =
      KeyframeMotion{{{1.0, Vec3(1, 2, 3), Vec3(10, 0, 0)}, {2.0, Vec3(4, 5, 6), Vec3(0, 30, 0)}}};
  for (const double t : {-5.0, 0.0, 1.0}) {
    expectVecNear(poseAt(script, t).position, Vec3(1, 2, 3), 0.0);
    expectRotationNear(poseAt(script, t).orientation, rotationFromDegrees(Vec3(10, 0, 0)), 1e-15);
  }
  for (const double t : {2.0, 2.5, 100.0}) {
    expectVecNear(poseAt(script, t).position, Vec3(4, 5, 6), 0.0);
    expectRotationNear(poseAt(script, t).orientation, rotationFromDegrees(Vec3(0, 30, 0)), 1e-15);
  }
  const KinematicScript single = KeyframeMotion{{{0.5, Vec3(1, 1, 1), Vec3(0, 0, 45)}}};
  expectVecNear(poseAt(single, 7.0).position, Vec3(1, 1, 1), 0.0);
}

// From 170 to -170 degrees about z the short way is through 180 (20 degrees), not through 0 (340).
TEST(KinematicScript, SlerpTakesTheShortWay) {
  const KinematicScript script =
      KeyframeMotion{{{0.0, Vec3::Zero(), Vec3(0, 0, 170)}, {1.0, Vec3::Zero(), Vec3(0, 0, -170)}}};
  expectRotationNear(poseAt(script, 0.5).orientation, aboutZ(180), 1e-14);
  expectRotationNear(poseAt(script, 0.25).orientation, aboutZ(175), 1e-14);
  // Also when the two keys' quaternions have opposite signs for nearby rotations.
  const KinematicScript wrapped =
      KeyframeMotion{{{0.0, Vec3::Zero(), Vec3(0, 0, 350)}, {1.0, Vec3::Zero(), Vec3(0, 0, 10)}}};
  expectRotationNear(poseAt(wrapped, 0.5).orientation, aboutZ(0), 1e-14);
}

TEST(KinematicScript, ConstantVelocityPath) {
  ConstantVelocityMotion motion;
  motion.translate = Vec3(1, 0, 0);
  motion.rotateDeg = Vec3(0, 0, 30);
  motion.linearVelocity = Vec3(0, -2, 0.5);
  motion.angularVelocityDeg = Vec3(0, 90, 0);  // a quarter turn about world y per second
  const KinematicScript script = motion;
  for (const double t : {0.0, 0.5, 2.0, -1.0}) {
    const RigidPose pose = poseAt(script, t);
    expectVecNear(pose.position, Vec3(1, -2 * t, 0.5 * t), 1e-15);
    const Quaterniond expected = Quaterniond(AngleAxisd(degToRad(90 * t), Vec3::UnitY())) * aboutZ(30);
    expectRotationNear(pose.orientation, expected, 1e-15);
  }
  // The rotation is about the body-frame origin: the origin itself only translates.
  expectVecNear(poseAt(script, 2.0).toWorld(Vec3::Zero()), Vec3(1, -4, 1), 1e-15);
  // A body point one metre along body x turns with the body.
  const Vec3 arm = poseAt(script, 1.0).toWorld(Vec3::UnitX()) - poseAt(script, 1.0).position;
  expectVecNear(arm, AngleAxisd(kPi / 2, Vec3::UnitY()) * (aboutZ(30) * Vec3::UnitX()), 1e-15);
}

// Over a step, every body point moves in a straight line from pose(t0) to pose(t1): moving by
// pointVelocity * (t1 - t0) lands exactly on the end pose.
TEST(KinematicScript, StepMotionMovesBodyPointsFromPoseToPose) {
  ConstantVelocityMotion motion;
  motion.translate = Vec3(0, 1, 0);
  motion.linearVelocity = Vec3(0.2, 0, 0);
  motion.angularVelocityDeg = Vec3(0, 0, 180);
  const KinematicScript script = motion;
  const double t0 = 0.3, t1 = 0.35;
  const PoseChange step = motionBetween(script, t0, t1);
  EXPECT_EQ(step.duration, t1 - t0);
  const Vec3 bodyPoint(0.5, -0.2, 0.1);
  const Vec3 start = poseAt(script, t0).toWorld(bodyPoint), end = poseAt(script, t1).toWorld(bodyPoint);
  expectVecNear(start + step.pointVelocity(start) * (t1 - t0), end, 1e-15);
  // The rigid description: the script's own velocities.
  expectVecNear(step.linearVelocity(), Vec3(0.2, 0, 0), 1e-13);
  expectVecNear(step.angularVelocity(), Vec3(0, 0, kPi), 1e-12);
  // ...which differ from the chord velocity only by the arc-versus-chord term O(|ω|² h r).
  const Vec3 rigid = step.linearVelocity() + step.angularVelocity().cross(start - step.start.position);
  const double r = (start - step.start.position).norm();
  EXPECT_LE((rigid - step.pointVelocity(start)).norm(), kPi * kPi * (t1 - t0) * r);
  EXPECT_GT((rigid - step.pointVelocity(start)).norm(), 0.0);
}

TEST(KinematicScript, StepAngularVelocityTakesTheShortWayBetweenKeys) {
  const KinematicScript script =
      KeyframeMotion{{{0.0, Vec3::Zero(), Vec3(0, 0, 170)}, {1.0, Vec3::Zero(), Vec3(0, 0, -170)}}};
  const PoseChange step = motionBetween(script, 0.0, 1.0);
  expectVecNear(step.angularVelocity(), Vec3(0, 0, degToRad(20)), 1e-13);
  expectVecNear(motionBetween(script, 2.0, 3.0).angularVelocity(), Vec3::Zero(), 0.0);  // held
}

}  // namespace
}  // namespace weft
