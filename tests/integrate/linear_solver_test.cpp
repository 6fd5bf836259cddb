// The linear solvers on stiff random systems shaped like cloth (3x3 blocks, stiff "membrane"
// couplings between grid neighbours, weak "bending" couplings two apart), checked against a dense
// LDL^T solution; the lagged Cholesky refactoring policy; the residual floor; and whole cloth steps.
#include <gtest/gtest.h>

#include <random>

#include <Eigen/Dense>

#include "integrate/lagged_cholesky_preconditioner.h"
#include "integrate/linear_solver.h"
#include "integrate/preconditioned_cg.h"
#include "integrate/strong_coupling_approximation.h"
#include "sim/world.h"
#include "support/random_vector.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

using Pairs = std::vector<std::pair<int, int>>;

// A side x side grid of vertices: strong pairs between grid neighbours (and one diagonal per
// cell), weak pairs between vertices two apart.
struct GridPattern {
  int side = 0;
  Pairs strong, weak;
};

GridPattern gridPattern(int side) {
  GridPattern g;
  g.side = side;
  auto id = [side](int x, int y) { return y * side + x; };
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      if (x + 1 < side) g.strong.emplace_back(id(x, y), id(x + 1, y));
      if (y + 1 < side) g.strong.emplace_back(id(x, y), id(x, y + 1));
      if (x + 1 < side && y + 1 < side) g.strong.emplace_back(id(x, y), id(x + 1, y + 1));
      if (x + 2 < side) g.weak.emplace_back(id(x, y), id(x + 2, y));
      if (y + 2 < side) g.weak.emplace_back(id(x, y), id(x, y + 2));
    }
  }
  return g;
}

// A = mass + sum over strong pairs of stiffness * J^T J (J random 2x6: stretch along random
// directions) + sum over weak pairs of weakStiffness * w w^T (w random 6-vector), assembled into
// the given pattern. SPD, and stiff when stiffness >> mass.
void fillStiffSystem(SystemMatrix& A, const GridPattern& g, unsigned seed, double stiffness, double weakStiffness,
                     double mass = 1.0) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto addPairBlock = [&](int i, int j, const Eigen::Matrix<double, 6, 6>& element) {
    A.addBlock(i, i, element.block<3, 3>(0, 0));
    A.addBlock(i, j, element.block<3, 3>(0, 3));
    A.addBlock(j, i, element.block<3, 3>(3, 0));
    A.addBlock(j, j, element.block<3, 3>(3, 3));
  };
  A.setZero();
  for (const auto& [i, j] : g.strong) {
    Eigen::Matrix<double, 2, 6> J;
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 6; ++c) J(r, c) = uniform(random);
    addPairBlock(i, j, stiffness * J.transpose() * J);
  }
  for (const auto& [i, j] : g.weak) {
    Eigen::Matrix<double, 6, 1> w;
    for (int c = 0; c < 6; ++c) w(c) = uniform(random);
    addPairBlock(i, j, weakStiffness * w * w.transpose());
  }
  for (int i = 0; i < A.vertexCount(); ++i) A.addDiagonal(i, mass * (1.0 + 0.5 * uniform(random)));
}

SystemMatrix patternOf(const GridPattern& g) {
  SystemMatrix A;
  A.setPattern(g.side * g.side, g.strong, g.weak);
  return A;
}

using test::randomVector;

Eigen::VectorXd denseSolve(const SystemMatrix& A, const Eigen::VectorXd& b) {
  const Eigen::MatrixXd dense(A.matrix());
  return dense.ldlt().solve(b);
}

SolverSpec cgSpec(PreconditionerKind preconditioner, double tolerance) {
  SolverSpec spec;
  spec.linearSolver = LinearSolverKind::ConjugateGradient;
  spec.linearPreconditioner = preconditioner;
  spec.linearTolerance = tolerance;
  spec.linearMaxIterations = 5000;
  return spec;
}

const PreconditionerKind kAllPreconditioners[] = {PreconditionerKind::BlockJacobi, PreconditionerKind::LaggedCholesky,
                                                  PreconditionerKind::LaggedExactCholesky, PreconditionerKind::Amg};

TEST(SystemMatrix, WeakPairsAreThoseNotAlsoStronglyCoupled) {
  SystemMatrix A;
  A.setPattern(4, {{0, 1}, {1, 2}}, {{0, 2}, {2, 1}, {1, 0}, {3, 3}, {2, 0}});
  EXPECT_EQ(A.weakPairs(), (Pairs{{0, 2}}));
  EXPECT_EQ(A.matrix().nonZeros(), 9 * (4 + 2 * 3));
}

