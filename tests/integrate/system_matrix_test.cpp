// The system matrix pattern grown tear by tear (SystemMatrix::growPattern) against one built from
// scratch: the same assembled matrix, and the same integrator step.
#include "integrate/system_matrix.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "forces/elastic_forces.h"
#include "integrate/integrator.h"
#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "sim/world.h"
#include "support/test_scenes.h"
#include "tearing/tear_mesh.h"

namespace weft {
namespace {

Cloth smallSheet(int resolution) {
  const Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-3), resolution, 1.0 / 100);
  return buildCloth(scene.cloths[0], "test", 0);
}

// Tears the cloth through a random vertex along a random direction until one tear goes through;
// returns what it changed (with the cloth's caches patched, as the tear stage does).
TopologyChange tearSomewhere(Cloth& cloth, std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  for (;;) {
    const int vertex = std::uniform_int_distribution<int>(0, cloth.mesh.vertexCount() - 1)(rng);
    const double a = angle(rng);
    TopologyChange change;
    if (tearThroughVertex(cloth.mesh, vertex, Vec2(std::cos(a), std::sin(a)), TearGuards{},
                          cloth.material.areaDensity, change)) {
      applyTopologyChange(cloth, change);
      return change;
    }
  }
}

SystemMatrix freshPattern(const Cloth& cloth) {
  SystemMatrix matrix;
  const CoupledVertexPairs pairs = coupledVertexPairs(cloth);
  matrix.setPattern(cloth.mesh.vertexCount(), pairs.edges, pairs.hingeWings);
  return matrix;
}

// The elastic Hessian of the cloth at positions x, assembled on the matrix's pattern, as a dense matrix.
Eigen::MatrixXd assembledHessian(const Cloth& cloth, const std::vector<Vec3>& x, SystemMatrix& matrix) {
  ElasticOptions options;
  options.hessian = HessianMode::Definite;
  ElasticWorkspace workspace;
  std::vector<Vec3> forces;
  StageProfile profile;
  matrix.setZero();
  evaluateElasticForces(cloth, x, options, workspace, forces, &matrix, profile);
  return Eigen::MatrixXd(matrix.matrix());
}

TEST(SystemMatrix, PatternGrownTearByTearAssemblesTheSameMatrixAsAFreshOne) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  Cloth cloth = smallSheet(7);
  SystemMatrix grown = freshPattern(cloth);
  for (int tear = 0; tear < 15; ++tear) {
    const int version = grown.patternVersion();
    const TopologyChange change = tearSomewhere(cloth, rng);
    const CoupledVertexPairs pairs = coupledVertexPairs(cloth, change);
    grown.growPattern(cloth.mesh.vertexCount(), pairs.edges, pairs.hingeWings);
    EXPECT_GT(grown.patternVersion(), version) << "solvers must see a new pattern";

    SystemMatrix fresh = freshPattern(cloth);
    ASSERT_EQ(grown.vertexCount(), fresh.vertexCount());
    // Every block of the fresh pattern is in the grown one (which may keep uncoupled pairs).
    for (int j = 0; j < fresh.vertexCount(); ++j) {
      for (int i = 0; i < fresh.vertexCount(); ++i) {
        if (fresh.hasBlock(i, j)) ASSERT_TRUE(grown.hasBlock(i, j)) << i << ", " << j << " after tear " << tear;
      }
    }
    std::vector<Vec3> x = cloth.mesh.x;
    for (Vec3& p : x) p += Vec3(noise(rng), noise(rng), noise(rng));
    const Eigen::MatrixXd expected = assembledHessian(cloth, x, fresh);
    EXPECT_GT(expected.norm(), 0.0);
    EXPECT_EQ(assembledHessian(cloth, x, grown), expected) << "after tear " << tear;
  }
}

// Two copies of a cloth, stepped by two integrators; after tears, one grows its pattern from the
// changes and the other rebuilds it: the steps agree to round-off (a direct solver, so that only
// the factorization's ordering on the two patterns differs).
TEST(SystemMatrix, IntegratorStepOnAGrownPatternEqualsTheStepOnAFreshOne) {
  std::mt19937 rng(8);
  Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-3), 8, 1.0 / 100);
  scene.solver.linearSolver = LinearSolverKind::Cholmod;
  Cloth grownCloth = buildCloth(scene.cloths[0], "test", 0);
  const std::unique_ptr<Integrator> grown = makeIntegrator(scene.solver);
  const std::unique_ptr<Integrator> rebuilt = makeIntegrator(scene.solver);
  StepInputs inputs;
  inputs.dt = scene.solver.dt;
  inputs.gravity = Vec3(0.0, -9.81, 0.0);
  StageProfile profile;
  SolverStats stats;
  grown->advance(grownCloth, inputs, profile, stats);
  Cloth rebuiltCloth = grownCloth;
  rebuilt->advance(rebuiltCloth, inputs, profile, stats);
  grown->advance(grownCloth, inputs, profile, stats);
  for (int round = 0; round < 5; ++round) {
    std::mt19937 sameRng = rng;  // the same tears in both copies
    for (int tear = 0; tear < 3; ++tear) {
      const TopologyChange change = tearSomewhere(grownCloth, rng);
      tearSomewhere(rebuiltCloth, sameRng);
      grown->topologyChanged(grownCloth, change);
      rebuilt->topologyChanged();
    }
    inputs.time += inputs.dt;
    grown->advance(grownCloth, inputs, profile, stats);
    rebuilt->advance(rebuiltCloth, inputs, profile, stats);
    ASSERT_EQ(grownCloth.mesh.vertexCount(), rebuiltCloth.mesh.vertexCount());
    double difference = 0.0, scale = 0.0;
    for (int v = 0; v < grownCloth.mesh.vertexCount(); ++v) {
      difference = std::max(difference, (grownCloth.mesh.x[v] - rebuiltCloth.mesh.x[v]).norm());
      scale = std::max(scale, (grownCloth.mesh.v[v] * inputs.dt).norm());
    }
    EXPECT_LT(difference, 1e-12 + 1e-9 * scale) << "round " << round;
  }
  EXPECT_EQ(stats.linearSolveFailures, 0);
}

}  // namespace
}  // namespace weft
