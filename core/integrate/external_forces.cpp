#include "forces/wind.h"
#include "integrate/integrator.h"
#include "sim/cloth.h"

namespace weft {

void externalForces(const Cloth& cloth, const StepInputs& inputs, std::vector<Vec3>& forces, StageProfile& profile) {
  const ClothMesh& mesh = cloth.mesh;
  forces.assign(mesh.vertexCount(), Vec3::Zero());
  if (inputs.gravity.squaredNorm() > 0.0) {
    StageTimer timer(profile, "gravity");
    for (int i = 0; i < mesh.vertexCount(); ++i) forces[i] = mesh.mass[i] * inputs.gravity;
  }
  if (inputs.wind) {
    StageTimer timer(profile, "wind");
    addWindForces(mesh, *inputs.wind, inputs.time, forces);
  }
}

}  // namespace weft
