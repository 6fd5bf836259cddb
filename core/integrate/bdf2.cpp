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

}  // namespace weft
