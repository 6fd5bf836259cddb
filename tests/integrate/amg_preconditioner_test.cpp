// The smoothed-aggregation multigrid preconditioner on real cloth systems (the benchmark's
// hanging sheet, royal-target at 1/60 s, taken in motion): a symmetric positive definite V-cycle,
// the CG reaching the direct solver's answer, iterations that stay bounded as the grid is refined
// (block Jacobi's grow with the resolution), a correct solve after the pattern grows as in a tear
// (patched or rebuilt; the patch itself: amg_patch_test.cpp),
// and whole runs, tearing included, that do not depend on the thread count.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "forces/elastic_forces.h"
#include "integrate/amg_preconditioner.h"
#include "integrate/block_jacobi_preconditioner.h"
#include "integrate/lagged_cholesky_preconditioner.h"
#include "integrate/linear_solver.h"
#include "integrate/preconditioned_cg.h"
#include "integrate/strong_coupling_approximation.h"
#include "scene/scene_json.h"
#include "sim/cloth.h"
#include "sim/world.h"
#include "support/tear_scenes.h"
#include "support/moving_sheet_system.h"
#include "support/random_vector.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

using test::ClothSystem;
using test::movingSheetSystem;

Eigen::VectorXd directSolve(const SystemMatrix& A, const Eigen::VectorXd& b) {
  SolverSpec spec;
  spec.linearSolver = LinearSolverKind::Cholmod;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  EXPECT_TRUE(makeLinearSolver(spec)->solve(A, b, 0.0, x).converged);
  return x;
}

using test::randomVector;

int iterationsToTolerance(const ClothSystem& system, Preconditioner& preconditioner, double tolerance) {
  PreconditionedConjugateGradient cg(tolerance, 20000);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(system.b.size());
  const LinearSolveResult result = cg.solve(system.A, system.b, 0.0, preconditioner, x);
  EXPECT_TRUE(result.converged);
  return result.iterations;
}

TEST(AmgPreconditioner, VCycleIsSymmetricPositiveDefiniteOnAClothSystem) {
  // In double to rounding; in single precision (the default cycle, amg_float_cycle.h) to float
  // rounding, which the CG's double arithmetic tolerates (next test).
  const ClothSystem system = movingSheetSystem(24, 15);
  for (const bool singlePrecision : {false, true}) {
    AmgPreconditioner::Settings settings;
    settings.singlePrecisionCycle = singlePrecision;
    AmgPreconditioner amg(settings);
    amg.prepare(system.A);
    ASSERT_GE(amg.hierarchy().levelCount(), 2);
    EXPECT_TRUE(amg.hierarchy().coarsestFactored());
    const Eigen::Index size = system.b.size();
    const double symmetry = singlePrecision ? 1e-5 : 1e-10;
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const Eigen::VectorXd u = randomVector(size, seed), v = randomVector(size, 100 + seed);
      Eigen::VectorXd mu, mv;
      amg.apply(u, mu);
      amg.apply(v, mv);
      // u^T M^-1 v = v^T M^-1 u, to rounding.
      EXPECT_NEAR(u.dot(mv), v.dot(mu), symmetry * u.norm() * mv.norm()) << (singlePrecision ? "float" : "double");
      EXPECT_GT(u.dot(mu), 0.0);
      EXPECT_GT(v.dot(mv), 0.0);
    }
  }
}

TEST(AmgPreconditioner, SinglePrecisionCycleIsTheDoubleCycleToFloatRounding) {
  const ClothSystem system = movingSheetSystem(32, 20);
  AmgPreconditioner::Settings settings;
  settings.singlePrecisionCycle = false;
  AmgPreconditioner exact(settings);
  settings.singlePrecisionCycle = true;
  AmgPreconditioner single(settings);
  exact.prepare(system.A);
  single.prepare(system.A);
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Eigen::VectorXd r = randomVector(system.b.size(), seed);
    Eigen::VectorXd zExact, zSingle;
    exact.apply(r, zExact);
    single.apply(r, zSingle);
    EXPECT_LT((zSingle - zExact).norm(), 1e-5 * zExact.norm());
  }
  // And the CG needs as many iterations with either, to a tolerance far below float's epsilon.
  PreconditionedConjugateGradient cg(1e-10, 1000);
  Eigen::VectorXd xExact = Eigen::VectorXd::Zero(system.b.size()), xSingle = xExact;
  const LinearSolveResult withExact = cg.solve(system.A, system.b, 0.0, exact, xExact);
  const LinearSolveResult withSingle = cg.solve(system.A, system.b, 0.0, single, xSingle);
  EXPECT_TRUE(withSingle.converged);
  EXPECT_LE(withSingle.iterations, withExact.iterations + 1);
}

