#include "tearing/cut_ray.h"

#include <cmath>

namespace weft {
namespace {

// Whatever the guards say, a crossing never makes a flat or inverted triangle.
bool passesGuards(const std::array<Vec2, 3>& shape, const TearGuards& guards) {
  if (!(cross2(shape[1] - shape[0], shape[2] - shape[0]) > 0.0)) return false;
  for (int k = 0; k < 3; ++k) {
    if (!((shape[(k + 1) % 3] - shape[k]).norm() >= guards.minEdgeLength)) return false;
  }
  return smallestAngle(shape[0], shape[1], shape[2]) >= degToRad(guards.minAngleDeg);
}

}  // namespace

std::optional<RayCut> planRayCut(const ClothMesh& mesh, const VertexFan& fan, const Vec2& direction,
                                 const TearGuards& guards) {
  const int hit = fanTriangleHitBy(mesh, fan, direction);
  if (hit == kNone) return std::nullopt;
  const Triangle& t = mesh.tris[fan.triangles[hit]];
  const int k = fan.corners[hit];
  const Vec2 toClockwise = t.rest[(k + 1) % 3] - t.rest[k];
  const Vec2 toCounterClockwise = t.rest[(k + 2) % 3] - t.rest[k];

  // Both cross products are >= 0 inside the wedge (fanTriangleHitBy).
  const double sinClockwise = cross2(toClockwise, direction);
  const double sinCounterClockwise = cross2(direction, toCounterClockwise);
  const double angleToClockwise = std::atan2(sinClockwise, toClockwise.dot(direction));
  const double angleToCounterClockwise = std::atan2(sinCounterClockwise, toCounterClockwise.dot(direction));
  const int nearerSpoke = angleToClockwise <= angleToCounterClockwise ? clockwiseSpoke(mesh, fan, hit)
                                                                      : counterClockwiseSpoke(mesh, fan, hit);

  auto follow = [&]() -> std::optional<RayCut> {
    if (mesh.edges[nearerSpoke].isBoundary()) return std::nullopt;
    RayCut cut;
    cut.spoke = nearerSpoke;
    return cut;
  };
  if (std::min(angleToClockwise, angleToCounterClockwise) <= degToRad(guards.snapAngleDeg)) return follow();

  // The ray meets the opposite side (clockwise end A to counter-clockwise end B) at A + s (B - A),
  // where the vector from the vertex is parallel to the ray:
  //   cross(toA + s (toB - toA), d) = 0  =>  s = cross(toA, d) / (cross(toA, d) + cross(d, toB)).
  RayCut cut;
  cut.split.triangle = fan.triangles[hit];
  cut.split.side = (k + 1) % 3;
  cut.split.fraction = sinClockwise / (sinClockwise + sinCounterClockwise);
  for (const auto& shape : restShapesAfterSplit(mesh, cut.split)) {
    if (!passesGuards(shape, guards)) return follow();
  }
  return cut;
}

}  // namespace weft
