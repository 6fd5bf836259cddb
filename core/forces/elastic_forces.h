#pragma once
// Internal (elastic) forces of a cloth: the membrane of every triangle and the bending of every
// hinge, with their energy and Hessian. Elements are evaluated in parallel into per-element
// buffers and then summed in element order, so the result never depends on the thread count.
#include <vector>

#include <Eigen/Core>

#include "forces/bending.h"
#include "forces/membrane.h"
#include "integrate/system_matrix.h"
#include "sim/stage_profile.h"

namespace weft {

struct Cloth;

struct ElasticOptions {
  bool bending = true;                     // evaluate bending hinges
  HessianMode hessian = HessianMode::None; // None: energy and forces only
  int threads = 1;
};

struct ElasticSummary {
  double membraneEnergy = 0.0;  // J
  double bendingEnergy = 0.0;   // J
  double maxPrincipalStrain = 0.0;
};

// Scratch space reused across steps (no allocation once sized).
struct ElasticWorkspace {
  std::vector<MembraneResult> membrane;
  std::vector<HingeResult> bending;
};

// Sets `forces` to the elastic forces at positions x (size n). When options.hessian != None,
// also adds the Hessian of the elastic energy into `hessian` (which the caller zeroed or filled).
ElasticSummary evaluateElasticForces(const Cloth& cloth, const std::vector<Vec3>& x, const ElasticOptions& options,
                                     ElasticWorkspace& workspace, std::vector<Vec3>& forces, SystemMatrix* hessian,
                                     StageProfile& profile);

// Largest principal value of the Green strain G = [[e_uu, g/2], [g/2, e_vv]].
double maxPrincipalStrain(const Eigen::Vector3d& strain);

}  // namespace weft
