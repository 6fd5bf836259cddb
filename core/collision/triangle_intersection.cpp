#include "collision/triangle_intersection.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Geometry>

#include "collision/exact_sign.h"

// Everything below is built from two exact predicates, orient3d and orient2d on a coordinate-plane
// projection, plus comparisons of coordinates. No tolerance appears anywhere, so every degenerate
// configuration (touching, coplanar, collinear, coincident points, triangles collapsed to a segment
// or a point) gets the true answer.
//
// The plan: two closed triangles meet exactly when an edge of one meets the other triangle (if
// their planes cross, the intersection segment ends on an edge of one of them; if they are
// coplanar, either their boundaries cross or one contains the other, and then its edges lie
// inside the other). So the core is one exact segment-triangle test, handling degenerate
// segments and triangles too.

namespace weft {

namespace {

constexpr double kUnitRoundoff = 0x1p-53;
// |computed - exact| <= bound * permanent for the determinants evaluated below: each of the six
// terms of the 3x3 determinant goes through at most 8 roundings (3 differences, 2 products, the
// minor's subtraction, 2 additions), so the error is below (8 + O(eps)) eps times the sum of the
// terms' magnitudes; the 2x2 determinant's terms go through 4. One extra eps covers the rounding
// of the permanent itself.
constexpr double kOrient3dErrorBound = 9.0 * kUnitRoundoff;
constexpr double kOrient2dErrorBound = 5.0 * kUnitRoundoff;
// Below this the relative bounds above may not hold (an underflowed product loses more than its
// relative error); such tiny determinants go to the exact evaluation.
constexpr double kMinFilteredPermanent = 0x1p-800;

// Sign of the 2x2 orientation determinant of a, b, c projected along `axis` onto the coordinate
// plane of the two other axes, taken in cyclic order (axis + 1, axis + 2): it has the sign of
// component `axis` of (b - a) x (c - a). Exact.
int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const double ux = b[i] - a[i], uy = b[j] - a[j];
  const double vx = c[i] - a[i], vy = c[j] - a[j];
  const double left = ux * vy, right = uy * vx;
  const double det = left - right;
  const double permanent = std::fabs(left) + std::fabs(right);
  if (permanent >= kMinFilteredPermanent) {
    const double bound = kOrient2dErrorBound * permanent;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  return exactOrient2dSign(Vec2(a[i], a[j]), Vec2(b[i], b[j]), Vec2(c[i], c[j]));
}

// Lexicographic order of (x, y, z). Along any line it is monotone, so it orders collinear points
// by their position on the line.
bool lexLess(const Vec3& p, const Vec3& q) {
  for (int k = 0; k < 3; ++k) {
    if (p[k] != q[k]) return p[k] < q[k];
  }
  return false;
}

const Vec3& lexMin(const Vec3& p, const Vec3& q) { return lexLess(q, p) ? q : p; }
const Vec3& lexMax(const Vec3& p, const Vec3& q) { return lexLess(p, q) ? q : p; }

// a, b, c on one line (or coincident): (b - a) x (c - a) vanishes in every component.
bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  return orient2d(a, b, c, 0) == 0 && orient2d(a, b, c, 1) == 0 && orient2d(a, b, c, 2) == 0;
}

// p on the closed segment [a, b] (a point when a == b).
bool onSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  if (!collinear(a, b, p)) return false;
  return !lexLess(p, lexMin(a, b)) && !lexLess(lexMax(a, b), p);
}

// --- In a coordinate-plane projection (`axis` dropped) ---------------------------------------

// For points already known to be collinear in the projection: p within the bounding box of the
// projected segment [a, b], i.e. on it.
bool withinProjectedBox(const Vec3& p, const Vec3& a, const Vec3& b, int axis) {
  for (int k : {(axis + 1) % 3, (axis + 2) % 3}) {
    if (p[k] < std::min(a[k], b[k]) || p[k] > std::max(a[k], b[k])) return false;
  }
  return true;
}

// Closed segments [p, q] and [r, s] meet in the projection; either may be a point.
bool segmentsMeet2d(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s, int axis) {
  const int r_pq = orient2d(p, q, r, axis), s_pq = orient2d(p, q, s, axis);
  const int p_rs = orient2d(r, s, p, axis), q_rs = orient2d(r, s, q, axis);
  if (r_pq * s_pq < 0 && p_rs * q_rs < 0) return true;  // proper crossing
  // Otherwise they meet only where an endpoint of one lies on the other.
  return (r_pq == 0 && withinProjectedBox(r, p, q, axis)) || (s_pq == 0 && withinProjectedBox(s, p, q, axis)) ||
         (p_rs == 0 && withinProjectedBox(p, r, s, axis)) || (q_rs == 0 && withinProjectedBox(q, r, s, axis));
}