TEST(AmgPreconditioner, FinestLevelIsTheStrongCouplingApproximation) {
  // The multigrid gathers its finest level straight from A, compensating the dropped hinge wings
  // itself: it must be the matrix StrongCouplingApproximation builds for the lagged Cholesky.
  const ClothSystem system = movingSheetSystem(16, 10);
  ASSERT_FALSE(system.A.weakPairs().empty());
  StrongCouplingApproximation approximation;
  approximation.setPattern(system.A);
  approximation.refill(system.A);
  const Eigen::MatrixXd expected = Eigen::MatrixXd(approximation.matrix());
  AmgPreconditioner amg;
  amg.prepare(system.A);
  const BlockSparseMatrix& finest = amg.hierarchy().level(0).A;
  Eigen::MatrixXd gathered = Eigen::MatrixXd::Zero(expected.rows(), expected.cols());
  for (int i = 0; i < finest.blockRows; ++i)
    for (int k = finest.rowStart[i]; k < finest.rowStart[i + 1]; ++k)
      gathered.block<3, 3>(3 * i, 3 * finest.column[k]) = finest.blocks[k];
  // To rounding: the multigrid computes the compensation in its fast form (the shift of a nearly
  // rank-one hinge block carries ~1e-8 of the block's norm either way).
  EXPECT_LE((gathered - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());
  // Same pattern: the dropped pairs are not stored.
  EXPECT_EQ(9 * static_cast<Eigen::Index>(finest.blockCount()), approximation.matrix().nonZeros());
}

TEST(AmgPreconditioner, CgReachesTheDirectSolversAnswerOnAMovingSheet) {
  const ClothSystem system = movingSheetSystem(32, 20);
  const Eigen::VectorXd expected = directSolve(system.A, system.b);
  SolverSpec spec;
  spec.linearPreconditioner = PreconditionerKind::Amg;
  spec.linearTolerance = 1e-10;
  spec.linearMaxIterations = 2000;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(system.b.size());
  const LinearSolveResult result = makeLinearSolver(spec)->solve(system.A, system.b, 0.0, x);
  EXPECT_TRUE(result.converged);
  EXPECT_LE((system.A.matrix() * x - system.b).norm(), 1.01e-10 * system.b.norm());
  EXPECT_LT((x - expected).norm(), 1e-6 * expected.norm());
}

TEST(AmgPreconditioner, IterationsStayBoundedAsTheGridIsRefined) {
  // Block Jacobi's CG iterations grow about 2x per halving of the edge (sqrt of the condition
  // number); multigrid's should hardly grow. Measured (tolerance 1e-8) at 16², 32², 64²: multigrid
  // 26, 32, 35; block Jacobi 304, 645, 1486.
  std::vector<int> amgIterations, jacobiIterations;
  for (int resolution : {16, 32, 64}) {
    const ClothSystem system = movingSheetSystem(resolution, 20);
    AmgPreconditioner amg;
    BlockJacobiPreconditioner jacobi;
    amgIterations.push_back(iterationsToTolerance(system, amg, 1e-8));
    jacobiIterations.push_back(iterationsToTolerance(system, jacobi, 1e-8));
  }
  for (size_t k = 0; k < amgIterations.size(); ++k)
    std::printf("refinement %zu: amg %d, block jacobi %d iterations\n", k, amgIterations[k], jacobiIterations[k]);
  EXPECT_LE(amgIterations[2], 2 * amgIterations[0]);
  EXPECT_GT(jacobiIterations[2], 2 * jacobiIterations[0]);  // what the bound above rules out
}

TEST(AmgPreconditioner, TheWingsEnterTheGalerkinProductWhereTheyCostIterations) {
  // The hinges' wing couplings grow against the membrane's about fourfold per halving of the edge
  // (docs/solver.md, "Why the iterations double at 256²"). Below the threshold the first coarse
  // level is built without them (the shipped resolutions); with them in it, the CG needs fewer
  // iterations on a fine sheet. 256² (52 against 36 iterations) is too slow for a test; 128² shows
  // the same direction (27 against 24).
  const ClothSystem coarse = movingSheetSystem(32, 20);
  AmgPreconditioner byDefault;
  byDefault.prepare(coarse.A);
  EXPECT_FALSE(byDefault.wingsInGalerkinProduct());
  const ClothSystem fine = movingSheetSystem(128, 20);
  AmgPreconditioner::Settings withWings;
  withWings.wingShareThreshold = 0.0;
  AmgPreconditioner without, with(withWings);
  const int iterationsWithout = iterationsToTolerance(fine, without, 1e-6);
  const int iterationsWith = iterationsToTolerance(fine, with, 1e-6);
  EXPECT_FALSE(without.wingsInGalerkinProduct());
  EXPECT_TRUE(with.wingsInGalerkinProduct());
  std::printf("128²: %d CG iterations without the wings in the first Galerkin product, %d with them\n",
              iterationsWithout, iterationsWith);
  EXPECT_LT(iterationsWith, iterationsWithout);
}

TEST(AmgPreconditioner, PatchesOrRebuildsAfterThePatternGrowsAsInATear) {
  // By default a pattern change patches the hierarchy (amg_patch.h); without the patch it is built
  // anew. Either way the solve after it is right.
  for (const bool patch : {true, false}) {
    ClothSystem system = movingSheetSystem(16, 20);
    PreconditionedConjugateGradient cg(1e-10, 2000);
    AmgPreconditioner::Settings settings;
    settings.patchAfterPatternChange = patch;
    AmgPreconditioner amg(settings);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(system.b.size());
    EXPECT_TRUE(cg.solve(system.A, system.b, 0.0, amg, x).converged);
    EXPECT_EQ(amg.fullSetups(), 1);
    // Same pattern, new values: no new setup.
    system.A.matrix() *= 1.1;
    x.setZero();
    EXPECT_TRUE(cg.solve(system.A, system.b, 0.0, amg, x).converged);
    EXPECT_EQ(amg.fullSetups(), 1);
    EXPECT_EQ(amg.patchedSetups(), 0);

    // A tear appends vertices and couples them: two new vertices hung off vertex `m` and each other.
    const int n = system.A.vertexCount();
    const int m = n / 2 + 8;
    system.A.growPattern(n + 2, {{m, n}, {n, n + 1}});
    const double k = system.A.matrix().coeff(3 * m, 3 * m);
    auto couple = [&](int i, int j) {
      system.A.addBlock(i, i, k * Mat3::Identity());
      system.A.addBlock(j, j, k * Mat3::Identity());
      system.A.addBlock(i, j, -k * Mat3::Identity());
      system.A.addBlock(j, i, -k * Mat3::Identity());
    };
    couple(m, n);
    couple(n, n + 1);
    system.A.addDiagonal(n, 1e-3);
    system.A.addDiagonal(n + 1, 1e-3);
    system.b.conservativeResize(3 * (n + 2));
    system.b.tail<6>() = randomVector(6, 5);
    x = Eigen::VectorXd::Zero(system.b.size());
    EXPECT_TRUE(cg.solve(system.A, system.b, 0.0, amg, x).converged);
    EXPECT_EQ(amg.fullSetups(), patch ? 1 : 2);
    EXPECT_EQ(amg.patchedSetups(), patch ? 1 : 0);
    EXPECT_EQ(amg.hierarchy().level(0).A.blockRows, n + 2);
    const Eigen::VectorXd expected = directSolve(system.A, system.b);
    EXPECT_LT((x - expected).norm(), 1e-6 * expected.norm()) << (patch ? "patched" : "rebuilt");
  }
}

TEST(AmgPreconditioner, DegenerateHierarchiesStillSolve) {
  // Every vertex pinned (identity rows, no couplings): nothing to coarsen, too large for the dense
  // solve; the sweeps alone are exact on a block diagonal matrix (in double; the single-precision
  // cycle to float rounding, which costs the CG one more iteration to 1e-12).
  SystemMatrix pinned;
  pinned.setPattern(500, {{0, 1}, {1, 2}}, {});
  pinned.setZero();
  for (int i = 0; i < 500; ++i) pinned.addDiagonal(i, 1.0 + i % 7);
  const Eigen::VectorXd b = randomVector(3 * 500, 9);
  PreconditionedConjugateGradient cg(1e-12, 100);
  AmgPreconditioner amg;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  const LinearSolveResult diagonal = cg.solve(pinned, b, 0.0, amg, x);
  EXPECT_EQ(amg.hierarchy().levelCount(), 1);
  EXPECT_FALSE(amg.hierarchy().coarsestFactored());
  EXPECT_TRUE(diagonal.converged);
  EXPECT_LE(diagonal.iterations, 2);
  AmgPreconditioner::Settings doubleCycle;
  doubleCycle.singlePrecisionCycle = false;
  AmgPreconditioner exactSweeps(doubleCycle);
  x = Eigen::VectorXd::Zero(b.size());
  const LinearSolveResult inDouble = cg.solve(pinned, b, 0.0, exactSweeps, x);
  EXPECT_TRUE(inDouble.converged);
  EXPECT_EQ(inDouble.iterations, 1);

  // A system no larger than the coarsest level: the dense factor solves it at once.
  const ClothSystem small = movingSheetSystem(6, 5);
  AmgPreconditioner direct;
  x = Eigen::VectorXd::Zero(small.b.size());
  const LinearSolveResult exact = cg.solve(small.A, small.b, 0.0, direct, x);
  EXPECT_EQ(direct.hierarchy().levelCount(), 1);
  EXPECT_TRUE(direct.hierarchy().coarsestFactored());
  EXPECT_TRUE(exact.converged);
  EXPECT_LE(exact.iterations, 12);  // the factor is of the strong couplings only (the hinges' wings dropped)
}

TEST(AmgPreconditioner, AMassDominatedSystemIsSmoothedNotFactoredDensely) {
  // The 20² sheet's system as a very short step makes it (the mass far above the stiffness): no
  // coupling is strong, nothing coarsens, and the 400-vertex finest level, small enough for the
  // dense solve, is left to the sweeps, which still solve it in a few iterations.
  ClothSystem system = movingSheetSystem(20, 5);
  for (int i = 0; i < system.A.vertexCount(); ++i) system.A.addDiagonal(i, 1e3);
  PreconditionedConjugateGradient cg(1e-10, 200);
  AmgPreconditioner amg;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(system.b.size());
  const LinearSolveResult result = cg.solve(system.A, system.b, 0.0, amg, x);
  EXPECT_EQ(amg.hierarchy().levelCount(), 1);
  EXPECT_FALSE(amg.hierarchy().coarsestFactored());
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.iterations, 10);
}

