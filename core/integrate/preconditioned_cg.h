#pragma once
// The preconditioned conjugate gradient method for A x = b with A symmetric positive definite.
//
// Stopping rule: |r| <= tolerance * max(|b|, rhsNormFloor), r = b - A x (the recursively updated
// residual). The floor is a scale of the right-hand side that the caller knows to be meaningful
// (the integrators pass the norm of one step's external impulse): near rest |b| itself becomes
// tiny, and a purely relative criterion would then demand a far more exact answer than any step
// in motion gets, costing hundreds of iterations for nothing. With rhsNormFloor = 0 the rule is
// the plain relative one.
//
// x holds the initial guess on entry (a warm start from the previous step); if it already meets the
// tolerance the solve returns at once, without touching the preconditioner. The work vectors are
// members: no allocation once the size is known. Deterministic: a fixed sequence of operations.
#include <vector>

#include <Eigen/Core>

#include "integrate/linear_solver.h"
#include "integrate/preconditioner.h"
#include "integrate/system_matrix.h"

namespace weft {

class PreconditionedConjugateGradient {
 public:
  PreconditionedConjugateGradient(double tolerance, int maxIterations)
      : tolerance_(tolerance), maxIterations_(maxIterations) {}

  LinearSolveResult solve(const SystemMatrix& A, const Eigen::VectorXd& b, double rhsNormFloor,
                          Preconditioner& preconditioner, Eigen::VectorXd& x);
  // Threads of the solve: the products with A by fixed ranges of rows, the vector updates by fixed
  // ranges of entries, the dot products as partial sums over fixed chunks added in chunk order
  // (preconditioned_cg.cpp), so the result is the same bits for any count.
  void setThreads(int threads) { threads_ = threads; }

  // outY = A x as the solve computes it: A's columns read as 3x3 blocks when its pattern is made
  // of whole blocks (as SystemMatrix builds it; checked once per pattern), else Eigen's product;
  // the same bits either way (a dot product of each column with x, rows in order).
  void multiply(const SystemMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& outY);
  // A's pattern is made of whole 3x3 blocks: a vertex's three columns hold the same rows, in runs
  // 3j, 3j+1, 3j+2.
  static bool hasWholeBlocks(const SystemMatrix::Sparse& A);

 private:
  // With several threads: the iterations from the first direction on, in one parallel region;
  // returns their count and leaves |r| in residualNorm.
  int iterateInTeam(const SystemMatrix& A, double threshold, Preconditioner& preconditioner, double rz,
                    Eigen::VectorXd& x, double& residualNorm);
  int threads_ = 1;
  std::vector<double> partial_;  // the chunked dot products' partial sums (preconditioned_cg.cpp)
  int checkedPatternVersion_ = -1;
  Eigen::Index checkedSize_ = -1, checkedNonZeros_ = -1;
  const int* checkedIndices_ = nullptr;
  bool wholeBlocks_ = false;
  double tolerance_;
  int maxIterations_;
  Eigen::VectorXd residual_, preconditioned_, direction_, product_;
};

}  // namespace weft