// p inside or on the projected triangle (a, b, c), which must not be degenerate in the projection.
bool insideTriangle2d(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int axis) {
  const int s0 = orient2d(a, b, p, axis), s1 = orient2d(b, c, p, axis), s2 = orient2d(c, a, p, axis);
  const bool anyPositive = s0 > 0 || s1 > 0 || s2 > 0;
  const bool anyNegative = s0 < 0 || s1 < 0 || s2 < 0;
  return !(anyPositive && anyNegative);
}

// Closed segment [p, q] meets closed triangle t in the projection. A triangle degenerate in the
// projection is the union of its edges, so the containment test applies only to proper ones.
bool segmentMeetsTriangle2d(const Vec3& p, const Vec3& q, const Vec3 t[3], int axis) {
  if (orient2d(t[0], t[1], t[2], axis) != 0 &&
      (insideTriangle2d(p, t[0], t[1], t[2], axis) || insideTriangle2d(q, t[0], t[1], t[2], axis))) {
    return true;
  }
  for (int k = 0; k < 3; ++k) {
    if (segmentsMeet2d(p, q, t[k], t[(k + 1) % 3], axis)) return true;
  }
  return false;
}

// --- In space --------------------------------------------------------------------------------

// A triangle with what the tests below ask of it: whether it is collapsed onto a line (or a point),
// and otherwise a projection axis along which it stays a proper triangle (that projection is
// one-to-one on the triangle's plane, so any coplanar question can be answered in it).
struct TriangleShape {
  const Vec3* v;
  bool collapsed = false;
  int axis = 2;
};

TriangleShape shapeOf(const Vec3 v[3]) {
  TriangleShape shape{v};
  // Prefer the axis the normal points most along (best conditioned projection); any axis whose
  // exact orientation is nonzero is correct.
  int preferred = 0;
  (v[1] - v[0]).cross(v[2] - v[0]).cwiseAbs().maxCoeff(&preferred);
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int axis = (preferred + attempt) % 3;
    if (orient2d(v[0], v[1], v[2], axis) != 0) {
      shape.axis = axis;
      return shape;
    }
  }
  shape.collapsed = true;
  return shape;
}

// The two extreme points of collinear points: their convex hull is the segment between them.
std::pair<Vec3, Vec3> extremes(const Vec3 v[3]) {
  return {lexMin(lexMin(v[0], v[1]), v[2]), lexMax(lexMax(v[0], v[1]), v[2])};
}

// Closed segments [p, q] and [r, s] meet in space; either may be a point. Segments that are not
// coplanar never meet. Coplanar ones meet exactly when their projections meet along all three
// axes: at least one projection is one-to-one on their common plane (or line), and meeting in
// space implies meeting in every projection.
bool segmentsMeet(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  if (orient3d(p, q, r, s) != 0) return false;
  return segmentsMeet2d(p, q, r, s, 0) && segmentsMeet2d(p, q, r, s, 1) && segmentsMeet2d(p, q, r, s, 2);
}

// Closed segment [p, q] (possibly a point) meets closed triangle t (possibly collapsed).
// `pSide` and `qSide` are orient3d(t, p) and orient3d(t, q), computed by the caller, who often
// has them already; unused when t is collapsed.
bool segmentMeetsTriangle(const Vec3& p, const Vec3& q, const TriangleShape& t, int pSide, int qSide) {
  if (t.collapsed) {
    const auto [lo, hi] = extremes(t.v);
    return segmentsMeet(p, q, lo, hi);
  }
  if (pSide * qSide > 0) return false;  // strictly on one side of the plane
  if (pSide == 0 && qSide == 0) return segmentMeetsTriangle2d(p, q, t.v, t.axis);  // in the plane
  // The line through p and q crosses the plane at one point, which lies on the segment. That point
  // is in the closed triangle exactly when the line passes on the same side of all three edge
  // lines (or touches them): the signed volumes below then never take both strict signs.
  const Vec3* v = t.v;
  const int s0 = orient3d(p, q, v[0], v[1]), s1 = orient3d(p, q, v[1], v[2]), s2 = orient3d(p, q, v[2], v[0]);
  const bool anyPositive = s0 > 0 || s1 > 0 || s2 > 0;
  const bool anyNegative = s0 < 0 || s1 < 0 || s2 < 0;
  return !(anyPositive && anyNegative);
}