TEST(StrongCouplingApproximation, DropsTheWeakBlocksAndStaysAboveTheMatrix) {
  const GridPattern g = gridPattern(5);
  SystemMatrix A = patternOf(g);
  fillStiffSystem(A, g, 7, 100.0, 3.0);
  StrongCouplingApproximation approximation;
  approximation.setPattern(A);
  approximation.refill(A);
  const Eigen::MatrixXd a(A.matrix());
  const Eigen::MatrixXd m(approximation.matrix());
  EXPECT_EQ(approximation.matrix().nonZeros(), A.matrix().nonZeros() - 2 * 9 * static_cast<Eigen::Index>(g.weak.size()));
  for (const auto& [i, j] : g.weak) {
    EXPECT_EQ(m.block(3 * i, 3 * j, 3, 3).norm(), 0.0);
    EXPECT_GT(a.block(3 * i, 3 * j, 3, 3).norm(), 0.0);
  }
  for (const auto& [i, j] : g.strong) EXPECT_EQ(m.block(3 * i, 3 * j, 3, 3), a.block(3 * i, 3 * j, 3, 3));
  // M - A is positive semidefinite: M >= A, so M is SPD and factorizable.
  const Eigen::VectorXd gap = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m - a).eigenvalues();
  EXPECT_GE(gap.minCoeff(), -1e-12 * a.norm());
}

TEST(StrongCouplingApproximation, FastCompensationKeepsEachDroppedPairPositiveSemidefinite) {
  // For a dropped B = A_ij, D = [[forI, -B], [-B^T, forJ]] must be >= 0 (then M >= A); the
  // multigrid's fast form must give the lagged Cholesky's compensation up to rounding. Random
  // blocks, and nearly rank-one ones like a bending hinge's.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    Mat3 B;
    for (int k = 0; k < 9; ++k) B(k % 3, k / 3) = uniform(random);
    if (trial % 2 == 1) {
      const Vec3 u(uniform(random), uniform(random), uniform(random)), v(uniform(random), uniform(random), uniform(random));
      B = u * v.transpose() + 1e-6 * B;
    }
    B *= std::pow(10.0, trial % 7 - 3);
    Mat3 forI, forJ, referenceI, referenceJ;
    ASSERT_TRUE(strongCouplingCompensationFast(B, forI, forJ));
    ASSERT_TRUE(strongCouplingCompensation(B, referenceI, referenceJ));
    Eigen::Matrix<double, 6, 6> D;
    D << forI, -B, -B.transpose(), forJ;
    const double scale = B.norm();
    using Solver6 = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>;
    const double smallest = Solver6(D).eigenvalues().minCoeff();
    // To rounding: a nearly rank-one B leaves D a zero eigenvalue, which both forms hit within
    // ~2e-10 |B| (measured; the lagged Cholesky's own form too).
    EXPECT_GE(smallest, -1e-9 * scale) << trial;
    // The shift is the square root of a difference that cancels for a rank-one B, so both forms
    // carry ~1e-8 |B| of rounding there.
    EXPECT_LE((forI - referenceI).norm(), 1e-7 * scale) << trial;
    EXPECT_LE((forJ - referenceJ).norm(), 1e-7 * scale) << trial;
  }
  Mat3 forI, forJ;
  EXPECT_FALSE(strongCouplingCompensationFast(Mat3::Zero(), forI, forJ));
}

class EveryPreconditioner : public ::testing::TestWithParam<PreconditionerKind> {};

TEST_P(EveryPreconditioner, SolvesAStiffBlockSystemToTolerance) {
  const GridPattern g = gridPattern(8);
  SystemMatrix A = patternOf(g);
  fillStiffSystem(A, g, 1, 1e4, 10.0);
  const Eigen::VectorXd b = randomVector(A.matrix().rows(), 2);
  const Eigen::VectorXd expected = denseSolve(A, b);
  const double tolerance = 1e-10;
  auto solver = makeLinearSolver(cgSpec(GetParam(), tolerance));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  const LinearSolveResult result = solver->solve(A, b, 0.0, x);
  EXPECT_TRUE(result.converged);
  EXPECT_GT(result.iterations, 0);
  EXPECT_LE(result.relativeResidual, tolerance);
  EXPECT_LE((A.matrix() * x - b).norm(), 1.01 * tolerance * b.norm());  // the reported residual is the true one
  EXPECT_LT((x - expected).norm(), 1e-5 * expected.norm());  // condition number ~1e4-1e5
}

