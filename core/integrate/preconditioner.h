#pragma once
// The preconditioner interface of the conjugate gradient (preconditioned_cg.h): an approximation M
// of the system matrix A whose inverse is cheap to apply.
#include <Eigen/Core>

#include "integrate/system_matrix.h"

namespace weft {

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  // Brings M up to date for a solve with A. A lagged preconditioner may keep an older M.
  virtual void prepare(const SystemMatrix& A) = 0;
  // outZ = M^-1 inR.
  virtual void apply(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) = 0;
  // apply, called by every thread of an enclosing parallel region with the same arguments (the
  // CG's with several threads); it returns on every thread once outZ is complete. By default one
  // thread of the team applies M and the others wait; a preconditioner may share the work.
  virtual void applyInTeam(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ);  // preconditioner.cpp
  // Called after every iteration of a solve that has not converged yet. A preconditioner that has
  // gone stale may rebuild M from A here and return true; the CG then restarts its search
  // direction (directions conjugate under the old M are not under the new one).
  virtual bool refreshIfStale(const SystemMatrix& /*A*/, int /*iterationsThisSolve*/) { return false; }
  // Called at the end of every solve that prepared the preconditioner, with its iteration count.
  virtual void solveFinished(int /*iterations*/) {}
  // Threads apply() and prepare() may use (solver.threads); results must not depend on it.
  virtual void setThreads(int /*threads*/) {}
  // Sparse factorizations done so far (for statistics and tests).
  virtual int factorizations() const { return 0; }
};

}  // namespace weft
