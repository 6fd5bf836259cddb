#pragma once
// Continuous collision detection (thesis §2.6, Eq. 2.61-2.68): every point moves linearly from its
// position at t = 0 to its position at t = 1 over the step. A vertex hits a triangle, or an edge
// hits an edge, when the four points become coplanar (a cubic in t) with the contact point inside
// both primitives.
//
// Contract: conservative. A query never misses a time at which the primitives come within
// `minDistance` of each other (a miss is a bug); it may report a pair that only comes within a tiny
// extra tolerance (a false positive costs only work). Robust to roots near t = 0 and t = 1,
// (near-)parallel or degenerate configurations, zero motion and very large motion. Never NaN.
#include <optional>

#include "util/types.h"

namespace weft {

struct VertexFaceHit {
  double t = 0.0;                       // earliest time of contact in [0, 1] (never later than the true one)
  double weights[3] = {1.0, 0.0, 0.0};  // barycentric coordinates of the contact point on the face at t
  Vec3 normal = Vec3::UnitZ();          // unit; points from the face towards the vertex's side at t = 0
};

struct EdgeEdgeHit {
  double t = 0.0;           // earliest time of contact in [0, 1]
  double s = 0.0;           // contact point on the first edge  = pa + s (pb - pa) at t
  double u = 0.0;           // contact point on the second edge = qa + u (qb - qa) at t
  Vec3 normal = Vec3::UnitZ();  // unit; points from the second edge towards the first edge's side at t = 0
};

// Vertex p against triangle (a, b, c); suffix 0 = positions at t = 0, suffix 1 = at t = 1.
std::optional<VertexFaceHit> vertexFaceCcd(const Vec3& p0, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                                           const Vec3& p1, const Vec3& a1, const Vec3& b1, const Vec3& c1,
                                           double minDistance = 0.0);

// Edge (pa, pb) against edge (qa, qb); suffix 0 = at t = 0, suffix 1 = at t = 1.
std::optional<EdgeEdgeHit> edgeEdgeCcd(const Vec3& pa0, const Vec3& pb0, const Vec3& qa0, const Vec3& qb0,
                                       const Vec3& pa1, const Vec3& pb1, const Vec3& qa1, const Vec3& qb1,
                                       double minDistance = 0.0);

}  // namespace weft