TEST_P(EveryPreconditioner, StopsAtOnceWhenTheInitialGuessMeetsTheFloor) {
  // Near rest the right-hand side is tiny: measured against the floor, the warm start (here 0) is
  // already good enough, and the solve must not iterate (nor factor) at all.
  const GridPattern g = gridPattern(6);
  SystemMatrix A = patternOf(g);
  fillStiffSystem(A, g, 3, 1e4, 10.0);
  const Eigen::VectorXd b = 1e-14 * randomVector(A.matrix().rows(), 4);
  auto solver = makeLinearSolver(cgSpec(GetParam(), 1e-6));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  const LinearSolveResult atRest = solver->solve(A, b, 1.0, x);
  EXPECT_TRUE(atRest.converged);
  EXPECT_EQ(atRest.iterations, 0);
  EXPECT_EQ(atRest.factorizations, 0);
  EXPECT_EQ(x, Eigen::VectorXd::Zero(b.size()));
  EXPECT_DOUBLE_EQ(atRest.relativeResidual, b.norm());
  // Without the floor the same solve has to work for its relative accuracy.
  const LinearSolveResult relative = solver->solve(A, b, 0.0, x);
  EXPECT_TRUE(relative.converged);
  EXPECT_GT(relative.iterations, 0);
  EXPECT_LE(relative.relativeResidual, 1e-6);
}

TEST_P(EveryPreconditioner, ZeroRightHandSideGivesZero) {
  const GridPattern g = gridPattern(4);
  SystemMatrix A = patternOf(g);
  fillStiffSystem(A, g, 5, 10.0, 1.0);
  auto solver = makeLinearSolver(cgSpec(GetParam(), 1e-8));
  Eigen::VectorXd x = randomVector(A.matrix().rows(), 6);
  const LinearSolveResult result = solver->solve(A, Eigen::VectorXd::Zero(x.size()), 0.0, x);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(x, Eigen::VectorXd::Zero(x.size()));
}

INSTANTIATE_TEST_SUITE_P(LinearSolver, EveryPreconditioner, ::testing::ValuesIn(kAllPreconditioners),
                         [](const ::testing::TestParamInfo<PreconditionerKind>& info) {
                           switch (info.param) {
                             case PreconditionerKind::BlockJacobi: return std::string("BlockJacobi");
                             case PreconditionerKind::LaggedCholesky: return std::string("LaggedCholesky");
                             case PreconditionerKind::LaggedExactCholesky: return std::string("LaggedExactCholesky");
                             case PreconditionerKind::Amg: return std::string("Amg");
                           }
                           return std::string("Unknown");
                         });

TEST(CholmodSolver, SolvesAStiffBlockSystemAndMeasuresTheResidualAgainstTheFloor) {
  const GridPattern g = gridPattern(8);
  SystemMatrix A = patternOf(g);
  fillStiffSystem(A, g, 1, 1e4, 10.0);
  const Eigen::VectorXd b = randomVector(A.matrix().rows(), 2);
  SolverSpec spec;
  spec.linearSolver = LinearSolverKind::Cholmod;
  auto solver = makeLinearSolver(spec);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  const LinearSolveResult result = solver->solve(A, b, 0.0, x);
  EXPECT_TRUE(result.converged);
  EXPECT_LT((x - denseSolve(A, b)).norm(), 1e-9 * x.norm());
  const double residual = (A.matrix() * x - b).norm();
  EXPECT_LT(result.relativeResidual, 1e-12);
  EXPECT_NEAR(result.relativeResidual, residual / b.norm(), 0.2 * residual / b.norm());  // both rounding-level
  const LinearSolveResult floored = solver->solve(A, b, 1e3 * b.norm(), x);
  EXPECT_LT(floored.relativeResidual, 2e-3 * result.relativeResidual);
}

