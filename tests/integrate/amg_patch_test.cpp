// The multigrid hierarchy patched after a tear (amg_patch.h) instead of built anew: the tear's
// pattern change is patched (counted), every patched level still holds the transfer a build would
// derive from its aggregates (P's smoothing and the Galerkin product, pattern and values), the
// V-cycle stays symmetric positive definite, the CG needs about as many iterations as with a fresh
// build, and the result does not depend on the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "forces/elastic_forces.h"
#include "integrate/amg_preconditioner.h"
#include "integrate/linear_solver.h"
#include "integrate/preconditioned_cg.h"
#include "scene/scene_json.h"
#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "sim/world.h"
#include "support/random_vector.h"
#include "tearing/tear_mesh.h"

namespace weft {
namespace {

// The hanging sheet of the benchmark (royal-target at 1/60 s) after a few steps of its fall, as in
// support/moving_sheet_system.h, but keeping the cloth so that it can be torn and its system
// assembled again on the grown pattern, as the integrator does.
class TornSheet {
 public:
  TornSheet(int resolution, int stepsBefore) {
    file_ = std::string(WEFT_SOURCE_DIR) + "/presets/scenes/hanging-sheet.json";
    const std::string size = std::to_string(resolution);
    scene_ = loadScene(file_, {"cloths.0.mesh.grid.resolution=[" + size + "," + size + "]"});
    World world(scene_);
    for (int s = 0; s < stepsBefore; ++s) world.step();
    time_ = world.time();
    cloth_ = buildCloth(scene_.cloths[0], file_, 0);
    cloth_.mesh = world.cloth(0);
    const CoupledVertexPairs pairs = coupledVertexPairs(cloth_);
    A.setPattern(cloth_.mesh.vertexCount(), pairs.edges, pairs.hingeWings);
    assemble();
  }

  // Tears through interior vertices near the middle (a fixed sequence) until `count` tears went
  // through; the pattern grows as SystemMatrix::growPattern grows it in a run, then the system is
  // assembled again.
  void tear(int count, unsigned seed) {
    std::mt19937 random(seed);
    const int n = cloth_.mesh.vertexCount();
    std::uniform_int_distribution<int> vertex(n / 4, 3 * n / 4);
    std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
    for (int made = 0; made < count;) {
      const double a = angle(random);
      TopologyChange change;
      if (!tearThroughVertex(cloth_.mesh, vertex(random), Vec2(std::cos(a), std::sin(a)), TearGuards{},
                             cloth_.material.areaDensity, change))
        continue;
      applyTopologyChange(cloth_, change);
      const CoupledVertexPairs pairs = coupledVertexPairs(cloth_, change);
      A.growPattern(cloth_.mesh.vertexCount(), pairs.edges, pairs.hingeWings);
      ++made;
    }
    assemble();
  }

  int vertexCount() const { return cloth_.mesh.vertexCount(); }

  SystemMatrix A;
  Eigen::VectorXd b;

 private:
  void assemble() {
    const int n = cloth_.mesh.vertexCount();
    const double h = scene_.solver.dt;
    A.setZero();
    ElasticOptions options;
    options.hessian = HessianMode::Definite;
    ElasticWorkspace workspace;
    std::vector<Vec3> forces;
    StageProfile profile;
    evaluateElasticForces(cloth_, cloth_.mesh.x, options, workspace, forces, &A, profile);
    A.matrix() *= h * h;
    b.resize(3 * n);
    for (int i = 0; i < n; ++i) {
      const double m = cloth_.mesh.mass[i];
      A.addDiagonal(i, (1.0 + h * scene_.forces.damping.mass) * m);
      b.segment<3>(3 * i) = m * cloth_.mesh.v[i] + h * (forces[i] + m * scene_.forces.gravity);
    }
    std::vector<int> pinned;
    std::vector<Vec3> targets;
    pinTargets(cloth_, time_ + h, pinned, targets, profile);
    Eigen::VectorXd known = Eigen::VectorXd::Zero(3 * n);
    for (size_t k = 0; k < pinned.size(); ++k)
      known.segment<3>(3 * pinned[k]) = (targets[k] - cloth_.mesh.x[pinned[k]]) / h;
    A.constrainVertices(pinned, known, b);
  }