bool segmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3 t[3]) {
  const TriangleShape shape = shapeOf(t);
  if (shape.collapsed) return segmentMeetsTriangle(p, q, shape, 0, 0);
  return segmentMeetsTriangle(p, q, shape, orient3d(t[0], t[1], t[2], p), orient3d(t[0], t[1], t[2], q));
}

// Coplanar closed triangles, `a` proper: compare them in the projection along a's axis, which is
// one-to-one on the common plane.
bool coplanarTrianglesMeet(const Vec3 a[3], const Vec3 b[3], int axis) {
  const bool bProper = orient2d(b[0], b[1], b[2], axis) != 0;
  for (int k = 0; k < 3; ++k) {
    if (insideTriangle2d(b[k], a[0], a[1], a[2], axis)) return true;
    if (bProper && insideTriangle2d(a[k], b[0], b[1], b[2], axis)) return true;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (segmentsMeet2d(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3], axis)) return true;
    }
  }
  return false;
}

bool strictlyOneSide(const int side[3]) {
  return (side[0] > 0 && side[1] > 0 && side[2] > 0) || (side[0] < 0 && side[1] < 0 && side[2] < 0);
}

// --- Triangles of one mesh sharing corners ----------------------------------------------------

// The triangles (v, p, q) and (v, r, s) meet somewhere other than v. Each is first cut into
// "fans" from v whose far side does not contain v (a proper triangle is one fan; one collapsed
// onto a segment through v is the two segments from v). For two fans (v, p, q) and (v, r, s), any
// common point x != v lies on a ray from v that leaves each fan through its far side, at a point
// of [p, q] and of [r, s]; the nearer of the two lies in both fans. So the fans meet beyond v
// exactly when [p, q] meets (v, r, s) or [r, s] meets (v, p, q) (neither far side contains v).
bool meetBeyondSharedCorner(const Vec3& v, const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  struct Fan {
    Vec3 near, far;  // the fan's far side [near, far], a point when near == far
  };
  auto fansOf = [&v](const Vec3& a, const Vec3& b, Fan fans[2]) {
    if (!onSegment(v, a, b)) {
      fans[0] = {a, b};
      return 1;
    }
    int count = 0;
    if (a != v) fans[count++] = {a, a};
    if (b != v) fans[count++] = {b, b};
    return count;
  };
  Fan fansA[2], fansB[2];
  const int countA = fansOf(p, q, fansA), countB = fansOf(r, s, fansB);
  for (int i = 0; i < countA; ++i) {
    for (int j = 0; j < countB; ++j) {
      const Vec3 fanA[3] = {v, fansA[i].near, fansA[i].far};
      const Vec3 fanB[3] = {v, fansB[j].near, fansB[j].far};
      if (segmentMeetsTriangle(fansA[i].near, fansA[i].far, fanB)) return true;
      if (segmentMeetsTriangle(fansB[j].near, fansB[j].far, fanA)) return true;
    }
  }
  return false;
}

// The triangles (u, w, a) and (u, w, b) meet somewhere off their shared edge [u, w].
bool meetBeyondSharedEdge(const Vec3& u, const Vec3& w, const Vec3& a, const Vec3& b) {
  if (u == w) return meetBeyondSharedCorner(u, w, a, w, b);  // the edge is a single point
  // Planes that cross meet in the line through u and w, and a proper triangle meets that line only
  // along its edge [u, w].
  if (orient3d(u, w, a, b) != 0) return false;
  // Coplanar. If (u, w, a) is proper, compare sides of the line uw in a projection that is
  // one-to-one on its plane: the same side means the triangles overlap next to the edge; the
  // other side, or b on the line (a triangle collapsed onto the line meets a proper one only
  // along [u, w]), means they touch only along the edge.
  for (int axis = 0; axis < 3; ++axis) {
    const int sideA = orient2d(u, w, a, axis);
    if (sideA != 0) return orient2d(u, w, b, axis) == sideA;
  }
  // (u, w, a) is collapsed onto the line; if (u, w, b) is proper, they touch only along [u, w].
  for (int axis = 0; axis < 3; ++axis) {
    if (orient2d(u, w, b, axis) != 0) return false;
  }
  // All four points on one line: both triangles are segments containing [u, w]; they overlap
  // beyond it when a and b stick out past the same end.
  const Vec3& lo = lexMin(u, w);
  const Vec3& hi = lexMax(u, w);
  return (lexLess(hi, a) && lexLess(hi, b)) || (lexLess(a, lo) && lexLess(b, lo));
}

}  // namespace

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
  const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
  const double wx = d.x() - a.x(), wy = d.y() - a.y(), wz = d.z() - a.z();
  const double vywz = vy * wz, vzwy = vz * wy;
  const double vzwx = vz * wx, vxwz = vx * wz;
  const double vxwy = vx * wy, vywx = vy * wx;
  const double det = ux * (vywz - vzwy) + uy * (vzwx - vxwz) + uz * (vxwy - vywx);
  const double permanent = std::fabs(ux) * (std::fabs(vywz) + std::fabs(vzwy)) +
                           std::fabs(uy) * (std::fabs(vzwx) + std::fabs(vxwz)) +
                           std::fabs(uz) * (std::fabs(vxwy) + std::fabs(vywx));
  // An infinite or NaN permanent fails this test too and goes to the exact evaluation.
  if (permanent >= kMinFilteredPermanent) {
    const double bound = kOrient3dErrorBound * permanent;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  return exactOrient3dSign(a, b, c, d);
}

