#include "integrate/implicit_system.h"

#include "sim/cloth.h"
#include "sim/world.h"

namespace weft {

void ImplicitSystem::ensurePattern(const Cloth& cloth) {
  if (!patternStale && matrix.vertexCount() == cloth.mesh.vertexCount()) return;
  const CoupledVertexPairs pairs = coupledVertexPairs(cloth);
  matrix.setPattern(cloth.mesh.vertexCount(), pairs.edges, pairs.hingeWings);
  patternStale = false;
}

void ImplicitSystem::topologyChanged(const Cloth& cloth, const TopologyChange& change) {
  if (patternStale || !matrix.hasPattern()) return;  // ensurePattern builds it at the next step
  const CoupledVertexPairs pairs = coupledVertexPairs(cloth, change);
  matrix.growPattern(cloth.mesh.vertexCount(), pairs.edges, pairs.hingeWings);
}

void ImplicitSystem::beginStep(const Cloth& cloth, const StepInputs& inputs, StageProfile& profile) {
  ensurePattern(cloth);
  solver->setThreads(inputs.threads);
  externalForces(cloth, inputs, externalForce, profile);
  pinTargets(cloth, inputs.time + inputs.dt, pinnedVertices, pinnedTargets, profile);
}

bool ImplicitSystem::solve(const Eigen::VectorXd& b, double rhsNormFloor, Eigen::VectorXd& x, StageProfile& profile,
                           SolverStats& stats) {
  StageTimer timer(profile, "linear_solve");
  guess = x;
  const LinearSolveResult result = solver->solve(matrix, b, rhsNormFloor, x);
  stats.linearIterations += result.iterations;
  stats.lastLinearResidual = result.relativeResidual;
  if (std::isfinite(result.relativeResidual))
    stats.maxLinearResidual = std::max(stats.maxLinearResidual, result.relativeResidual);
  const bool finite = x.allFinite();
  if (!result.converged) ++stats.linearSolveFailures;
  if (!finite) {
    x = guess;
    return false;
  }
  return true;
}

}  // namespace weft
