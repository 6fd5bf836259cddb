#include "contact/near_pairs.h"

#include <cmath>

#include <Eigen/Geometry>

#include "collision/closest_points.h"

namespace weft {
namespace {

Vec3 unitOrAnyPerpendicular(const Vec3& v, const Vec3& alongIfNone) {
  if (v.squaredNorm() > 0.0) return v.normalized();
  const Vec3 axis = std::abs(alongIfNone.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 n = alongIfNone.cross(axis);
  return n.squaredNorm() > 0.0 ? n.normalized() : Vec3::UnitY();
}

bool measure(const std::vector<ContactBody>& bodies, const PrimitivePair& pair, double reach, NearPair& out) {
  const std::vector<Vec3>& xa = *bodies[pair.bodyA].x0;
  const std::vector<Vec3>& xb = *bodies[pair.bodyB].x0;
  Vec3 difference, geometric;
  if (pair.kind == PairKind::VertexFace) {
    const auto& face = bodies[pair.bodyB].topology->triangles[pair.featureB];
    const Vec3& p = xa[pair.featureA];
    const PointTriangleClosest c = closestPointOnTriangle(p, xb[face[0]], xb[face[1]], xb[face[2]]);
    if (!(c.distance < reach)) return false;
    out.a = vertexSide(pair.bodyA, pair.featureA);
    out.b = faceSide(bodies, pair.bodyB, pair.featureB, c.weights);
    out.distance = c.distance;
    difference = p - c.point;
    geometric = (xb[face[1]] - xb[face[0]]).cross(xb[face[2]] - xb[face[0]]);
  } else {
    const auto& ea = bodies[pair.bodyA].topology->edges[pair.featureA];
    const auto& eb = bodies[pair.bodyB].topology->edges[pair.featureB];
    const SegmentSegmentClosest c = closestSegmentSegment(xa[ea[0]], xa[ea[1]], xb[eb[0]], xb[eb[1]]);
    if (!(c.distance < reach)) return false;
    out.a = edgeSide(bodies, pair.bodyA, pair.featureA, c.s);
    out.b = edgeSide(bodies, pair.bodyB, pair.featureB, c.t);
    out.distance = c.distance;
    difference = sidePosition(bodies, out.a, false) - sidePosition(bodies, out.b, false);
    geometric = (xa[ea[1]] - xa[ea[0]]).cross(xb[eb[1]] - xb[eb[0]]);
  }
  out.pair = pair;
  // Below a thousandth of the reach the closest-point direction is mostly rounding.
  out.touching = !(out.distance > 1e-3 * reach);
  out.normal = out.touching ? unitOrAnyPerpendicular(geometric, difference)
                            : Vec3(difference / out.distance);
  return true;
}

}  // namespace

void measureNearPairs(const std::vector<ContactBody>& bodies, const std::vector<PrimitivePair>& pairs, double reach,
                      std::vector<NearPair>& out) {
  out.clear();
  NearPair near;
  for (const PrimitivePair& pair : pairs) {
    if (measure(bodies, pair, reach, near)) out.push_back(near);
  }
}

}  // namespace weft