  std::string file_;
  Scene scene_;
  Cloth cloth_;
  double time_ = 0.0;
};

LinearSolveResult solveWith(const TornSheet& sheet, Preconditioner& preconditioner, double tolerance,
                            Eigen::VectorXd& x, int threads = 1) {
  PreconditionedConjugateGradient cg(tolerance, 5000);
  cg.setThreads(threads);
  preconditioner.setThreads(threads);
  x = Eigen::VectorXd::Zero(sheet.b.size());
  return cg.solve(sheet.A, sheet.b, 0.0, preconditioner, x);
}

// Every level patched (none built anew below a size or for the share it frees), the cycle in double.
AmgPreconditioner::Settings everyLevelPatched() {
  AmgPreconditioner::Settings settings;
  settings.hierarchy.patchMinimumVertices = 0;
  settings.hierarchy.patchLimit = 1.0;
  settings.singlePrecisionCycle = false;
  return settings;
}

AmgPreconditioner::Settings rebuildingSettings() {
  AmgPreconditioner::Settings settings;
  settings.patchAfterPatternChange = false;
  return settings;
}

Eigen::MatrixXd dense(const BlockSparseMatrix& M) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(3 * M.blockRows, 3 * M.blockColumns);
  for (int i = 0; i < M.blockRows; ++i)
    for (int k = M.rowStart[i]; k < M.rowStart[i + 1]; ++k) D.block<3, 3>(3 * i, 3 * M.column[k]) = M.blocks[k];
  return D;
}

std::set<std::pair<int, int>> patternOf(const BlockSparseMatrix& M) {
  std::set<std::pair<int, int>> blocks;
  for (int i = 0; i < M.blockRows; ++i)
    for (int k = M.rowStart[i]; k < M.rowStart[i + 1]; ++k) blocks.emplace(i, M.column[k]);
  return blocks;
}

// What AmgHierarchy::coarsen derives from level l's operator and aggregates, checked against what
// the (patched) hierarchy holds: every coarse vertex has fine vertices; P's pattern is the
// aggregates of each vertex and its neighbours and its values (I - omega D^-1 A) T; the coarse
// operator's pattern is that of P^T A P and its values the symmetrized product.
// `product`: the operator the first Galerkin product takes instead of the level's own (the system
// matrix with its wings, AmgPreconditioner::Settings::wingShareThreshold); P still comes from A.
void expectConsistentTransfer(const AmgHierarchy& hierarchy, int l, const BlockSparseMatrix* product = nullptr) {
  const AmgHierarchy::Level& fine = hierarchy.level(l);
  const AmgHierarchy::Level& coarse = hierarchy.level(l + 1);
  const BlockSparseMatrix& A = fine.A;
  const BlockSparseMatrix& B = product != nullptr ? *product : fine.A;
  const int n = A.blockRows, coarseCount = coarse.A.blockRows;
  ASSERT_EQ(static_cast<int>(fine.aggregateOf.size()), n) << "level " << l;
  std::vector<int> members(coarseCount, 0);
  for (const int J : fine.aggregateOf) {
    ASSERT_GE(J, -1);
    ASSERT_LT(J, coarseCount);
    if (J >= 0) ++members[J];
  }
  for (int J = 0; J < coarseCount; ++J) EXPECT_GT(members[J], 0) << "empty coarse vertex " << J << " of level " << l + 1;

  std::set<std::pair<int, int>> expectedP, expectedAc;
  for (int i = 0; i < n; ++i) {
    if (fine.aggregateOf[i] >= 0) expectedP.emplace(i, fine.aggregateOf[i]);
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
      if (fine.aggregateOf[A.column[k]] >= 0) expectedP.emplace(i, fine.aggregateOf[A.column[k]]);
  }
  EXPECT_EQ(patternOf(fine.P), expectedP) << "P of level " << l;
  // P^T B P: (I, K) for every i with P(i, I), j with B(i, j), and P(j, K).
  std::vector<std::vector<int>> rowsOfP(n);
  for (const auto& [i, I] : expectedP) rowsOfP[i].push_back(I);
  for (int i = 0; i < n; ++i)
    for (const int I : rowsOfP[i])
      for (int k = B.rowStart[i]; k < B.rowStart[i + 1]; ++k)
        for (const int K : rowsOfP[B.column[k]]) expectedAc.emplace(I, K);
  EXPECT_EQ(patternOf(coarse.A), expectedAc) << "coarse operator of level " << l + 1;

  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(3 * n, 3 * coarseCount);
  Eigen::MatrixXd inverseDiagonal = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) {
    if (fine.aggregateOf[i] >= 0) T.block<3, 3>(3 * i, 3 * fine.aggregateOf[i]) = Mat3::Identity();
    inverseDiagonal.block<3, 3>(3 * i, 3 * i) = fine.inverseDiagonal[i];
  }
  const Eigen::MatrixXd denseA = dense(A);
  const Eigen::MatrixXd expectedPValues = T - fine.omega * inverseDiagonal * denseA * T;
  EXPECT_LE((dense(fine.P) - expectedPValues).cwiseAbs().maxCoeff(), 1e-12 * expectedPValues.cwiseAbs().maxCoeff())
      << "P of level " << l;
  const Eigen::MatrixXd P = dense(fine.P);
  const Eigen::MatrixXd galerkinProduct = P.transpose() * dense(B) * P;
  const Eigen::MatrixXd galerkin = 0.5 * (galerkinProduct + galerkinProduct.transpose());
  EXPECT_LE((dense(coarse.A) - galerkin).cwiseAbs().maxCoeff(), 1e-10 * galerkin.cwiseAbs().maxCoeff())
      << "coarse operator of level " << l + 1;
}

