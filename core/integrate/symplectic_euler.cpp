#include "integrate/symplectic_euler.h"

#include "sim/cloth.h"
#include "sim/world.h"

namespace weft {

void SymplecticEuler::advance(Cloth& cloth, const StepInputs& in, StageProfile& profile, SolverStats&) {
  ClothMesh& mesh = cloth.mesh;
  const double h = in.dt;
  externalForces(cloth, in, externalForce_, profile);
  ElasticOptions options;
  options.bending = in.bending;
  options.threads = in.threads;
  evaluateElasticForces(cloth, mesh.x, options, elastic_, internalForce_, nullptr, profile);
  if (in.grab != nullptr) addGrabForce(*in.grab, mesh.x, internalForce_, profile);  // explicit: a stiff grab needs small steps
  pinTargets(cloth, in.time + h, pinnedVertices_, pinnedTargets_, profile);

  StageTimer timer(profile, "update");
  for (int i = 0; i < mesh.vertexCount(); ++i) {
    if (mesh.pinned[i] || mesh.mass[i] <= 0.0) continue;
    const Vec3 acceleration = (internalForce_[i] + externalForce_[i]) / mesh.mass[i] - in.damping.mass * mesh.v[i];
    mesh.v[i] += h * acceleration;
    mesh.x[i] += h * mesh.v[i];
  }
  for (size_t k = 0; k < pinnedVertices_.size(); ++k) {
    const int p = pinnedVertices_[k];
    mesh.v[p] = (pinnedTargets_[k] - mesh.x[p]) / h;
    mesh.x[p] = pinnedTargets_[k];
  }
}

}  // namespace weft
