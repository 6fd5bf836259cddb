#include "integrate/linear_solver.h"

#include <algorithm>
#include <cmath>

#include "integrate/amg_preconditioner.h"
#include "integrate/block_jacobi_preconditioner.h"
#include "integrate/lagged_cholesky_preconditioner.h"
#include "integrate/preconditioned_cg.h"
#include "integrate/sparse_cholesky.h"

namespace weft {
namespace {

std::unique_ptr<Preconditioner> makePreconditioner(PreconditionerKind kind) {
  switch (kind) {
    case PreconditionerKind::BlockJacobi: return std::make_unique<BlockJacobiPreconditioner>();
    case PreconditionerKind::LaggedCholesky: return std::make_unique<LaggedCholeskyPreconditioner>();
    case PreconditionerKind::LaggedExactCholesky:
      return std::make_unique<LaggedCholeskyPreconditioner>(LaggedCholeskyPreconditioner::Factored::WholeMatrix);
    case PreconditionerKind::Amg: return std::make_unique<AmgPreconditioner>();
  }
  return std::make_unique<BlockJacobiPreconditioner>();
}

class ConjugateGradientSolver final : public LinearSolver {
 public:
  explicit ConjugateGradientSolver(const SolverSpec& spec)
      : cg_(spec.linearTolerance, spec.linearMaxIterations), preconditioner_(makePreconditioner(spec.linearPreconditioner)) {}

  LinearSolveResult solve(const SystemMatrix& A, const Eigen::VectorXd& b, double rhsNormFloor,
                          Eigen::VectorXd& x) override {
    const int factorizationsBefore = preconditioner_->factorizations();
    LinearSolveResult result = cg_.solve(A, b, rhsNormFloor, *preconditioner_, x);
    result.factorizations = preconditioner_->factorizations() - factorizationsBefore;
    return result;
  }
  void setThreads(int threads) override {
    cg_.setThreads(threads);
    preconditioner_->setThreads(threads);
  }

 private:
  PreconditionedConjugateGradient cg_;
  std::unique_ptr<Preconditioner> preconditioner_;
};

class CholmodSolver final : public LinearSolver {
 public:
  LinearSolveResult solve(const SystemMatrix& A, const Eigen::VectorXd& b, double rhsNormFloor,
                          Eigen::VectorXd& x) override {
    // The symbolic analysis (fill-reducing ordering) depends on the pattern only: redo it only
    // when the topology changed.
    if (analyzedPatternVersion_ != A.patternVersion() || analyzedSize_ != A.matrix().rows()) {
      cholesky_.analyze(A.matrix());
      analyzedPatternVersion_ = A.patternVersion();
      analyzedSize_ = A.matrix().rows();
    }
    LinearSolveResult result;
    result.iterations = 1;
    result.factorizations = 1;
    if (!cholesky_.factorize(A.matrix())) return result;  // not positive definite
    cholesky_.solve(b, x);
    residual_.noalias() = A.matrix().transpose() * x;  // = A x, faster (see preconditioned_cg.cpp)
    residual_ -= b;
    const double scale = std::max(b.norm(), rhsNormFloor);
    result.relativeResidual = scale > 0.0 ? residual_.norm() / scale : residual_.norm();
    result.converged = std::isfinite(result.relativeResidual);
    return result;
  }

 private:
  SparseCholesky cholesky_;
  int analyzedPatternVersion_ = -1;
  Eigen::Index analyzedSize_ = -1;
  Eigen::VectorXd residual_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeLinearSolver(const SolverSpec& spec) {
  if (spec.linearSolver == LinearSolverKind::Cholmod) return std::make_unique<CholmodSolver>();
  return std::make_unique<ConjugateGradientSolver>(spec);
}

}  // namespace weft
