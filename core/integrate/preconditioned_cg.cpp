#include "integrate/preconditioned_cg.h"

#include <algorithm>
#include <cmath>

namespace weft {

LinearSolveResult PreconditionedConjugateGradient::solve(const SystemMatrix& A, const Eigen::VectorXd& b,
                                                        double rhsNormFloor, Preconditioner& preconditioner,
                                                        Eigen::VectorXd& x) {
  // A is symmetric and stored in full, so A = A^T. Eigen multiplies a column-major A^T by a vector
  // as dot products of A's columns with it (reads only); A itself would scatter into the result,
  // whose store-to-load dependencies make it ~1.4x slower.
  const auto matrix = A.matrix().transpose();
  LinearSolveResult result;
  const double scale = std::max(b.norm(), rhsNormFloor);
  if (!(scale > 0.0)) {  // b = 0 and no floor: the answer is exactly 0 (or b is not finite)
    if (scale == 0.0) x.setZero();
    result.converged = scale == 0.0;
    return result;
  }
  const double threshold = tolerance_ * scale;

  residual_.noalias() = matrix * x;
  residual_ = b - residual_;
  double residualNorm = residual_.norm();
  if (residualNorm > threshold) {
    preconditioner.prepare(A);
    preconditioner.apply(residual_, preconditioned_);
    direction_ = preconditioned_;
    double rz = residual_.dot(preconditioned_);
    while (result.iterations < maxIterations_) {
      product_.noalias() = matrix * direction_;
      const double curvature = direction_.dot(product_);
      if (!(curvature > 0.0)) break;  // A (or M) not positive definite along the direction, or NaN
      const double alpha = rz / curvature;
      x += alpha * direction_;
      residual_ -= alpha * product_;
      ++result.iterations;
      residualNorm = residual_.norm();
      if (residualNorm <= threshold) break;
      const bool restart = preconditioner.refreshIfStale(A, result.iterations);
      preconditioner.apply(residual_, preconditioned_);
      const double rzNext = residual_.dot(preconditioned_);
      if (restart) {
        direction_ = preconditioned_;
      } else {
        direction_ = preconditioned_ + (rzNext / rz) * direction_;
      }
      rz = rzNext;
    }
    preconditioner.solveFinished(result.iterations);
  }
  result.relativeResidual = residualNorm / scale;
  result.converged = residualNorm <= threshold;
  return result;
}

}  // namespace weft
