#pragma once
// Exact intersection tests on double inputs, for checking that contact handling left no
// penetration: the answer is the true one for the given floating-point coordinates (filtered
// floating-point orientation predicates with an exact fallback), never a tolerance-based guess.
#include "util/types.h"

namespace weft {

// Sign of det[b - a, c - a, d - a]: > 0 when d lies on the side of plane (a, b, c) that its
// counter-clockwise normal points to, 0 when coplanar. Exact.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// True when the closed triangles (a0, a1, a2) and (b0, b1, b2) share at least one point. Exact.
bool trianglesIntersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                        const Vec3& b2);

// For two triangles of one mesh, given their vertex ids: true when they intersect anywhere other
// than in the corners and the edge they share (triangles sharing a vertex touch there, triangles
// sharing an edge along it; that contact does not count). Triangles with no shared vertex: same as
// trianglesIntersect. Exact.
bool meshTrianglesIntersect(const Vec3 a[3], const int ida[3], const Vec3 b[3], const int idb[3]);

}  // namespace weft
