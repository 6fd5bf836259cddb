#include "integrate/lagged_cholesky_preconditioner.h"

#include <algorithm>
#include <cmath>

namespace weft {

bool LaggedCholeskyPreconditioner::dropsWeakCouplings(const SystemMatrix& A) const {
  return factored_ == Factored::StrongCouplings && !A.weakPairs().empty();
}

void LaggedCholeskyPreconditioner::analyze(const SystemMatrix& A) {
  if (dropsWeakCouplings(A)) {
    approximation_.setPattern(A);
    cholesky_.analyze(approximation_.matrix());
  } else {
    cholesky_.analyze(A.matrix());
  }
  analyzedPatternVersion_ = A.patternVersion();
  analyzedSize_ = A.matrix().rows();
  // One CG iteration: two triangular solves with L and a product with A.
  const double iterationFlops = 4.0 * cholesky_.factorNonZeros() + 2.0 * static_cast<double>(A.matrix().nonZeros());
  const double cost = iterationFlops > 0.0 ? cholesky_.factorizationFlops() / iterationFlops : 0.0;
  factorizationCostInIterations_ = std::max(kMinFactorizationCostInIterations, static_cast<int>(std::lround(cost)));
  freshIterations_ = 0;
  upFrontRefactorsLeft_ = 0;
  probeInterval_ = 1;
}

void LaggedCholeskyPreconditioner::refactor(const SystemMatrix& A) {
  ++factorizations_;
  factorIsCurrent_ = true;
  if (dropsWeakCouplings(A)) {
    approximation_.refill(A);
    usingFallback_ = !cholesky_.factorize(approximation_.matrix());
  } else {
    usingFallback_ = !cholesky_.factorize(A.matrix());
  }
  if (usingFallback_) fallback_.prepare(A);
}

void LaggedCholeskyPreconditioner::prepare(const SystemMatrix& A) {
  const bool patternChanged = A.patternVersion() != analyzedPatternVersion_ || A.matrix().rows() != analyzedSize_;
  if (patternChanged) analyze(A);
  if (patternChanged || usingFallback_ || !cholesky_.hasFactor() || upFrontRefactorsLeft_ > 0) {
    upFrontRefactorsLeft_ = std::max(0, upFrontRefactorsLeft_ - 1);
    refactor(A);
  } else {
    factorIsCurrent_ = false;  // try the old factor
  }
  startedFresh_ = factorIsCurrent_;
}

bool LaggedCholeskyPreconditioner::refreshIfStale(const SystemMatrix& A, int iterationsThisSolve) {
  if (factorIsCurrent_ || iterationsThisSolve < staleIterationLimit()) return false;
  // The old factor failed: the matrix is changing fast. Factor up front for a while.
  upFrontRefactorsLeft_ = probeInterval_;
  probeInterval_ = std::min(2 * probeInterval_, kMaxProbeInterval);
  refactor(A);
  return true;
}

void LaggedCholeskyPreconditioner::solveFinished(int iterations) {
  if (startedFresh_) {
    if (!usingFallback_) freshIterations_ = iterations;
  } else if (!factorIsCurrent_) {
    probeInterval_ = 1;  // the old factor did the whole solve: it still works
  }
}

void LaggedCholeskyPreconditioner::apply(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) {
  if (usingFallback_) {
    fallback_.apply(inR, outZ);
    return;
  }
  cholesky_.solve(inR, outZ);
}

}  // namespace weft