std::uint64_t runHash(Scene scene, int threads, int steps) {
  scene.solver.threads = threads;
  World world(scene);
  for (int s = 0; s < steps; ++s) world.step();
  EXPECT_EQ(world.solverStats().linearSolveFailures, 0);
  return world.stateHash();
}

TEST(AmgPreconditioner, StateHashDoesNotDependOnThreadCountOrRun) {
  const Material royal = loadMaterialFile(test::presetPath("royal-target"));
  Scene scene = test::hangingSheet(royal, 16, 1.0 / 60);
  scene.forces.wind.velocity = Vec3(2.0, 0.0, 1.0);
  scene.solver.linearPreconditioner = PreconditionerKind::Amg;
  const std::uint64_t reference = runHash(scene, 1, 20);
  EXPECT_EQ(runHash(scene, 1, 20), reference);
  EXPECT_EQ(runHash(scene, 2, 20), reference);
}

TEST(AmgPreconditioner, SolveIsTheSameBitsWithOneAndTwoThreads) {
  // 64²: large enough that the CG's products and the finest level's row-wise parts (residual,
  // prolongation, gathering, prolongator smoothing, A P) do split over two threads (the scene
  // test above, at 16², stays below their thresholds).
  // The second level (703 rows) splits too, by its blocks (BlockSparseMatrix::kBlocksPerThread),
  // and with two threads the CG does each iteration's vector work in two parallel regions
  // (PreconditionedConjugateGradient::fusedStep): one thread does it call by call.
  const ClothSystem system = movingSheetSystem(64, 3);
  ASSERT_GE(system.A.vertexCount(), 2 * BlockSparseMatrix::kRowsPerThread);
  std::vector<Eigen::VectorXd> answers;
  std::vector<int> iterations;
  for (int threads : {1, 2}) {
    AmgPreconditioner amg;
    amg.setThreads(threads);
    PreconditionedConjugateGradient cg(1e-8, 1000);
    cg.setThreads(threads);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(system.b.size());
    EXPECT_TRUE(cg.solve(system.A, system.b, 0.0, amg, x).converged);  // the build
    ASSERT_GE(amg.hierarchy().levelCount(), 3);
    EXPECT_LT(amg.hierarchy().level(1).A.blockRows, BlockSparseMatrix::kRowsPerThread);
    EXPECT_GE(amg.hierarchy().level(1).A.blockCount(), BlockSparseMatrix::kBlocksPerThread);
    Eigen::VectorXd again = Eigen::VectorXd::Zero(system.b.size());
    const LinearSolveResult result = cg.solve(system.A, system.b, 0.0, amg, again);  // a refresh
    EXPECT_TRUE(result.converged);
    EXPECT_EQ(again, x);
    answers.push_back(again);
    iterations.push_back(result.iterations);
  }
  EXPECT_EQ(iterations[0], iterations[1]);
  EXPECT_TRUE(answers[0] == answers[1]) << "largest difference " << (answers[0] - answers[1]).cwiseAbs().maxCoeff();
}

