#pragma once
// What the implicit integrators share: the system matrix kept in step with the cloth's topology,
// the linear solver, and scratch vectors reused from step to step.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "forces/elastic_forces.h"
#include "integrate/integrator.h"
#include "integrate/linear_solver.h"
#include "integrate/system_matrix.h"

namespace weft {

struct Cloth;
struct SolverStats;

// Views a vector of Vec3 as one flat 3n vector without copying.
inline Eigen::Map<Eigen::VectorXd> flat(std::vector<Vec3>& v) {
  return Eigen::Map<Eigen::VectorXd>(v.empty() ? nullptr : v[0].data(), 3 * static_cast<Eigen::Index>(v.size()));
}
inline Eigen::Map<const Eigen::VectorXd> flat(const std::vector<Vec3>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.empty() ? nullptr : v[0].data(), 3 * static_cast<Eigen::Index>(v.size()));
}

struct ImplicitSystem {
  explicit ImplicitSystem(const SolverSpec& spec) : solver(makeLinearSolver(spec)) {}

  // Rebuilds the matrix pattern when the topology changed (or on first use).
  void ensurePattern(const Cloth& cloth);
  // After a tear: grows the pattern by the pairs `change` couples (or leaves it to ensurePattern
  // when there is none yet).
  void topologyChanged(const Cloth& cloth, const TopologyChange& change);
  // What every implicit step starts with: the pattern in step with the topology, the external
  // forces and the pins' targets at the end of the step.
  void beginStep(const Cloth& cloth, const StepInputs& inputs, StageProfile& profile);
  // Solves matrix * x = rhs to |matrix * x - rhs| <= tolerance * max(|rhs|, rhsNormFloor) (see
  // linear_solver.h), records the statistics; returns false when the solve failed or gave a
  // non-finite answer (x is then left at its initial guess).
  bool solve(const Eigen::VectorXd& rhs, double rhsNormFloor, Eigen::VectorXd& x, StageProfile& profile,
             SolverStats& stats);

  SystemMatrix matrix;
  std::unique_ptr<LinearSolver> solver;
  ElasticWorkspace elastic;
  bool patternStale = true;
  // Scratch.
  std::vector<Vec3> internalForce, externalForce;
  std::vector<int> pinnedVertices;
  std::vector<Vec3> pinnedTargets;
  Eigen::VectorXd rhs, solution, known, guess;
};

}  // namespace weft
