#pragma once
// Shared by the fuzz targets that build a World (scene_overrides, world_step): is its state finite?
// Every cloth position and velocity (what sim/finite_state.h's stateIsFinite reads, and what
// World::metrics().finite reports), and every obstacle as the contact stage reads it: its vertices
// in the world, its pose and velocities, and a dynamic body's mass and inertia. Cheaper than
// World::metrics(), which also evaluates the elastic forces to report energies and strain (a fifth
// of a scene_overrides unit when it was used for this check).
#include <cmath>

#include "contact/obstacle.h"
#include "sim/world.h"

namespace weft::fuzz {

inline bool worldStateFinite(const World& world) {
  for (int c = 0; c < world.clothCount(); ++c) {
    const ClothMesh& mesh = world.cloth(c);
    for (std::size_t k = 0; k < mesh.x.size(); ++k) {
      if (!mesh.x[k].allFinite() || !mesh.v[k].allFinite()) return false;
    }
  }
  for (int i = 0; i < world.obstacleCount(); ++i) {
    const Obstacle& o = world.obstacle(i);
    const RigidState& s = o.body.state;
    if (!s.position.allFinite() || !s.orientation.coeffs().allFinite() || !s.linearVelocity.allFinite() ||
        !s.angularVelocity.allFinite()) {
      return false;
    }
    if (o.motion == ObstacleMotion::Dynamic && (!std::isfinite(o.body.mass) || !o.body.inertiaBody.allFinite())) {
      return false;
    }
    for (const Vec3& p : world.obstacleVertices(i)) {
      if (!p.allFinite()) return false;
    }
  }
  return true;
}

}  // namespace weft::fuzz
