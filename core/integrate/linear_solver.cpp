#include "integrate/linear_solver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/LU>

namespace weft {
namespace {

// Inverts each 3x3 diagonal block: cloth couples the three coordinates of a vertex strongly
// (stretch along a deformed direction), so a block preconditioner beats the plain diagonal one.
class BlockJacobiPreconditioner {
 public:
  using StorageIndex = int;
  BlockJacobiPreconditioner() = default;
  template <typename MatType>
  explicit BlockJacobiPreconditioner(const MatType& mat) { compute(mat); }

  template <typename MatType>
  BlockJacobiPreconditioner& analyzePattern(const MatType&) { return *this; }
  template <typename MatType>
  BlockJacobiPreconditioner& factorize(const MatType& mat) {
    const Eigen::Index blocks = mat.cols() / 3;
    inverse_.resize(blocks);
    for (Eigen::Index b = 0; b < blocks; ++b) {
      Mat3 block;
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) block(r, c) = mat.coeff(3 * b + r, 3 * b + c);
      bool invertible = false;
      double determinant = 0.0;
      block.computeInverseAndDetWithCheck(inverse_[b], determinant, invertible);
      if (!invertible) inverse_[b] = Mat3::Identity();
    }
    return *this;
  }
  template <typename MatType>
  BlockJacobiPreconditioner& compute(const MatType& mat) { return factorize(mat); }

  template <typename Rhs>
  Eigen::VectorXd solve(const Eigen::MatrixBase<Rhs>& b) const {
    Eigen::VectorXd x(b.size());
    for (size_t k = 0; k < inverse_.size(); ++k) x.segment<3>(3 * k) = inverse_[k] * b.template segment<3>(3 * k);
    return x;
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  std::vector<Mat3> inverse_;
};

class ConjugateGradientSolver final : public LinearSolver {
 public:
  explicit ConjugateGradientSolver(const SolverSpec& spec) {
    cg_.setTolerance(spec.linearTolerance);
    cg_.setMaxIterations(spec.linearMaxIterations);
  }
  LinearSolveResult solve(const SystemMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    cg_.compute(A.matrix());
    x = cg_.solveWithGuess(b, x);
    LinearSolveResult result;
    result.iterations = static_cast<int>(cg_.iterations());
    result.relativeResidual = cg_.error();
    result.converged = cg_.info() == Eigen::Success;
    return result;
  }

 private:
  Eigen::ConjugateGradient<SystemMatrix::Sparse, Eigen::Lower | Eigen::Upper, BlockJacobiPreconditioner> cg_;
};

class CholmodSolver final : public LinearSolver {
 public:
  LinearSolveResult solve(const SystemMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    // The symbolic analysis (fill-reducing ordering) depends on the pattern only: redo it only
    // when the topology changed.
    if (analyzedVersion_ != A.patternVersion()) {
      cholesky_.analyzePattern(A.matrix());
      analyzedVersion_ = A.patternVersion();
    }
    cholesky_.factorize(A.matrix());
    LinearSolveResult result;
    result.iterations = 1;
    if (cholesky_.info() != Eigen::Success) return result;  // not positive definite
    x = cholesky_.solve(b);
    const double bNorm = b.norm();
    result.relativeResidual = bNorm > 0.0 ? (A.matrix() * x - b).norm() / bNorm : (A.matrix() * x).norm();
    result.converged = std::isfinite(result.relativeResidual);
    return result;
  }

 private:
  Eigen::CholmodSupernodalLLT<SystemMatrix::Sparse, Eigen::Lower> cholesky_;
  int analyzedVersion_ = -1;
};

}  // namespace

std::unique_ptr<LinearSolver> makeLinearSolver(const SolverSpec& spec) {
  if (spec.linearSolver == LinearSolverKind::Cholmod) return std::make_unique<CholmodSolver>();
  return std::make_unique<ConjugateGradientSolver>(spec);
}

}  // namespace weft
