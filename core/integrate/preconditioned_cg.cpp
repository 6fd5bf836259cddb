#include "integrate/preconditioned_cg.h"

#include <algorithm>
#include <cmath>

namespace weft {
namespace {

// outY = A^T x (= A x for the symmetric A) as Eigen computes it on one thread (a dot product of
// each column of A with x), split into fixed ranges of columns: the same bits for any thread count.
void multiplyTransposed(const SystemMatrix::Sparse& A, const Eigen::VectorXd& x, Eigen::VectorXd& outY, int threads) {
  const Eigen::Index n = A.cols();
  outY.resize(n);
  constexpr Eigen::Index kMinimumColumnsPerThread = 6000;  // below this the fork costs more than it saves
  const int parts = static_cast<int>(std::clamp<Eigen::Index>(n / kMinimumColumnsPerThread, 1, std::max(threads, 1)));
  if (parts == 1) {
    outY.noalias() = A.transpose() * x;
    return;
  }
#pragma omp parallel for num_threads(parts) schedule(static, 1)
  for (int part = 0; part < parts; ++part) {
    const Eigen::Index begin = n * part / parts;
    const Eigen::Index end = n * (part + 1) / parts;
    outY.segment(begin, end - begin).noalias() = A.middleCols(begin, end - begin).transpose() * x;
  }
}

}  // namespace

LinearSolveResult PreconditionedConjugateGradient::solve(const SystemMatrix& A, const Eigen::VectorXd& b,
                                                        double rhsNormFloor, Preconditioner& preconditioner,
                                                        Eigen::VectorXd& x) {
  // A is symmetric and stored in full, so A = A^T. Eigen multiplies a column-major A^T by a vector
  // as dot products of A's columns with it (reads only); A itself would scatter into the result,
  // whose store-to-load dependencies make it ~1.4x slower. Hence multiplyTransposed.
  LinearSolveResult result;
  const double scale = std::max(b.norm(), rhsNormFloor);
  if (!(scale > 0.0)) {  // b = 0 and no floor: the answer is exactly 0 (or b is not finite)
    if (scale == 0.0) x.setZero();
    result.converged = scale == 0.0;
    return result;
  }
  const double threshold = tolerance_ * scale;

  multiplyTransposed(A.matrix(), x, residual_, threads_);
  residual_ = b - residual_;
  double residualNorm = residual_.norm();
  if (residualNorm > threshold) {
    preconditioner.prepare(A);
    preconditioner.apply(residual_, preconditioned_);
    direction_ = preconditioned_;
    double rz = residual_.dot(preconditioned_);
    while (result.iterations < maxIterations_) {
      multiplyTransposed(A.matrix(), direction_, product_, threads_);
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
