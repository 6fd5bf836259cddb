// The grab spring's force is minus the gradient of its energy and its Jacobian the derivative of
// the force (finite differences); in a world it holds a vertex, and a released vertex falls.
#include <algorithm>

#include <gtest/gtest.h>

#include "forces/grab_spring.h"
#include "sim/world.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

GrabSpring spring() {
  GrabSpring s;
  s.vertex = 0;
  s.target = Vec3(0.3, -0.2, 0.7);
  s.stiffness = 250.0;
  return s;
}

TEST(GrabSpring, ForceIsMinusEnergyGradient) {
  const GrabSpring s = spring();
  const Vec3 x(0.1, 0.4, -0.5);
  const double eps = 1e-6;
  Vec3 gradient;
  for (int k = 0; k < 3; ++k) {
    Vec3 plus = x, minus = x;
    plus[k] += eps;
    minus[k] -= eps;
    gradient[k] = (grabEnergy(s, plus) - grabEnergy(s, minus)) / (2 * eps);
  }
  EXPECT_LT((grabForce(s, x) + gradient).norm(), 1e-6 * gradient.norm());
  EXPECT_GT(gradient.norm(), 1.0);  // the check is not vacuous
  EXPECT_DOUBLE_EQ(grabEnergy(s, s.target), 0.0);
}

TEST(GrabSpring, JacobianIsForceDerivative) {
  const GrabSpring s = spring();
  const Vec3 x(-0.2, 0.1, 0.3);
  const double eps = 1e-6;
  Mat3 numeric;
  for (int k = 0; k < 3; ++k) {
    Vec3 plus = x, minus = x;
    plus[k] += eps;
    minus[k] -= eps;
    numeric.col(k) = (grabForce(s, plus) - grabForce(s, minus)) / (2 * eps);
  }
  EXPECT_LT((grabForceJacobian(s) - numeric).norm(), 1e-6 * s.stiffness);
}

TEST(GrabSpring, AddsForceOnlyToItsVertex) {
  GrabSpring s = spring();
  s.vertex = 1;
  const std::vector<Vec3> x = {Vec3::Zero(), Vec3(1, 1, 1), Vec3(2, 0, 0)};
  std::vector<Vec3> forces(3, Vec3::Ones());
  StageProfile profile;
  addGrabForce(s, x, forces, profile);
  EXPECT_EQ(forces[0], Vec3::Ones());
  EXPECT_EQ(forces[2], Vec3::Ones());
  EXPECT_LT((forces[1] - (Vec3::Ones() + grabForce(s, x[1]))).norm(), 1e-12);
  EXPECT_EQ(profile.names, std::vector<std::string>{"grab"});
}

// A free sheet (no pins) in the x-y plane: only the grab holds it up.
Scene freeSheet(IntegratorKind integrator) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-5), 8, 1.0 / 60);
  scene.cloths[0].pins.clear();
  scene.solver.integrator = integrator;
  return scene;
}

int topMiddleVertex(const ClothMesh& mesh) {
  int best = 0;
  for (int i = 0; i < mesh.vertexCount(); ++i) {
    const double score = mesh.x[i].y() - std::abs(mesh.x[i].x() - 0.5);
    if (score > mesh.x[best].y() - std::abs(mesh.x[best].x() - 0.5)) best = i;
  }
  return best;
}

bool runs(const World& world, const std::string& stage) {
  const auto stages = world.stagesRun();
  return std::find(stages.begin(), stages.end(), stage) != stages.end();
}

void checkGrabHoldsMovesAndReleases(IntegratorKind integrator, double stiffness) {
  World world(freeSheet(integrator));
  const int v = topMiddleVertex(world.cloth(0));
  const Vec3 start = world.cloth(0).x[v];
  world.grab(0, v, start, stiffness);
  EXPECT_TRUE(runs(world, "grab"));
  for (int s = 0; s < 60; ++s) world.step();
  ASSERT_TRUE(world.metrics().finite);
  // Held: an unheld sheet falls 4.9 m in this second; the weight (0.2 kg) stretches the spring by
  // about 2 N / k.
  EXPECT_LT((world.cloth(0).x[v] - start).norm(), 0.05);

  const Vec3 moved = start + Vec3(0.3, 0.2, 0.1);
  world.moveGrab(moved);
  ASSERT_TRUE(world.grabState().has_value());
  EXPECT_EQ(world.grabState()->spring.target, moved);
  for (int s = 0; s < 90; ++s) world.step();
  ASSERT_TRUE(world.metrics().finite);
  EXPECT_LT((world.cloth(0).x[v] - moved).norm(), 0.05);

  world.releaseGrab();
  EXPECT_FALSE(world.grabState().has_value());
  EXPECT_FALSE(runs(world, "grab"));
  const double heldHeight = world.cloth(0).x[v].y();
  for (int s = 0; s < 30; ++s) world.step();
  // Half a second of free fall: 1.2 m.
  EXPECT_LT(world.cloth(0).x[v].y(), heldHeight - 0.8);
}

TEST(GrabInWorld, LinearizedBackwardEulerHoldsMovesAndReleases) {
  checkGrabHoldsMovesAndReleases(IntegratorKind::LinearizedBackwardEuler, 500.0);
}

TEST(GrabInWorld, NewtonHoldsMovesAndReleases) { checkGrabHoldsMovesAndReleases(IntegratorKind::Newton, 500.0); }

// Implicit: a grab far stiffer than the time step could take explicitly (k h^2 / m ~ 4e3) stays
// stable and holds the vertex within millimetres.
TEST(GrabInWorld, StiffGrabIsStable) {
  World world(freeSheet(IntegratorKind::LinearizedBackwardEuler));
  const int v = topMiddleVertex(world.cloth(0));
  const Vec3 target = world.cloth(0).x[v] + Vec3(0.0, 0.1, 0.0);
  world.grab(0, v, target, 1e5);
  for (int s = 0; s < 60; ++s) world.step();
  ASSERT_TRUE(world.metrics().finite);
  EXPECT_LT((world.cloth(0).x[v] - target).norm(), 2e-3);
  EXPECT_LT(world.metrics().kineticEnergy, 1.0);
}

TEST(GrabInWorld, RejectsBadVertex) {
  World world(freeSheet(IntegratorKind::LinearizedBackwardEuler));
  EXPECT_THROW(world.grab(0, world.cloth(0).vertexCount(), Vec3::Zero(), 10.0), std::out_of_range);
  EXPECT_THROW(world.grab(1, 0, Vec3::Zero(), 10.0), std::out_of_range);
  EXPECT_THROW(world.grab(0, 0, Vec3::Zero(), -1.0), std::invalid_argument);
  EXPECT_FALSE(world.grabState().has_value());
}

}  // namespace
}  // namespace weft
