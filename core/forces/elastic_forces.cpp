#include "forces/elastic_forces.h"

#include <algorithm>
#include <cmath>

#include "sim/cloth.h"

namespace weft {

double maxPrincipalStrain(const Eigen::Vector3d& e) {
  const double mean = 0.5 * (e[0] + e[1]);
  const double radius = std::sqrt(0.25 * (e[0] - e[1]) * (e[0] - e[1]) + 0.25 * e[2] * e[2]);
  return mean + radius;
}

ElasticSummary evaluateElasticForces(const Cloth& cloth, const std::vector<Vec3>& x, const ElasticOptions& options,
                                     ElasticWorkspace& workspace, std::vector<Vec3>& forces, SystemMatrix* hessian,
                                     StageProfile& profile) {
  ElasticSummary summary;
  forces.assign(x.size(), Vec3::Zero());
  const HessianMode mode = hessian ? options.hessian : HessianMode::None;
  const int triangleCount = static_cast<int>(cloth.membranes.size());
  {
    StageTimer timer(profile, "membrane");
    workspace.membrane.resize(triangleCount);
#pragma omp parallel for num_threads(options.threads) schedule(static)
    for (int t = 0; t < triangleCount; ++t) {
      const MembraneElement& element = cloth.membranes[t];
      workspace.membrane[t] = evaluateMembrane(element, cloth.material.elasticity, x[element.v[0]], x[element.v[1]],
                                               x[element.v[2]], mode);
    }
    // Scatter in triangle order (deterministic).
    for (int t = 0; t < triangleCount; ++t) {
      const MembraneElement& element = cloth.membranes[t];
      const MembraneResult& r = workspace.membrane[t];
      summary.membraneEnergy += r.energy;
      summary.maxPrincipalStrain = std::max(summary.maxPrincipalStrain, maxPrincipalStrain(r.strain));
      for (int i = 0; i < 3; ++i) forces[element.v[i]] += r.force.segment<3>(3 * i);
      if (mode != HessianMode::None)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) hessian->addBlock(element.v[i], element.v[j], r.hessian.block<3, 3>(3 * i, 3 * j));
    }
  }
  if (options.bending && !cloth.hinges.empty()) {
    StageTimer timer(profile, "bending");
    const int hingeCount = static_cast<int>(cloth.hinges.size());
    workspace.bending.resize(hingeCount);
#pragma omp parallel for num_threads(options.threads) schedule(static)
    for (int h = 0; h < hingeCount; ++h) {
      const BendingHinge& hinge = cloth.hinges[h];
      workspace.bending[h] = evaluateHinge(hinge, cloth.material.bending, x[hinge.v[0]], x[hinge.v[1]], x[hinge.v[2]],
                                           x[hinge.v[3]], mode);
    }
    for (int h = 0; h < hingeCount; ++h) {
      const BendingHinge& hinge = cloth.hinges[h];
      const HingeResult& r = workspace.bending[h];
      summary.bendingEnergy += r.energy;
      for (int i = 0; i < 4; ++i) forces[hinge.v[i]] += r.force.segment<3>(3 * i);
      if (mode != HessianMode::None)
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) hessian->addBlock(hinge.v[i], hinge.v[j], r.hessian.block<3, 3>(3 * i, 3 * j));
    }
  }
  return summary;
}

}  // namespace weft
