// Integrators on whole cloths: stability at the extremes, agreement as the step shrinks, and
// agreement between the linear solvers.
#include <gtest/gtest.h>

#include "sim/world.h"
#include "support/test_scenes.h"
#include "support/world_measures.h"

namespace weft {
namespace {

using test::maxDistance;
using test::totalEnergy;

// The stiffest preset at a large step: stays finite, and (backward Euler dissipates) the total
// energy never grows and the swinging dies down.
TEST(Integrators, StiffestPresetHangingAtLargeStepStaysFiniteAndLosesEnergy) {
  const Material royal = loadMaterialFile(test::presetPath("royal-target"));
  for (IntegratorKind kind : {IntegratorKind::LinearizedBackwardEuler, IntegratorKind::Newton}) {
    Scene scene = test::hangingSheet(royal, 16, 1.0 / 30.0);
    scene.solver.integrator = kind;
    World world(scene);
    double previous = totalEnergy(world);
    double kineticEarly = 0.0;
    for (int step = 0; step < 150; ++step) {
      world.step();
      const WorldMetrics m = world.metrics();
      ASSERT_TRUE(m.finite) << "step " << step;
      const double energy = m.kineticEnergy + m.elasticEnergy + m.gravityEnergy;
      EXPECT_LE(energy, previous + 1e-9 * std::abs(previous) + 1e-12) << "step " << step;
      previous = energy;
      if (step == 10) kineticEarly = m.kineticEnergy;
    }
    EXPECT_LT(world.metrics().kineticEnergy, 0.05 * kineticEarly);
    EXPECT_LT(world.metrics().maxStrain, 0.2);
  }
}

// Both are backward Euler: the linearized step differs from the converged one by O(dt^2) per
// step, so after a fixed time the gap shrinks (about linearly) with dt.
TEST(Integrators, LinearizedBackwardEulerApproachesNewtonAsStepShrinks) {
  const Material material = test::isotropicMaterial(500.0, 0.3, 1e-6);
  const double duration = 0.25;
  std::vector<double> gaps;
  for (double dt : {1.0 / 50, 1.0 / 100, 1.0 / 200, 1.0 / 400}) {
    Scene linearized = test::hangingSheet(material, 8, dt);
    Scene newton = linearized;
    newton.solver.integrator = IntegratorKind::Newton;
    newton.solver.newtonTolerance = 1e-10;
    newton.solver.newtonMaxIterations = 50;
    newton.solver.linearSolver = linearized.solver.linearSolver = LinearSolverKind::Cholmod;
    World a(linearized), b(newton);
    const int steps = static_cast<int>(std::lround(duration / dt));
    for (int s = 0; s < steps; ++s) {
      a.step();
      b.step();
    }
    gaps.push_back(maxDistance(a.cloth(0), b.cloth(0)));
  }
  for (size_t k = 1; k < gaps.size(); ++k) {
    EXPECT_LT(gaps[k], 0.7 * gaps[k - 1]) << "dt halving " << k;
  }
  EXPECT_GT(gaps.front(), 0.0);
}

// Converged Newton steps of backward Euler at dt, dt/2, dt/4 approach a limit (first order).
// The steps must resolve the stiffest membrane mode (period ~15 ms here) to be in the asymptotic
// regime: backward Euler at larger steps damps that mode instead of following it.
TEST(Integrators, NewtonConvergesAsStepShrinks) {
  const Material material = test::isotropicMaterial(500.0, 0.3, 1e-6);
  auto run = [&](double dt) {
    Scene scene = test::hangingSheet(material, 8, dt);
    scene.solver.integrator = IntegratorKind::Newton;
    scene.solver.newtonTolerance = 1e-10;
    scene.solver.newtonMaxIterations = 50;
    scene.solver.linearSolver = LinearSolverKind::Cholmod;
    auto world = std::make_unique<World>(scene);
    for (int s = 0; s < static_cast<int>(std::lround(0.1 / dt)); ++s) world->step();
    return world;
  };
  auto coarse = run(1.0 / 800), medium = run(1.0 / 1600), fine = run(1.0 / 3200);
  const double e1 = maxDistance(coarse->cloth(0), medium->cloth(0));
  const double e2 = maxDistance(medium->cloth(0), fine->cloth(0));
  EXPECT_GT(e1, 0.0);
  EXPECT_LT(e2, 0.7 * e1);  // first order: about half
}

TEST(Integrators, ConjugateGradientAndCholmodGiveTheSameStep) {
  const Material royal = loadMaterialFile(test::presetPath("royal-target"));
  Scene cg = test::hangingSheet(royal, 12, 1.0 / 60);
  cg.solver.linearSolver = LinearSolverKind::ConjugateGradient;
  cg.solver.linearTolerance = 1e-12;
  cg.solver.linearMaxIterations = 5000;
  Scene direct = cg;
  direct.solver.linearSolver = LinearSolverKind::Cholmod;
  World a(cg), b(direct);
  for (int s = 0; s < 5; ++s) {
    a.step();
    b.step();
    double d = 0.0;
    for (int i = 0; i < a.cloth(0).vertexCount(); ++i) d = std::max(d, (a.cloth(0).v[i] - b.cloth(0).v[i]).norm());
    EXPECT_LT(d, 1e-7) << "step " << s;
  }
  EXPECT_EQ(a.solverStats().linearSolveFailures, 0);
  EXPECT_EQ(b.solverStats().linearSolveFailures, 0);
}

// The explicit baseline agrees with the implicit one at small steps.
TEST(Integrators, SymplecticEulerAgreesWithBackwardEulerAtSmallSteps) {
  const Material material = test::isotropicMaterial(200.0, 0.3, 1e-6);
  Scene implicit = test::hangingSheet(material, 6, 1.0 / 2000);
  Scene explicitScene = implicit;
  explicitScene.solver.integrator = IntegratorKind::SymplecticEuler;
  implicit.solver.linearSolver = LinearSolverKind::Cholmod;
  World a(implicit), b(explicitScene);
  for (int s = 0; s < 200; ++s) {
    a.step();
    b.step();
  }
  ASSERT_TRUE(b.metrics().finite);
  // Both have fallen ~2 cm; they differ by much less.
  EXPECT_LT(maxDistance(a.cloth(0), b.cloth(0)), 2e-3);
}

TEST(Integrators, PinnedVerticesFollowTheirScript) {
  const Material material = test::isotropicMaterial();
  Scene scene = test::hangingSheet(material, 6, 1.0 / 60);
  scene.cloths[0].pins[0].script = {{0.0, Vec3::Zero()}, {1.0, Vec3(0.3, 0.0, 0.0)}};
  World world(scene);
  const Vec3 start = world.cloth(0).x[30];  // top-left corner of a 6x6 grid (id 5*6+0)
  for (int s = 0; s < 30; ++s) world.step();
  EXPECT_NEAR((world.cloth(0).x[30] - start).x(), 0.15, 1e-12);
  EXPECT_NEAR((world.cloth(0).x[30] - start).y(), 0.0, 1e-12);
}

// Mass and stiffness (Rayleigh) damping take energy out in both implicit integrators: a swinging
// sheet moves less with them than without.
TEST(Integrators, DampingRemovesKineticEnergy) {
  const Material material = test::isotropicMaterial(800.0, 0.3, 1e-5);
  for (IntegratorKind kind : {IntegratorKind::LinearizedBackwardEuler, IntegratorKind::Newton}) {
    auto kineticAfter = [&](double massDamping, double stiffnessDamping) {
      Scene scene = test::hangingSheet(material, 8, 1.0 / 60);
      scene.cloths[0].placement.rotateDeg = Vec3(-90.0, 0.0, 0.0);  // starts horizontal: it swings
      scene.solver.integrator = kind;
      scene.solver.linearSolver = LinearSolverKind::Cholmod;
      scene.forces.damping.mass = massDamping;
      scene.forces.damping.stiffness = stiffnessDamping;
      World world(scene);
      for (int s = 0; s < 30; ++s) world.step();
      EXPECT_TRUE(world.metrics().finite);
      return world.metrics().kineticEnergy;
    };
    const double undamped = kineticAfter(0.0, 0.0);
    EXPECT_LT(kineticAfter(2.0, 0.0), 0.8 * undamped);
    EXPECT_LT(kineticAfter(0.0, 0.05), 0.8 * undamped);
  }
}

}  // namespace
}  // namespace weft
