// The editor's interaction with a running world: a ball thrown in collides with the cloth, a grab
// survives tears, a kinematic tool follows a hand-given position.
#include <gtest/gtest.h>

#include "contact/obstacle.h"
#include "support/contact_checks.h"
#include "support/test_scenes.h"
#include "sim/world.h"

namespace weft {
namespace {

std::vector<std::array<int, 3>> obstacleTriangles(const Obstacle& o) { return o.topology.triangles; }

TEST(ThrowBall, HitsPinnedSheetWithoutTunnelling) {
  // The sheet hangs in the x-y plane (x, y in [0, 1], z = 0) from its top corners.
  Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-5), 12, 1.0 / 120);
  World world(scene);
  for (int s = 0; s < 30; ++s) world.step();  // let it settle a little
  EXPECT_FALSE(world.contactRuns());

  const Vec3 start(0.5, 0.45, 0.4);
  const Vec3 velocity(0.0, 0.0, -4.0);
  const int ball = world.throwBall(start, velocity, 0.1, 0.5);
  EXPECT_EQ(ball, 0);
  EXPECT_EQ(world.obstacleCount(), 1);
  EXPECT_EQ(world.obstacle(ball).motion, ObstacleMotion::Dynamic);
  EXPECT_TRUE(world.contactRuns());
  EXPECT_TRUE(world.scene().stages.collision);
  ASSERT_EQ(world.scene().obstacles.size(), 1u);

  double lowestZ = 0.0;
  const auto ballTriangles = obstacleTriangles(world.obstacle(ball));
  for (int s = 0; s < 36; ++s) {
    world.step();
    ASSERT_TRUE(world.metrics().finite);
    const auto& mesh = world.cloth(0);
    EXPECT_EQ(test::countIntersections(world.obstacleVertices(ball), ballTriangles, mesh.x, test::clothTriangles(mesh)), 0)
        << "step " << s;
    for (const Vec3& x : mesh.x) lowestZ = std::min(lowestZ, x.z());
  }
  EXPECT_LT(lowestZ, -0.05);  // the ball pushed the sheet back
  // The ball was slowed: in free flight it would be 1.2 m further along -z.
  const Vec3 ballAt = world.obstacle(ball).body.state.position;
  EXPECT_GT(ballAt.z(), start.z() + velocity.z() * 0.3 + 0.1);
  EXPECT_GT(world.contactStats().proximityImpulses + world.contactStats().ccdCollisions + world.contactStats().heldVertices, 0);
}

TEST(ThrowBall, MissingTheSheetFlies) {
  World world(test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-5), 6, 1.0 / 60));
  const int ball = world.throwBall(Vec3(3, 0, 0), Vec3(1, 0, 0), 0.1, 1.0);
  for (int s = 0; s < 60; ++s) world.step();
  const Vec3 at = world.obstacle(ball).body.state.position;
  EXPECT_NEAR(at.x(), 4.0, 1e-9);
  EXPECT_NEAR(at.y(), -0.5 * 9.81, 0.1);  // gravity over one second
}

Scene sheetWithTool(ObstacleMotion motion) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-5), 8, 1.0 / 60);
  ObstacleSpec tool;
  tool.name = "tool";
  tool.shape.kind = ShapeKind::Box;
  tool.shape.halfExtents = Vec3(0.05, 0.05, 0.05);
  tool.translate = Vec3(0.5, 0.5, 0.5);
  tool.rotateDeg = Vec3(0, 30, 0);
  tool.motion = motion;
  scene.obstacles.push_back(tool);
  return scene;
}