TEST(AmgPatch, ATearIsPatchedAndTheCgNeedsAboutTheIterationsOfAFreshBuild) {
  TornSheet sheet(32, 20);
  AmgPreconditioner patched;
  AmgPreconditioner rebuilt(rebuildingSettings());
  Eigen::VectorXd x;
  ASSERT_TRUE(solveWith(sheet, patched, 1e-8, x).converged);
  ASSERT_TRUE(solveWith(sheet, rebuilt, 1e-8, x).converged);
  const int before = sheet.vertexCount();
  for (int round = 1; round <= 6; ++round) {
    sheet.tear(3, round);  // three tears between two solves, as in a tearing step
    const LinearSolveResult withPatch = solveWith(sheet, patched, 1e-8, x);
    EXPECT_TRUE(withPatch.converged);
    EXPECT_LE((sheet.A.matrix() * x - sheet.b).norm(), 1.01e-8 * sheet.b.norm());
    const LinearSolveResult withBuild = solveWith(sheet, rebuilt, 1e-8, x);
    EXPECT_TRUE(withBuild.converged);
    std::printf("after %d tears (%d vertices): %d iterations patched, %d built anew\n", 3 * round, sheet.vertexCount(),
                withPatch.iterations, withBuild.iterations);
    EXPECT_LE(withPatch.iterations, withBuild.iterations + withBuild.iterations / 5 + 2) << "after round " << round;
  }
  EXPECT_GT(sheet.vertexCount(), before);
  EXPECT_EQ(patched.fullSetups(), 1);
  EXPECT_EQ(patched.patchedSetups(), 6);
  EXPECT_EQ(rebuilt.fullSetups(), 7);
  EXPECT_EQ(rebuilt.patchedSetups(), 0);
}

TEST(AmgPatch, EveryPatchedLevelHoldsTheTransferOfItsAggregates) {
  // Every level patched (none built anew below a size or for the share it frees), so that the
  // coarse levels' patches (seeds from the level above, holes in the numbering, coarse rows
  // removed) are exercised too.
  TornSheet sheet(20, 15);
  AmgPreconditioner amg(everyLevelPatched());
  amg.prepare(sheet.A);
  ASSERT_GE(amg.hierarchy().levelCount(), 3);
  for (int round = 1; round <= 4; ++round) {
    sheet.tear(2, 10 + round);
    amg.prepare(sheet.A);
    ASSERT_EQ(amg.patchedSetups(), round);
    for (int l = 0; l + 1 < amg.hierarchy().levelCount(); ++l) expectConsistentTransfer(amg.hierarchy(), l);
  }
  EXPECT_EQ(amg.fullSetups(), 1);
}

// The system matrix as whole 3x3 blocks, every block (the wings too), as AmgPreconditioner reads it.
BlockSparseMatrix wholeBlocks(const SystemMatrix& A) {
  const SystemMatrix::Sparse& M = A.matrix();
  BlockSparseMatrix B;
  const int n = A.vertexCount();
  std::vector<std::vector<int>> columns(n);
  for (int i = 0; i < n; ++i)
    for (int k = M.outerIndexPtr()[3 * i]; k < M.outerIndexPtr()[3 * i + 1]; k += 3) columns[i].push_back(M.innerIndexPtr()[k] / 3);
  B.setPattern(n, n, columns);
  for (int i = 0; i < n; ++i)
    for (int k = B.rowStart[i]; k < B.rowStart[i + 1]; ++k)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) B.blocks[k](r, c) = M.coeff(3 * i + r, 3 * B.column[k] + c);
  return B;
}

