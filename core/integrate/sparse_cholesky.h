#pragma once
// A sparse Cholesky factorization A = L L^T of the system matrix (CHOLMOD, simplicial), shared by
// the direct solver and the lagged-Cholesky preconditioner.
//
// Why simplicial and not supernodal: supernodal factorization spends its time in BLAS, so its speed
// and its floating-point results would depend on which BLAS the machine has (Debian's reference
// BLAS makes it no faster than simplicial; a threaded BLAS could make results depend on the thread
// count). Simplicial needs no BLAS, and its triangular solves, which the preconditioned CG repeats
// every iteration, are about twice as fast here.
#include <memory>

#include <Eigen/Core>

#include "integrate/system_matrix.h"

namespace weft {

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Fill-reducing ordering (nested dissection) and symbolic factorization: depends on the pattern
  // only, so it is redone only when the pattern changes. A pattern that grew by unknowns appended
  // at the end (a tear) keeps the previous ordering, the new unknowns last, while the fill stays
  // within a quarter of a fresh ordering's.
  void analyze(const SystemMatrix::Sparse& A);
  // Numeric factorization of A, which must have the analyzed pattern; reads the lower triangle.
  // Returns false when A is not numerically positive definite (the factor is then unusable).
  // CHOLMOD allocates a permuted copy of A inside each call (small next to the factorization).
  bool factorize(const SystemMatrix::Sparse& A);
  bool hasFactor() const;
  // Of the analyzed pattern: the nonzeros of L and the floating-point operations of a factorization.
  double factorNonZeros() const;
  double factorizationFlops() const;
  // x = A^-1 b with the last factor. Allocates its work vectors on the first call only.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

 private:
  struct Cholmod;  // CHOLMOD's handles stay out of this header
  std::unique_ptr<Cholmod> cholmod_;
};

}  // namespace weft
