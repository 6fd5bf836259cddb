#pragma once
// Linear solvers for the implicit integrators, chosen by SolverSpec:
//   - cg: our preconditioned conjugate gradient (preconditioned_cg.h) with the preconditioner named
//     by SolverSpec::linearPreconditioner: one V-cycle of a smoothed-aggregation multigrid
//     hierarchy (amg_preconditioner.h; the default: linear cost per step, docs/solver.md), a
//     lagged sparse Cholesky factor of the strong couplings of A or of A itself
//     (lagged_cholesky_preconditioner.h), or block Jacobi;
//   - cholmod: a sparse Cholesky factorization of A (sparse_cholesky.h) every solve.
#include <memory>

#include <Eigen/Core>

#include "integrate/system_matrix.h"
#include "scene/scene.h"

namespace weft {

struct LinearSolveResult {
  bool converged = false;
  int iterations = 0;             // CG iterations (0: the initial guess was good enough; 1 for a direct solve)
  double relativeResidual = 0.0;  // |A x - b| / max(|b|, rhsNormFloor)
  int factorizations = 0;         // sparse Cholesky factorizations done by this solve
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Solves A x = b for the symmetric positive definite A. x holds the initial guess on entry
  // (used by CG; warm starts from the previous step make it cheap). The CG stops when
  // |A x - b| <= tolerance * max(|b|, rhsNormFloor): rhsNormFloor is a norm of the kind of b that
  // stays meaningful at rest (see preconditioned_cg.h); 0 gives the plain relative criterion.
  virtual LinearSolveResult solve(const SystemMatrix& A, const Eigen::VectorXd& b, double rhsNormFloor,
                                  Eigen::VectorXd& x) = 0;
  // Threads the solve may use (solver.threads). The answer does not depend on it, bit for bit.
  virtual void setThreads(int /*threads*/) {}
};

std::unique_ptr<LinearSolver> makeLinearSolver(const SolverSpec& spec);

}  // namespace weft