bool trianglesIntersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1,
                        const Vec3& b2) {
  const Vec3 a[3] = {a0, a1, a2};
  const Vec3 b[3] = {b0, b1, b2};
  // Quick rejection: one triangle strictly on one side of the other's plane. (A collapsed
  // triangle gives all zeros here and is never rejected this way.)
  int bAgainstPlaneA[3], aAgainstPlaneB[3];  // orient3d of each corner against the other's plane
  for (int k = 0; k < 3; ++k) bAgainstPlaneA[k] = orient3d(a0, a1, a2, b[k]);
  if (strictlyOneSide(bAgainstPlaneA)) return false;
  for (int k = 0; k < 3; ++k) aAgainstPlaneB[k] = orient3d(b0, b1, b2, a[k]);
  if (strictlyOneSide(aAgainstPlaneB)) return false;

  const TriangleShape shapeA = shapeOf(a);
  const TriangleShape shapeB = shapeOf(b);
  if (!shapeA.collapsed && bAgainstPlaneA[0] == 0 && bAgainstPlaneA[1] == 0 && bAgainstPlaneA[2] == 0) {
    return coplanarTrianglesMeet(a, b, shapeA.axis);
  }
  for (int k = 0; k < 3; ++k) {
    const int next = (k + 1) % 3;
    if (segmentMeetsTriangle(a[k], a[next], shapeB, aAgainstPlaneB[k], aAgainstPlaneB[next])) return true;
    if (segmentMeetsTriangle(b[k], b[next], shapeA, bAgainstPlaneA[k], bAgainstPlaneA[next])) return true;
  }
  return false;
}

bool meshTrianglesIntersect(const Vec3 a[3], const int ida[3], const Vec3 b[3], const int idb[3]) {
  // Corner k of a is shared with corner sharedIn[k] of b (-1: not shared).
  int sharedIn[3] = {-1, -1, -1};
  int sharedCount = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (ida[i] == idb[j]) {
        sharedIn[i] = j;
        ++sharedCount;
      }
    }
  }
  // Shared corners take a's positions (the two triangles' copies are the same mesh vertex).
  switch (sharedCount) {
    case 0:
      return trianglesIntersect(a[0], a[1], a[2], b[0], b[1], b[2]);
    case 1: {
      const int i = static_cast<int>(std::find_if(sharedIn, sharedIn + 3, [](int j) { return j >= 0; }) - sharedIn);
      const int j = sharedIn[i];
      return meetBeyondSharedCorner(a[i], a[(i + 1) % 3], a[(i + 2) % 3], b[(j + 1) % 3], b[(j + 2) % 3]);
    }
    case 2: {
      const int loneA = static_cast<int>(std::find(sharedIn, sharedIn + 3, -1) - sharedIn);
      const int u = (loneA + 1) % 3, w = (loneA + 2) % 3;
      int loneB = 0;
      while (loneB == sharedIn[u] || loneB == sharedIn[w]) ++loneB;
      return meetBeyondSharedEdge(a[u], a[w], a[loneA], b[loneB]);
    }
    default:
      // The same three corners: a duplicated face covers the other one entirely, which is more
      // than its shared edges unless it is collapsed onto them.
      return !collinear(a[0], a[1], a[2]);
  }
}

}  // namespace weft
