#pragma once
#include "forces/elastic_forces.h"
#include "integrate/integrator.h"

namespace weft {

// Symplectic (semi-implicit) Euler: v += h M^-1 f(x), then x += h v. The explicit baseline: cheap
// per step but stable only for steps below the stiffest element's period. Stiffness damping
// (beta) needs the Hessian and is not applied here; mass damping is.
class SymplecticEuler final : public Integrator {
 public:
  void advance(Cloth& cloth, const StepInputs& inputs, StageProfile& profile, SolverStats& stats) override;

 private:
  ElasticWorkspace elastic_;
  std::vector<Vec3> internalForce_, externalForce_, pinnedTargets_;
  std::vector<int> pinnedVertices_;
};

}  // namespace weft
