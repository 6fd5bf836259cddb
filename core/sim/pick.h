#pragma once
// Picking for the editor, without GL: which cloth triangle or obstacle feature a ray (from the
// camera through the mouse) meets. The caller turns pixels into a world ray and a world distance.
#include <optional>

#include "mesh/cloth_mesh.h"  // kNone
#include "util/types.h"

namespace weft {

class World;

struct ClothHit {
  int cloth = 0;
  int triangle = 0;          // the cloth triangle the ray meets first
  int vertex = 0;            // the corner of that triangle nearest the hit point
  Vec3 point = Vec3::Zero(); // world hit point (m)
  double distance = 0.0;     // along the ray, in units of |rayDir|
};

// The nearest cloth triangle the ray origin + s * rayDir (s >= 0) meets, both faces counting;
// none when it meets no cloth.
std::optional<ClothHit> pickCloth(const World& world, const Vec3& rayOrigin, const Vec3& rayDir);

struct ObstacleFeatureHit {
  int obstacle = 0;
  int triangle = 0;           // obstacle triangle (CollisionMesh id) the ray meets first
  Vec3 point = Vec3::Zero();  // world hit point (m)
  int vertex = kNone;         // nearest obstacle vertex within the tolerance of the hit point; kNone: none
  int edge = kNone;           // nearest CollisionMesh edge within the tolerance; kNone: none
};

// The nearest obstacle surface the ray meets, and the vertex and edge (ids of the obstacle's
// CollisionMesh, as sharp tags name them) nearest the hit point, each only if within `tolerance`
// metres of it; none when the ray meets no obstacle.
std::optional<ObstacleFeatureHit> pickObstacleFeature(const World& world, const Vec3& rayOrigin, const Vec3& rayDir,
                                                      double tolerance);

}  // namespace weft
