#pragma once
// Measures of a whole simulation shared by the integrator tests.
#include <algorithm>

#include "mesh/cloth_mesh.h"
#include "sim/world.h"

namespace weft::test {

// Kinetic, elastic and gravitational energy of the world (J).
inline double totalEnergy(const World& world) {
  const WorldMetrics m = world.metrics();
  return m.kineticEnergy + m.elasticEnergy + m.gravityEnergy;
}

// Largest distance between the same vertex of two meshes (m).
inline double maxDistance(const ClothMesh& a, const ClothMesh& b) {
  double d = 0.0;
  for (int i = 0; i < a.vertexCount(); ++i) d = std::max(d, (a.x[i] - b.x[i]).norm());
  return d;
}

}  // namespace weft::test