TEST(AmgPreconditioner, ASplitSweepIsASymmetricGaussSeidelAsGoodAsTheRowOrder) {
  // 48²: 2,304 rows, so the finest level's sweeps run in two groups and an interface
  // (amg_float_cycle.h). The V-cycle stays symmetric positive definite (the backward sweep is the
  // forward one's exact reverse), the CG needs about as many iterations as with the rows' own
  // order, and one and two threads give the same bits.
  const ClothSystem system = movingSheetSystem(48, 15);
  ASSERT_GE(system.A.vertexCount(), AmgFloatCycle::kDefaultSplitRows);
  AmgPreconditioner::Settings rowOrder;
  rowOrder.splitSweepRows = 0;
  AmgPreconditioner plain(rowOrder);
  const int plainIterations = iterationsToTolerance(system, plain, 1e-8);
  std::vector<Eigen::VectorXd> answers;
  for (int threads : {1, 2}) {
    AmgPreconditioner split;
    split.setThreads(threads);
    split.prepare(system.A);
    const Eigen::Index size = system.b.size();
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const Eigen::VectorXd u = randomVector(size, seed), v = randomVector(size, 100 + seed);
      Eigen::VectorXd mu, mv;
      split.apply(u, mu);
      split.apply(v, mv);
      EXPECT_NEAR(u.dot(mv), v.dot(mu), 1e-5 * u.norm() * mv.norm());
      EXPECT_GT(u.dot(mu), 0.0);
    }
    Eigen::VectorXd z;
    split.apply(system.b, z);
    answers.push_back(z);
    const int splitIterations = iterationsToTolerance(system, split, 1e-8);
    EXPECT_LE(splitIterations, plainIterations + 2) << threads << " threads";
    EXPECT_GE(splitIterations, plainIterations - 2) << threads << " threads";
  }
  EXPECT_TRUE(answers[0] == answers[1]);
  // The split is in force: its cycle is not the row order's.
  Eigen::VectorXd zPlain;
  plain.apply(system.b, zPlain);
  EXPECT_FALSE(zPlain == answers[0]);
}

