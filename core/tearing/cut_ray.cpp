#include "tearing/cut_ray.h"

#include <algorithm>
#include <cmath>

namespace weft {
namespace {

// A spoke this close in angle to the ray lies on the line (rad): a vertex moved onto the line, or
// a line along the grid, up to round-off.
constexpr double kOnTheLine = 1e-9;

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
                                 const TearGuards& guards, const std::vector<int>& keep) {
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
  const bool clockwiseNearer = angleToClockwise <= angleToCounterClockwise;
  const int clockwise = clockwiseSpoke(mesh, fan, hit);
  const int counterClockwise = counterClockwiseSpoke(mesh, fan, hit);

  auto follow = [&](int spoke, std::optional<VertexMove> move = std::nullopt) -> std::optional<RayCut> {
    if (mesh.edges[spoke].isBoundary()) return std::nullopt;
    RayCut cut;
    cut.spoke = spoke;
    cut.move = move;
    return cut;
  };
  if (std::min(angleToClockwise, angleToCounterClockwise) <= kOnTheLine) {
    return follow(clockwiseNearer ? clockwise : counterClockwise);
  }

  // The ray meets the opposite side (clockwise end A to counter-clockwise end B) at A + s (B - A),
  // where the vector from the vertex is parallel to the ray:
  //   cross(toA + s (toB - toA), d) = 0  =>  s = cross(toA, d) / (cross(toA, d) + cross(d, toB)).
  RayCut crossing;
  crossing.split.triangle = fan.triangles[hit];
  crossing.split.side = (k + 1) % 3;
  crossing.split.fraction = sinClockwise / (sinClockwise + sinCounterClockwise);
  const bool beyondSnap = std::min(angleToClockwise, angleToCounterClockwise) > degToRad(guards.snapAngleDeg);
  if (beyondSnap) {
    const auto shapes = restShapesAfterSplit(mesh, crossing.split);
    if (std::all_of(shapes.begin(), shapes.end(), [&](const auto& s) { return passesGuards(s, guards); })) {
      return crossing;
    }
  }

  // Move an end of the opposite side onto the line and follow its spoke: the end nearer the
  // crossing first (the smaller move).
  const int endA = t.v[(k + 1) % 3], endB = t.v[(k + 2) % 3];
  const bool aFirst = crossing.split.fraction <= 0.5;
  for (const bool useA : {aFirst, !aFirst}) {
    const int end = useA ? endA : endB;
    const int spoke = useA ? clockwise : counterClockwise;
    if (mesh.edges[spoke].isBoundary() || std::find(keep.begin(), keep.end(), end) != keep.end()) continue;
    if (const std::optional<VertexMove> move = planVertexMove(mesh, end, t.rest[k], direction, guards)) {
      // The moved end is on the ray's side of the vertex (never behind it).
      if ((move->to - t.rest[k]).dot(direction) > 0.0) return follow(spoke, move);
    }
  }
  // Across after all, when the pieces at the vertex are sound and only the neighbour beyond the
  // crossed side is thin: flips repair that (and the crack keeps its line).
  if (beyondSnap) {
    const auto shapes = restShapesAfterSplit(mesh, crossing.split);
    const auto atVertex = [&](const std::array<Vec2, 3>& shape) {
      return std::any_of(shape.begin(), shape.end(), [&](const Vec2& p) { return (p - t.rest[k]).norm() == 0.0; });
    };
    const bool soundAtVertex = std::all_of(shapes.begin(), shapes.end(), [&](const auto& shape) {
      return !atVertex(shape) || passesGuards(shape, guards);
    });
    if (shapes.size() == 4 && soundAtVertex) {
      crossing.repair = true;
      return crossing;
    }
    // Across, re-triangulating the vertex's fan too, when the new edges at the split point are
    // long enough (neither a flip nor a split lengthens them).
    const Vec2 a = t.rest[(k + 1) % 3], b = t.rest[(k + 2) % 3];
    const Vec2 splitPoint = a + crossing.split.fraction * (b - a);
    const double side = (b - a).norm();
    if (std::min(crossing.split.fraction, 1.0 - crossing.split.fraction) * side >= guards.minEdgeLength &&
        (splitPoint - t.rest[k]).norm() >= guards.minEdgeLength) {
      crossing.repair = true;
      crossing.repairAtVertex = true;
      return crossing;
    }
  }
  if (!beyondSnap) return follow(clockwiseNearer ? clockwise : counterClockwise);
  return std::nullopt;
}

}  // namespace weft