// The refactoring policy, step by step, on one pattern whose values change.
TEST(LaggedCholesky, KeepsAGoodFactorRefactorsAStaleOneAndAfterAPatternChange) {
  for (auto factored : {LaggedCholeskyPreconditioner::Factored::WholeMatrix,
                        LaggedCholeskyPreconditioner::Factored::StrongCouplings}) {
    SCOPED_TRACE(factored == LaggedCholeskyPreconditioner::Factored::WholeMatrix ? "whole matrix" : "strong couplings");
    const GridPattern g = gridPattern(8);
    SystemMatrix A = patternOf(g);
    const double tolerance = 1e-10;
    PreconditionedConjugateGradient cg(tolerance, 5000);
    LaggedCholeskyPreconditioner lagged(factored);
    const Eigen::VectorXd b = randomVector(A.matrix().rows(), 11);
    auto solve = [&](const SystemMatrix& matrix) {
      Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
      const LinearSolveResult result = cg.solve(matrix, b, 0.0, lagged, x);
      EXPECT_TRUE(result.converged);
      EXPECT_LE(result.relativeResidual, tolerance);
      EXPECT_LT((x - denseSolve(matrix, b)).norm(), 1e-5 * x.norm());
      return result;
    };

    // First solve: factors.
    fillStiffSystem(A, g, 1, 1e4, 10.0);
    const LinearSolveResult first = solve(A);
    EXPECT_EQ(lagged.factorizations(), 1);
    if (factored == LaggedCholeskyPreconditioner::Factored::WholeMatrix) EXPECT_EQ(first.iterations, 1);
    EXPECT_GE(lagged.factorizationCostInIterations(), LaggedCholeskyPreconditioner::kMinFactorizationCostInIterations);
    EXPECT_EQ(lagged.staleIterationLimit(), first.iterations + lagged.factorizationCostInIterations());

    // A slightly changed matrix: the old factor is still good enough, no refactoring.
    fillStiffSystem(A, g, 1, 1e4, 10.0, 1.02);
    const LinearSolveResult nearby = solve(A);
    EXPECT_EQ(lagged.factorizations(), 1);
    EXPECT_LT(nearby.iterations, lagged.staleIterationLimit());

    // A very different matrix (same pattern): the old factor is refreshed in the middle of the
    // solve, once the iterations reach the stale limit, and the solve still converges.
    fillStiffSystem(A, g, 2, 1e4, 10.0);
    const int limit = lagged.staleIterationLimit();
    const LinearSolveResult changed = solve(A);
    EXPECT_EQ(lagged.factorizations(), 2);
    EXPECT_GE(changed.iterations, limit);
    EXPECT_LE(changed.iterations, limit + 2 * first.iterations + 5);

    // The next solve after a stale factor refactors up front, without trying the old one...
    fillStiffSystem(A, g, 3, 1e4, 10.0);
    const LinearSolveResult upFront = solve(A);
    EXPECT_EQ(lagged.factorizations(), 3);
    EXPECT_LT(upFront.iterations, limit);
    // ...and the one after that tries the old factor again (here it is still exact).
    solve(A);
    EXPECT_EQ(lagged.factorizations(), 3);

    // A new pattern: analyzed and factored again.
    A.setPattern(g.side * g.side, g.strong, g.weak);
    fillStiffSystem(A, g, 3, 1e4, 10.0);
    solve(A);
    EXPECT_EQ(lagged.factorizations(), 4);
  }
}

// Whole cloth steps: every preconditioner gives the direct solver's step.
TEST(LinearSolvers, EveryPreconditionerGivesTheDirectSolversClothStep) {
  const Material royal = loadMaterialFile(test::presetPath("royal-target"));
  Scene direct = test::hangingSheet(royal, 12, 1.0 / 60);
  direct.solver.linearSolver = LinearSolverKind::Cholmod;
  World reference(direct);
  std::vector<std::unique_ptr<World>> worlds;
  for (PreconditionerKind kind : kAllPreconditioners) {
    Scene scene = direct;
    scene.solver.linearSolver = LinearSolverKind::ConjugateGradient;
    scene.solver.linearPreconditioner = kind;
    scene.solver.linearTolerance = 1e-12;
    scene.solver.linearMaxIterations = 5000;
    worlds.push_back(std::make_unique<World>(scene));
  }
  for (int s = 0; s < 5; ++s) {
    reference.step();
    for (size_t k = 0; k < worlds.size(); ++k) {
      worlds[k]->step();
      double d = 0.0;
      for (int i = 0; i < reference.cloth(0).vertexCount(); ++i)
        d = std::max(d, (worlds[k]->cloth(0).v[i] - reference.cloth(0).v[i]).norm());
      EXPECT_LT(d, 1e-7) << "preconditioner " << k << ", step " << s;
    }
  }
  for (const auto& world : worlds) EXPECT_EQ(world->solverStats().linearSolveFailures, 0);
}

}  // namespace
}  // namespace weft