TEST(PreconditionedCg, APreconditionerThatDoesNotShareItsApplyGivesTheSameBitsInTheTeam) {
  // With two threads the CG runs its iterations in one parallel region; the lagged Cholesky and
  // block Jacobi are applied there by one thread of it (Preconditioner::applyInTeam's default),
  // the answer the same bits as one thread's call by call.
  const ClothSystem system = movingSheetSystem(64, 3);
  auto solveWith = [&](Preconditioner& preconditioner, int threads, int& iterations) {
    PreconditionedConjugateGradient cg(1e-8, 300);
    cg.setThreads(threads);
    preconditioner.setThreads(threads);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(system.b.size());
    iterations = cg.solve(system.A, system.b, 0.0, preconditioner, x).iterations;
    return x;
  };
  for (int kind = 0; kind < 2; ++kind) {
    std::vector<Eigen::VectorXd> answers;
    std::vector<int> iterations(2);
    for (int threads : {1, 2}) {
      LaggedCholeskyPreconditioner cholesky;
      BlockJacobiPreconditioner jacobi;
      Preconditioner& preconditioner = kind == 0 ? static_cast<Preconditioner&>(cholesky) : jacobi;
      answers.push_back(solveWith(preconditioner, threads, iterations[threads - 1]));
    }
    EXPECT_GT(iterations[0], 1) << kind;
    EXPECT_EQ(iterations[0], iterations[1]) << kind;
    EXPECT_TRUE(answers[0] == answers[1]) << kind << ": largest difference " << (answers[0] - answers[1]).cwiseAbs().maxCoeff();
  }
}

