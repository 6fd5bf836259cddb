#pragma once
// Linear solvers for the implicit integrators: conjugate gradient with a 3x3 block-Jacobi
// preconditioner (Eigen), or a sparse Cholesky factorization (CHOLMOD from SuiteSparse).
#include <memory>

#include <Eigen/Core>

#include "integrate/system_matrix.h"
#include "scene/scene.h"

namespace weft {

struct LinearSolveResult {
  bool converged = false;
  int iterations = 0;            // CG iterations (1 for a direct solve)
  double relativeResidual = 0.0; // |A x - b| / |b|
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Solves A x = b for the symmetric positive definite A. x holds the initial guess on entry
  // (used by CG; warm starts from the previous step make it cheap).
  virtual LinearSolveResult solve(const SystemMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
};

std::unique_ptr<LinearSolver> makeLinearSolver(const SolverSpec& spec);

}  // namespace weft