TEST(AmgPatch, WithTheWingsInTheGalerkinProductEveryPatchedLevelStillHoldsItsTransfer) {
  // The first coarse level as P^T A P with A's wing couplings (forced on: a 20² sheet's wings are
  // far below the default threshold), patched through tears that change the wings too.
  TornSheet sheet(20, 15);
  AmgPreconditioner::Settings settings = everyLevelPatched();
  settings.wingShareThreshold = 0.0;
  AmgPreconditioner amg(settings);
  amg.prepare(sheet.A);
  ASSERT_TRUE(amg.wingsInGalerkinProduct());
  ASSERT_GE(amg.hierarchy().levelCount(), 3);
  BlockSparseMatrix whole = wholeBlocks(sheet.A);
  expectConsistentTransfer(amg.hierarchy(), 0, &whole);
  for (int round = 1; round <= 4; ++round) {
    sheet.tear(2, 30 + round);
    amg.prepare(sheet.A);
    ASSERT_EQ(amg.patchedSetups(), round);
    whole = wholeBlocks(sheet.A);
    expectConsistentTransfer(amg.hierarchy(), 0, &whole);
    for (int l = 1; l + 1 < amg.hierarchy().levelCount(); ++l) expectConsistentTransfer(amg.hierarchy(), l);
  }
  EXPECT_EQ(amg.fullSetups(), 1);
  EXPECT_TRUE(amg.wingsInGalerkinProduct());
  Eigen::VectorXd x;
  EXPECT_TRUE(solveWith(sheet, amg, 1e-8, x).converged);
}

TEST(AmgPatch, PatchedVCycleIsSymmetricPositiveDefinite) {
  TornSheet sheet(32, 15);
  for (const bool singlePrecision : {false, true}) {
    TornSheet torn = sheet;
    AmgPreconditioner::Settings settings;
    settings.singlePrecisionCycle = singlePrecision;
    AmgPreconditioner amg(settings);
    amg.prepare(torn.A);
    torn.tear(8, 3);
    amg.prepare(torn.A);
    ASSERT_EQ(amg.patchedSetups(), 1);
    const double symmetry = singlePrecision ? 1e-5 : 1e-10;
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const Eigen::VectorXd u = test::randomVector(torn.b.size(), seed), v = test::randomVector(torn.b.size(), 50 + seed);
      Eigen::VectorXd mu, mv;
      amg.apply(u, mu);
      amg.apply(v, mv);
      EXPECT_NEAR(u.dot(mv), v.dot(mu), symmetry * u.norm() * mv.norm()) << (singlePrecision ? "float" : "double");
      EXPECT_GT(u.dot(mu), 0.0);
      EXPECT_GT(v.dot(mv), 0.0);
    }
  }
}

TEST(AmgPatch, AChangeBeyondThePatchLimitIsBuiltAnew) {
  TornSheet sheet(24, 10);
  AmgPreconditioner::Settings settings;
  settings.hierarchy.patchLimit = 0.0;  // no vertex may be freed: every change is "too large"
  AmgPreconditioner amg(settings);
  Eigen::VectorXd x;
  ASSERT_TRUE(solveWith(sheet, amg, 1e-8, x).converged);
  sheet.tear(2, 4);
  EXPECT_TRUE(solveWith(sheet, amg, 1e-8, x).converged);
  EXPECT_EQ(amg.fullSetups(), 2);
  EXPECT_EQ(amg.patchedSetups(), 0);
}

TEST(AmgPatch, PatchedSolveIsTheSameBitsWithOneAndTwoThreads) {
  // 64²: the finest level's row-wise parts split over two threads (BlockSparseMatrix::kRowsPerThread).
  TornSheet sheet(64, 3);
  ASSERT_GE(sheet.vertexCount(), 2 * BlockSparseMatrix::kRowsPerThread);
  std::vector<Eigen::VectorXd> answers;
  std::vector<int> iterations;
  for (const int threads : {1, 2}) {
    TornSheet torn = sheet;
    AmgPreconditioner amg;
    Eigen::VectorXd x;
    ASSERT_TRUE(solveWith(torn, amg, 1e-8, x, threads).converged);
    torn.tear(5, 21);
    const LinearSolveResult result = solveWith(torn, amg, 1e-8, x, threads);
    ASSERT_TRUE(result.converged);
    EXPECT_EQ(amg.patchedSetups(), 1);
    answers.push_back(x);
    iterations.push_back(result.iterations);
  }
  EXPECT_EQ(iterations[0], iterations[1]);
  EXPECT_TRUE(answers[0] == answers[1]) << "largest difference " << (answers[0] - answers[1]).cwiseAbs().maxCoeff();
}

}  // namespace
}  // namespace weft
