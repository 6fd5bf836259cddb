#include "integrate/bdf2.h"

#include "sim/cloth.h"
#include "sim/world.h"

namespace weft {

bool Bdf2Integrator::historyHolds(const Cloth& cloth, const StepInputs& in) const {
  // Exact comparison on purpose: any change made outside the integrator invalidates the history.
  return hasHistory_ && in.dt == stepLength_ && in.heldVertices == nullptr && cloth.mesh.x == currentX_ &&
         cloth.mesh.v == currentV_;
}

void Bdf2Integrator::advance(Cloth& cloth, const StepInputs& in, StageProfile& profile, SolverStats& stats) {
  ClothMesh& mesh = cloth.mesh;
  StepInputs inputs = in;
  {
    StageTimer timer(profile, "update");
    if (historyHolds(cloth, in)) {
      setBdf2Step(previousX_, previousV_, currentX_, currentV_, in.dt, step_);
      inputs.form = &step_;
    } else {
      ++stats.bdf2Restarts;  // one backward Euler step from the state as it is
      currentX_ = mesh.x;
      currentV_ = mesh.v;
    }
  }
  solver_->advance(cloth, inputs, profile, stats);
  StageTimer timer(profile, "update");
  previousX_.swap(currentX_);
  previousV_.swap(currentV_);
  currentX_ = mesh.x;
  currentV_ = mesh.v;
  stepLength_ = in.dt;
  hasHistory_ = true;
}

std::unique_ptr<Integrator> Bdf2Integrator::copyWithoutCaches(const SolverSpec& spec) const {
  std::unique_ptr<Integrator> copy = makeIntegrator(spec);
  // The history is physics (the next step's form), not a cache; spec names BDF2 unless a solver
  // edit is being copied mid-change, which leaves the copy to restart as any integrator change does.
  if (auto* bdf2 = dynamic_cast<Bdf2Integrator*>(copy.get())) {
    bdf2->hasHistory_ = hasHistory_;
    bdf2->stepLength_ = stepLength_;
    bdf2->previousX_ = previousX_;
    bdf2->previousV_ = previousV_;
    bdf2->currentX_ = currentX_;
    bdf2->currentV_ = currentV_;
  }
  return copy;
}

}  // namespace weft