TEST(KinematicOverride, FollowsPositionAndRecordsVelocity) {
  World world(sheetWithTool(ObstacleMotion::Kinematic));
  const double dt = world.scene().solver.dt;
  world.step();
  const RigidPose before = world.obstacle(0).body.state.pose();
  EXPECT_LT((before.position - Vec3(0.5, 0.5, 0.5)).norm(), 1e-12);  // held by its (empty) script

  const Vec3 target(0.6, 0.45, 0.5);
  world.setKinematicOverride(0, target);
  world.step();
  const RigidState& state = world.obstacle(0).body.state;
  EXPECT_LT((state.position - target).norm(), 1e-12);
  EXPECT_LT((state.linearVelocity - (target - before.position) / dt).norm(), 1e-9);
  EXPECT_LT(state.orientation.angularDistance(before.orientation), 1e-12);  // orientation kept
  // The world vertices moved rigidly with it.
  const std::vector<Vec3> vertices = world.obstacleVertices(0);
  EXPECT_LT((world.obstacle(0).x1[0] - vertices[0]).norm(), 1e-12);

  world.step();  // held at the target: no velocity
  EXPECT_LT(world.obstacle(0).body.state.linearVelocity.norm(), 1e-9);

  world.clearKinematicOverride(0);
  world.step();
  EXPECT_LT((world.obstacle(0).body.state.position - Vec3(0.5, 0.5, 0.5)).norm(), 1e-12);  // its script again
}

TEST(KinematicOverride, SubstepsShareTheWay) {
  Scene scene = sheetWithTool(ObstacleMotion::Kinematic);
  scene.solver.substeps = 4;
  World world(scene);
  const Vec3 target(0.5, 0.5, 0.3);
  world.setKinematicOverride(0, target);
  world.step();
  const RigidState& state = world.obstacle(0).body.state;
  EXPECT_LT((state.position - target).norm(), 1e-12);
  // The last substep's velocity: a quarter of the way in a quarter of the step.
  EXPECT_LT((state.linearVelocity - (target - Vec3(0.5, 0.5, 0.5)) / scene.solver.dt).norm(), 1e-9);
}

TEST(KinematicOverride, DraggedToolPushesClothWithoutTunnelling) {
  Scene scene = sheetWithTool(ObstacleMotion::Kinematic);
  scene.obstacles[0].translate = Vec3(0.5, 0.4, 0.2);
  World world(scene);
  const auto toolTriangles = obstacleTriangles(world.obstacle(0));
  double lowestZ = 0.0;
  for (int s = 1; s <= 30; ++s) {
    world.setKinematicOverride(0, Vec3(0.5, 0.4, 0.2 - 0.01 * s));  // 0.6 m/s through the sheet's plane
    world.step();
    ASSERT_TRUE(world.metrics().finite);
    const auto& mesh = world.cloth(0);
    EXPECT_EQ(test::countIntersections(world.obstacleVertices(0), toolTriangles, mesh.x, test::clothTriangles(mesh)), 0)
        << "step " << s;
    for (const Vec3& x : mesh.x) lowestZ = std::min(lowestZ, x.z());
  }
  EXPECT_LT(lowestZ, -0.03);
}

TEST(KinematicOverride, RejectsNonKinematicObstacle) {
  World world(sheetWithTool(ObstacleMotion::Static));
  EXPECT_THROW(world.setKinematicOverride(0, Vec3::Zero()), std::invalid_argument);
  EXPECT_THROW(world.setKinematicOverride(1, Vec3::Zero()), std::out_of_range);
}

TEST(GrabAndTear, GrabSurvivesTears) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-5), 10, 1.0 / 120);
  TearTable weak;
  weak.strength = {1.0};
  weak.unitNPerM = 0.5;
  scene.cloths[0].material.tearTable = weak;
  World world(scene);
  // Pull the middle of the sheet hard towards the viewer: the cloth tears around it.
  int middle = 0;
  for (int i = 0; i < world.cloth(0).vertexCount(); ++i)
    if ((world.cloth(0).x[i] - Vec3(0.5, 0.5, 0)).norm() < (world.cloth(0).x[middle] - Vec3(0.5, 0.5, 0)).norm()) middle = i;
  world.grab(0, middle, Vec3(0.5, 0.5, 1.0), 2000.0);
  for (int s = 0; s < 60; ++s) world.step();
  ASSERT_TRUE(world.metrics().finite);
  EXPECT_GT(world.tearLog().size(), 0u);
  ASSERT_TRUE(world.grabState().has_value());
  EXPECT_EQ(world.grabState()->spring.vertex, middle);  // ids are stable across tears
  EXPECT_GT(world.cloth(0).x[middle].z(), 0.2);
}

}  // namespace
}  // namespace weft