TEST(PreconditionedCg, BlockProductIsTheSameBitsAsEigensOnAnyThreadCount) {
  // The CG reads A's columns as 3x3 blocks (preconditioned_cg.cpp); every sum must be Eigen's own,
  // so that the default solver's trajectories (and the goldens) do not move. Pins included: their
  // rows and columns hold explicit zeros.
  const ClothSystem system = movingSheetSystem(64, 3);
  ASSERT_TRUE(PreconditionedConjugateGradient::hasWholeBlocks(system.A.matrix()));
  for (int seed : {1, 2}) {
    Eigen::VectorXd x = randomVector(system.b.size(), seed);
    x[7] = 0.0;
    const Eigen::VectorXd eigen = system.A.matrix().transpose() * x;
    for (int threads : {1, 2, 3}) {
      PreconditionedConjugateGradient cg(1e-6, 10);
      cg.setThreads(threads);
      Eigen::VectorXd y;
      cg.multiply(system.A, x, y);
      EXPECT_TRUE(y == eigen) << threads << " threads, largest difference " << (y - eigen).cwiseAbs().maxCoeff();
    }
  }
  // A pattern that is not made of whole blocks (an entry dropped) takes Eigen's product.
  SystemMatrix partial = system.A;
  partial.matrix().coeffRef(0, 1) = 0.0;
  partial.matrix().prune(0.0, 0.0);
  EXPECT_FALSE(PreconditionedConjugateGradient::hasWholeBlocks(partial.matrix()));
  const Eigen::VectorXd x = randomVector(system.b.size(), 3);
  PreconditionedConjugateGradient cg(1e-6, 10);
  Eigen::VectorXd y;
  cg.multiply(partial, x, y);
  EXPECT_TRUE(y == Eigen::VectorXd(partial.matrix().transpose() * x));
}

TEST(AmgPreconditioner, TearingSheetSolvesEveryStepAndStaysDeterministic) {
  Scene scene = test::biaxialSheet(16, test::tearTable({12.0, 14.0, 13.0}, 10.0), 10.0, false);
  scene.solver.linearPreconditioner = PreconditionerKind::Amg;
  scene.solver.threads = 1;
  World world(scene);
  for (int s = 0; s < 240 && world.tearLog().empty(); ++s) world.step();
  ASSERT_FALSE(world.tearLog().empty()) << "the sheet should have torn";
  for (int s = 0; s < 20; ++s) world.step();
  EXPECT_EQ(world.solverStats().linearSolveFailures, 0);
  const std::uint64_t hash = world.stateHash();
  scene.solver.threads = 2;
  World twoThreads(scene);
  for (int s = 0; s < 240 && twoThreads.tearLog().empty(); ++s) twoThreads.step();
  for (int s = 0; s < 20; ++s) twoThreads.step();
  EXPECT_EQ(twoThreads.stateHash(), hash);
}

}  // namespace
}  // namespace weft
