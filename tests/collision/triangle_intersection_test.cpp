#include "collision/triangle_intersection.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <gmpxx.h>

#include "collision/bvh.h"
#include "support/collision_meshes.h"

namespace weft {
namespace {

// The reference: the same determinant in GMP rationals, which hold every double exactly.
int rationalOrient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  mpq_class m[3][3];
  for (int k = 0; k < 3; ++k) {
    m[0][k] = mpq_class(b[k]) - mpq_class(a[k]);
    m[1][k] = mpq_class(c[k]) - mpq_class(a[k]);
    m[2][k] = mpq_class(d[k]) - mpq_class(a[k]);
  }
  const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                        m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                        m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return sgn(det);
}

// What plain double arithmetic says.
int naiveOrient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double det = (b - a).dot((c - a).cross(d - a));
  return (det > 0) - (det < 0);
}

Vec3 ulpsFrom(const Vec3& p, int dx, int dy, int dz) {
  Vec3 q = p;
  const int steps[3] = {dx, dy, dz};
  for (int k = 0; k < 3; ++k) {
    const double direction = steps[k] > 0 ? INFINITY : -INFINITY;
    for (int s = 0; s < std::abs(steps[k]); ++s) q[k] = std::nextafter(q[k], direction);
  }
  return q;
}

TEST(Orient3d, ExactOnPointsPerturbedOffALineWhereDoublesGetTheSignWrong) {
  // a, b, c nearly on one line (so the plane through them is nearly undefined) and d nearby: the
  // classic setting where rounding in the differences flips the computed sign.
  const Vec3 b(12.0, 12.0, 12.0), c(24.0, 24.0, 24.0), d(0.1, 0.7, 0.3);
  const Vec3 base(0.5, 0.5, 0.5);
  int disagreements = 0, zeros = 0, cases = 0;
  for (int i = -8; i <= 8; ++i) {
    for (int j = -8; j <= 8; ++j) {
      for (int k = -2; k <= 2; ++k) {
        const Vec3 a = ulpsFrom(base, i, j, k);
        const int exact = rationalOrient3d(a, b, c, d);
        EXPECT_EQ(orient3d(a, b, c, d), exact) << i << " " << j << " " << k;
        disagreements += naiveOrient3d(a, b, c, d) != exact ? 1 : 0;
        zeros += exact == 0 ? 1 : 0;
        ++cases;
      }
    }
  }
  // The test only means something if plain doubles fail here.
  EXPECT_GT(disagreements, cases / 20);
  EXPECT_GT(zeros, 0);
}

TEST(Orient3d, ExactForPointsWithinAnUlpOfATiltedPlane) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto randomPoint = [&] { return Vec3(unit(rng), unit(rng), unit(rng)); };
  int disagreements = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a = randomPoint(), b = randomPoint(), c = randomPoint();
    // A point on the plane (rounded), then nudged by a few ulps.
    const double s = unit(rng), t = unit(rng);
    const Vec3 onPlane = a + s * (b - a) + t * (c - a);
    const Vec3 d = ulpsFrom(onPlane, trial % 3 - 1, trial / 3 % 3 - 1, trial / 9 % 3 - 1);
    const int exact = rationalOrient3d(a, b, c, d);
    ASSERT_EQ(orient3d(a, b, c, d), exact) << "trial " << trial;
    // Swapping two points flips the sign; a cyclic shift of the first three keeps it.
    EXPECT_EQ(orient3d(b, a, c, d), -exact);
    EXPECT_EQ(orient3d(b, c, a, d), exact);
    disagreements += naiveOrient3d(a, b, c, d) != exact ? 1 : 0;
  }
  EXPECT_GT(disagreements, 0);
}

TEST(Orient3d, ExactlyCoplanarPointsGiveZeroAndTheSignFollowsTheNormal) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(orient3d(a, b, c, Vec3(0.3, 0.7, 0.0)), 0);
  EXPECT_EQ(orient3d(a, b, c, Vec3(0.3, 0.7, 1e-300)), 1);   // counter-clockwise normal is +z
  EXPECT_EQ(orient3d(a, b, c, Vec3(5.0, -3.0, -4.9e-324)), -1);  // the smallest subnormal
  // A tilted plane with exactly representable points: z = x + 2y.
  const Vec3 p(0.125, 0.5, 1.125), q(-3.0, 0.25, -2.5), r(1.5, -1.0, -0.5), s(0.0625, 0.0625, 0.1875);
  EXPECT_EQ(orient3d(p, q, r, s), 0);
  EXPECT_EQ(orient3d(p, q, r, ulpsFrom(s, 0, 0, 1)), -orient3d(p, q, r, ulpsFrom(s, 0, 0, -1)));
  EXPECT_NE(orient3d(p, q, r, ulpsFrom(s, 0, 0, 1)), 0);
}

TEST(Orient3d, ExactForHugeAndTinyCoordinates) {
  // The same near-degenerate configurations scaled by powers of two (which changes no sign):
  // products overflow or underflow in doubles, and the expansions give way to GMP.
  std::mt19937 rng(32);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto randomPoint = [&] { return Vec3(unit(rng), unit(rng), unit(rng)); };
  for (int scaleExponent : {-1070, -1000, -600, -300, 300, 600, 1000}) {
    for (int trial = 0; trial < 100; ++trial) {
      const Vec3 a = randomPoint(), b = randomPoint(), c = randomPoint();
      const Vec3 d = ulpsFrom(a + 0.5 * (b - a) + 0.25 * (c - a), trial % 3 - 1, 0, 1);
      const int unscaled = orient3d(a, b, c, d);
      ASSERT_EQ(unscaled, rationalOrient3d(a, b, c, d));
      auto scaled = [&](const Vec3& p) {
        return Vec3(std::ldexp(p.x(), scaleExponent), std::ldexp(p.y(), scaleExponent),
                    std::ldexp(p.z(), scaleExponent));
      };
      const Vec3 as = scaled(a), bs = scaled(b), cs = scaled(c), ds = scaled(d);
      // Scaling down to subnormals rounds the coordinates; compare with the rational answer for
      // the scaled coordinates themselves.
      EXPECT_EQ(orient3d(as, bs, cs, ds), rationalOrient3d(as, bs, cs, ds)) << "2^" << scaleExponent;
      if (scaleExponent >= -1000) {
        EXPECT_EQ(orient3d(as, bs, cs, ds), unscaled) << "2^" << scaleExponent;
      }
    }
  }
}

// --- trianglesIntersect ---------------------------------------------------------------------

struct Tri {
  Vec3 v[3];
};

bool intersect(const Tri& a, const Tri& b) {
  return trianglesIntersect(a.v[0], a.v[1], a.v[2], b.v[0], b.v[1], b.v[2]);
}

// The answer must not depend on the order of the triangles or of their corners.
void expectIntersect(const Tri& a, const Tri& b, bool expected, const char* what) {
  const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& o : orders) {
    const Tri ap{{a.v[o[0]], a.v[o[1]], a.v[o[2]]}};
    const Tri bp{{b.v[o[2]], b.v[o[0]], b.v[o[1]]}};
    EXPECT_EQ(intersect(ap, bp), expected) << what;
    EXPECT_EQ(intersect(bp, ap), expected) << what << " (swapped)";
  }
}

TEST(TriangleIntersection, CrossingTouchingAndSeparateTriangles) {
  const Tri flat{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};
  expectIntersect(flat, Tri{{Vec3(0.2, 0.2, -1), Vec3(0.3, 0.2, 1), Vec3(0.2, 0.3, 1)}}, true, "piercing");
  expectIntersect(flat, Tri{{Vec3(0.2, 0.2, 0.1), Vec3(0.3, 0.2, 1), Vec3(0.2, 0.3, 1)}}, false, "above");
  expectIntersect(flat, Tri{{Vec3(0.2, 0.2, 0), Vec3(0.3, 0.2, 1), Vec3(0.2, 0.3, 1)}}, true, "vertex on the face");
  expectIntersect(flat, Tri{{Vec3(0.5, 0.5, 0), Vec3(0.5, 0.5, 1), Vec3(1, 1, 1)}}, true, "vertex on the edge");
  expectIntersect(flat, Tri{{Vec3(1, 0, 0), Vec3(2, 0, 1), Vec3(2, 1, 1)}}, true, "corner on corner");
  expectIntersect(flat, Tri{{Vec3(0.5, -1, 0), Vec3(0.5, 1, 0), Vec3(0.5, 0, 1)}}, true, "edge across the face");
  expectIntersect(flat, Tri{{Vec3(0.6, 0.6, -1), Vec3(0.6, 0.6, 1), Vec3(2, 2, 0)}}, false, "edge past the hypotenuse");
  expectIntersect(flat, Tri{{Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1), Vec3(2, 2, 0)}}, true,
                  "edge through the hypotenuse");
  expectIntersect(flat, Tri{{Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0)}}, false, "coplanar apart");
}

TEST(TriangleIntersection, ExactAtTheLastBit) {
  const Tri flat{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};
  const double tiny = 4.9e-324;  // the smallest subnormal
  expectIntersect(flat, Tri{{Vec3(0.2, 0.2, tiny), Vec3(0.3, 0.2, 1), Vec3(0.2, 0.3, 1)}}, false, "a subnormal above");
  // A vertex exactly on the hypotenuse x + y = 1, and one ulp outside it.
  const Vec3 onEdge(0.75, 0.25, 0.0);
  expectIntersect(flat, Tri{{onEdge, Vec3(0.75, 0.25, 1), Vec3(2, 2, 1)}}, true, "on the hypotenuse");
  expectIntersect(flat, Tri{{ulpsFrom(onEdge, 1, 0, 0), Vec3(0.75, 0.25, 1), Vec3(2, 2, 1)}}, false, "an ulp outside");
  // A tilted face (plane z = x + 2y, exactly representable) and a needle through a corner of it.
  const Tri tilted{{Vec3(0.125, 0.5, 1.125), Vec3(-3.0, 0.25, -2.5), Vec3(1.5, -1.0, -0.5)}};
  const Vec3 corner = tilted.v[0];
  expectIntersect(tilted, Tri{{corner, ulpsFrom(corner, 0, 0, 1), Vec3(9, 9, 9)}}, true, "touching the tilted corner");
  expectIntersect(tilted, Tri{{ulpsFrom(corner, 0, 1, 0), Vec3(0.125, 1.0, 4.0), Vec3(0.125, 1.0, 5.0)}}, false,
                  "an ulp past the corner, pointing away");
}

TEST(TriangleIntersection, CoplanarOverlapContainmentAndTouching) {
  const Tri flat{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};
  expectIntersect(flat, Tri{{Vec3(0.5, 0.5, 0), Vec3(-0.5, 0.2, 0), Vec3(0.2, -0.5, 0)}}, true, "overlapping");
  expectIntersect(flat, Tri{{Vec3(0.1, 0.1, 0), Vec3(0.2, 0.1, 0), Vec3(0.1, 0.2, 0)}}, true, "contained");
  expectIntersect(flat, Tri{{Vec3(-1, -1, 0), Vec3(3, -1, 0), Vec3(-1, 3, 0)}}, true, "containing");
  expectIntersect(flat, Tri{{Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0)}}, true, "sharing a corner point");
  expectIntersect(flat, Tri{{Vec3(0.5, 0.5, 0), Vec3(1, 1, 0), Vec3(2, 0, 0)}}, true, "touching along the hypotenuse");
  expectIntersect(flat, Tri{{ulpsFrom(Vec3(0.5, 0.5, 0), 1, 1, 0), Vec3(1, 1, 0), Vec3(2, 0.5, 0)}}, false,
                  "an ulp off the hypotenuse");
  // A star of David: the edges cross but no corner lies in the other triangle.
  const Tri up{{Vec3(0, 0, 1), Vec3(2, 0, 1), Vec3(1, 2, 1)}};
  const Tri down{{Vec3(0, 1.4, 1), Vec3(1, -0.6, 1), Vec3(2, 1.4, 1)}};
  expectIntersect(up, down, true, "star");
}

TEST(TriangleIntersection, CollapsedTriangles) {
  const Tri flat{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};
  expectIntersect(flat, Tri{{Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(0.2, 0.2, 0.5)}}, true, "needle through");
  expectIntersect(flat, Tri{{Vec3(0.2, 0.2, 0.5), Vec3(0.2, 0.2, 1), Vec3(0.2, 0.2, 0.7)}}, false, "needle above");
  expectIntersect(flat, Tri{{Vec3(0.2, 0.2, 0), Vec3(0.2, 0.2, 0), Vec3(0.2, 0.2, 0)}}, true, "point on the face");
  expectIntersect(flat, Tri{{Vec3(2, 2, 0), Vec3(2, 2, 0), Vec3(2, 2, 0)}}, false, "point beside it");
  expectIntersect(flat, Tri{{Vec3(-1, 0.5, 0), Vec3(2, 0.5, 0), Vec3(0, 0.5, 0)}}, true,
                  "segment across, in the plane");
  expectIntersect(flat, Tri{{Vec3(-1, 2, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)}}, false, "segment beside, in the plane");
  // Two collapsed triangles: collinear overlapping, collinear apart, crossing, skew.
  const Tri along{{Vec3(0, 0, 0), Vec3(2, 2, 2), Vec3(1, 1, 1)}};
  expectIntersect(along, Tri{{Vec3(1.5, 1.5, 1.5), Vec3(3, 3, 3), Vec3(4, 4, 4)}}, true, "collinear overlap");
  expectIntersect(along, Tri{{Vec3(2.5, 2.5, 2.5), Vec3(3, 3, 3), Vec3(4, 4, 4)}}, false, "collinear apart");
  expectIntersect(along, Tri{{Vec3(0, 2, 0), Vec3(2, 0, 2), Vec3(0, 2, 0)}}, true, "crossing segments");
  expectIntersect(along, Tri{{Vec3(0, 2, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)}}, false, "skew segments");
}

// An independent reference for triangles with small integer coordinates: two closed triangles
// (neither collapsed... at most one of them) are disjoint exactly when some axis separates their
// projections. The candidate axes cover both triangles seen as flat prisms: normals, edge
// crosses, and in-plane edge normals. Integer arithmetic, so exact.
using IVec = std::array<std::int64_t, 3>;
IVec sub(const IVec& a, const IVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
IVec cross(const IVec& a, const IVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
std::int64_t dot(const IVec& a, const IVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool isZero(const IVec& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

bool separatingAxisIntersect(const std::array<IVec, 3>& a, const std::array<IVec, 3>& b) {
  std::vector<IVec> axes;
  const IVec na = cross(sub(a[1], a[0]), sub(a[2], a[0])), nb = cross(sub(b[1], b[0]), sub(b[2], b[0]));
  std::vector<IVec> edgesA, edgesB;
  for (int k = 0; k < 3; ++k) {
    edgesA.push_back(sub(a[(k + 1) % 3], a[k]));
    edgesB.push_back(sub(b[(k + 1) % 3], b[k]));
  }
  std::vector<IVec> directionsA = edgesA, directionsB = edgesB;
  directionsA.push_back(na);
  directionsB.push_back(nb);
  axes.push_back(na);
  axes.push_back(nb);
  for (const IVec& da : directionsA) {
    for (const IVec& db : directionsB) axes.push_back(cross(da, db));
  }
  for (const IVec& e : edgesA) axes.push_back(cross(na, e));
  for (const IVec& e : edgesB) axes.push_back(cross(nb, e));
  for (const IVec& axis : axes) {
    if (isZero(axis)) continue;
    std::int64_t loA = INT64_MAX, hiA = INT64_MIN, loB = INT64_MAX, hiB = INT64_MIN;
    for (int k = 0; k < 3; ++k) {
      loA = std::min(loA, dot(axis, a[k]));
      hiA = std::max(hiA, dot(axis, a[k]));
      loB = std::min(loB, dot(axis, b[k]));
      hiB = std::max(hiB, dot(axis, b[k]));
    }
    if (hiA < loB || hiB < loA) return false;
  }
  return true;
}

TEST(TriangleIntersection, AgreesWithSeparatingAxesOnRandomLatticeTriangles) {
  // Coordinates in {-2..2}: many touching, coplanar and collinear configurations.
  std::mt19937 rng(33);
  std::uniform_int_distribution<int> coordinate(-2, 2);
  auto randomTriangle = [&] {
    std::array<IVec, 3> t;
    for (auto& p : t) p = {coordinate(rng), coordinate(rng), coordinate(rng)};
    return t;
  };
  auto toVec = [](const IVec& p) { return Vec3(double(p[0]), double(p[1]), double(p[2])); };
  int hits = 0, coplanar = 0;
  for (int trial = 0; trial < 30000; ++trial) {
    std::array<IVec, 3> a = randomTriangle(), b = randomTriangle();
    if (trial % 4 == 0) {  // both in the plane z = 1: the coplanar cases
      for (auto& p : a) p[2] = 1;
      for (auto& p : b) p[2] = 1;
    }
    const bool aCollapsed = isZero(cross(sub(a[1], a[0]), sub(a[2], a[0])));
    const bool bCollapsed = isZero(cross(sub(b[1], b[0]), sub(b[2], b[0])));
    if (aCollapsed && bCollapsed) continue;  // the reference's axes do not cover two segments
    const bool expected = separatingAxisIntersect(a, b);
    ASSERT_EQ(trianglesIntersect(toVec(a[0]), toVec(a[1]), toVec(a[2]), toVec(b[0]), toVec(b[1]), toVec(b[2])),
              expected)
        << "trial " << trial;
    hits += expected ? 1 : 0;
    const IVec na = cross(sub(a[1], a[0]), sub(a[2], a[0]));
    coplanar += !aCollapsed && dot(na, sub(b[0], a[0])) == 0 && dot(na, sub(b[1], a[0])) == 0 &&
                dot(na, sub(b[2], a[0])) == 0;
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(coplanar, 3000);
}

// --- meshTrianglesIntersect -----------------------------------------------------------------

bool meshIntersect(const Tri& a, std::array<int, 3> ida, const Tri& b, std::array<int, 3> idb) {
  return meshTrianglesIntersect(a.v, ida.data(), b.v, idb.data());
}

TEST(TriangleIntersection, MeshNeighboursSharingAnEdge) {
  const Vec3 u(0, 0, 0), w(1, 0, 0);
  const Tri a{{u, w, Vec3(0.5, 1, 0)}};
  // Flat neighbours, and neighbours bent at any angle: contact only along the shared edge.
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{w, u, Vec3(0.5, -1, 0)}}, {1, 0, 3}));
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{w, u, Vec3(0.5, 0.3, 1)}}, {1, 0, 3}));
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{w, u, Vec3(0.5, 1e-300, 1e-300)}}, {1, 0, 3}));
  // Folded flat onto each other: they overlap next to the edge.
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{w, u, Vec3(0.2, 3, 0)}}, {1, 0, 3}));
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{u, w, Vec3(0.5, 1e-300, 0)}}, {0, 1, 3}));
  // The shared edge comes in any corner order; the result does not depend on it.
  EXPECT_TRUE(meshIntersect(Tri{{Vec3(0.5, 1, 0), u, w}}, {2, 0, 1}, Tri{{Vec3(0.2, 3, 0), w, u}}, {3, 1, 0}));
  // Without the ids the shared edge itself is an intersection.
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{w, u, Vec3(0.5, -1, 0)}}, {4, 5, 3}));
  // A collapsed neighbour lying on the shared edge's line, beyond its end: it touches only at w.
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{u, w, Vec3(2, 0, 0)}}, {0, 1, 3}));
  // Both collapsed onto that line: they overlap beyond the edge when they stick out past the
  // same end.
  EXPECT_TRUE(meshIntersect(Tri{{u, w, Vec3(2, 0, 0)}}, {0, 1, 2}, Tri{{u, w, Vec3(3, 0, 0)}}, {0, 1, 3}));
  EXPECT_FALSE(meshIntersect(Tri{{u, w, Vec3(2, 0, 0)}}, {0, 1, 2}, Tri{{u, w, Vec3(-1, 0, 0)}}, {0, 1, 3}));
  EXPECT_FALSE(meshIntersect(Tri{{u, w, Vec3(0.5, 0, 0)}}, {0, 1, 2}, Tri{{u, w, Vec3(0.7, 0, 0)}}, {0, 1, 3}));
  // A shared edge of zero length: the triangles are segments from that point.
  EXPECT_FALSE(meshIntersect(Tri{{u, u, Vec3(1, 0, 0)}}, {0, 1, 2}, Tri{{u, u, Vec3(0, 1, 0)}}, {0, 1, 3}));
  EXPECT_TRUE(meshIntersect(Tri{{u, u, Vec3(1, 0, 0)}}, {0, 1, 2}, Tri{{u, u, Vec3(2, 0, 0)}}, {0, 1, 3}));
}

TEST(TriangleIntersection, MeshNeighboursSharingACorner) {
  const Vec3 v(0, 0, 0);
  const Tri a{{v, Vec3(1, 0, 0), Vec3(0, 1, 0)}};
  // Fanned around the shared corner, flat or bent, and touching only there.
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(-1, 0, 0), Vec3(0, -1, 0)}}, {0, 3, 4}));
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(-1, 1, 1), Vec3(-1, -1, 1)}}, {0, 3, 4}));
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(-1, 1, 1), Vec3(1, -1, 1)}}, {0, 3, 4}));  // above, but for v
  // Folded through: the neighbour's far edge passes under a's interior while it leaves v above.
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(0.3, 0.3, -1), Vec3(0.5, 0.1, 1)}}, {0, 3, 4}));
  // Cutting through a from the corner: the intersection is a segment starting at v.
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(1, 1, 1), Vec3(1, 1, -1)}}, {0, 3, 4}));
  // Coplanar and overlapping in a wedge at v; coplanar and touching along a ray from v.
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(1, 1, 0), Vec3(2, 0.5, 0)}}, {0, 3, 4}));
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(2, 0, 0), Vec3(2, -1, 0)}}, {0, 3, 4}));
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{v, ulpsFrom(Vec3(2, 0, 0), 0, -1, 0), Vec3(2, -1, 0)}}, {0, 3, 4}));
  // Standing on a's edge from v: b meets a's plane in a segment along that edge.
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(1, 0, 1), Vec3(0, 0, -1)}}, {0, 3, 4}));
  // Crossing a's plane only outside a: b meets the plane in a segment from v away from a.
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(-1, 0, 1), Vec3(0.5, 0.5, -1)}}, {0, 3, 4}));
  // Its diagonal edge (v to (1, 1, 0)) lies in a's plane and runs through a's interior.
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(1, 1, 0), Vec3(1, 1, 1)}}, {0, 3, 4}));
  // A neighbour collapsed onto a segment from v or through v: only what lies beyond v counts.
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(-1, -1, 0), Vec3(-2, -2, 0)}}, {0, 3, 4}));
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(-1, 1, 0), Vec3(1, -1, 0)}}, {0, 3, 4}));
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(-1, 1, 1), Vec3(1, -1, -1)}}, {0, 3, 4}));
  EXPECT_TRUE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(-1, -1, 0), Vec3(0.2, 0.2, 0)}}, {0, 3, 4}));
  EXPECT_FALSE(meshIntersect(a, {0, 1, 2}, Tri{{v, Vec3(-1, -1, 1), Vec3(0.2, 0.2, -0.2)}}, {0, 3, 4}));
}

TEST(TriangleIntersection, MeshNeighboursAgreeWithAnIntegerReferenceOnRandomLatticeTriangles) {
  // Proper triangles with corners in {-2..2}^3 sharing a corner or an edge. References, in
  // integer arithmetic: sharing corner v, the triangles meet elsewhere exactly when the side
  // opposite v in one meets the other triangle (the opposite side of a proper triangle does not
  // contain v); sharing edge uw, exactly when they are coplanar and on the same side of uw.
  std::mt19937 rng(34);
  std::uniform_int_distribution<int> coordinate(-2, 2);
  auto randomPoint = [&] { return IVec{coordinate(rng), coordinate(rng), coordinate(rng)}; };
  auto toVec = [](const IVec& p) { return Vec3(double(p[0]), double(p[1]), double(p[2])); };
  auto proper = [](const IVec& p, const IVec& q, const IVec& r) { return !isZero(cross(sub(q, p), sub(r, p))); };
  int cornerHits = 0, edgeHits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    IVec v = randomPoint(), a1 = randomPoint(), a2 = randomPoint(), b1 = randomPoint(), b2 = randomPoint();
    if (trial % 3 == 0) {  // all in the plane z = 0: the coplanar cases
      for (IVec* p : {&v, &a1, &a2, &b1, &b2}) (*p)[2] = 0;
    }
    if (!proper(v, a1, a2) || !proper(v, b1, b2)) continue;
    const Tri a{{toVec(v), toVec(a1), toVec(a2)}}, b{{toVec(b1), toVec(v), toVec(b2)}};

    // Shared corner v (id 0).
    const bool cornerExpected = separatingAxisIntersect({a1, a2, a2}, {v, b1, b2}) ||
                                separatingAxisIntersect({b1, b2, b2}, {v, a1, a2});
    ASSERT_EQ(meshIntersect(a, {0, 1, 2}, b, {3, 0, 4}), cornerExpected) << "corner, trial " << trial;
    cornerHits += cornerExpected ? 1 : 0;

    // Shared edge v-a1 (ids 0, 1); b's lone corner is b2.
    if (!proper(v, a1, b2)) continue;
    const IVec normalA = cross(sub(a1, v), sub(a2, v)), normalB = cross(sub(a1, v), sub(b2, v));
    const bool edgeExpected = isZero(cross(normalA, normalB)) && dot(normalA, normalB) > 0;
    const Tri bEdge{{toVec(a1), toVec(b2), toVec(v)}};
    ASSERT_EQ(meshIntersect(a, {0, 1, 2}, bEdge, {1, 5, 0}), edgeExpected) << "edge, trial " << trial;
    edgeHits += edgeExpected ? 1 : 0;
  }
  EXPECT_GT(cornerHits, 500);
  EXPECT_GT(edgeHits, 50);
}

// A grid cloth's triangles, checked pairwise through a BVH: the way tests prove that no
// self-intersection is left.
int countSelfIntersections(const CollisionMesh& mesh, const std::vector<Vec3>& x) {
  std::vector<Aabb> boxes(mesh.triangles.size());
  for (size_t t = 0; t < boxes.size(); ++t) {
    for (int v : mesh.triangles[t]) boxes[t].grow(x[v]);
  }
  Bvh tree;
  tree.build(boxes);
  int count = 0;
  tree.selfOverlappingPairs([&](int i, int j) {
    const auto& ti = mesh.triangles[i];
    const auto& tj = mesh.triangles[j];
    const Vec3 a[3] = {x[ti[0]], x[ti[1]], x[ti[2]]};
    const Vec3 b[3] = {x[tj[0]], x[tj[1]], x[tj[2]]};
    count += meshTrianglesIntersect(a, ti.data(), b, tj.data()) ? 1 : 0;
  });
  return count;
}

TEST(TriangleIntersection, ClothWithoutSelfIntersectionsUntilAVertexIsPushedThroughAnotherLayer) {
  const test::PositionedMesh cloth = test::gridMesh(64, 1.0);
  EXPECT_EQ(countSelfIntersections(cloth.mesh, cloth.x), 0);  // exactly flat: every pair coplanar

  // A smooth height field (it cannot cross itself) tilted out of the coordinate planes, so that
  // flat-ish neighbours are coplanar only up to rounding.
  std::vector<Vec3> wavy = cloth.x;
  const double c = std::cos(0.3), s = std::sin(0.3);
  for (Vec3& p : wavy) {
    const double z = 0.2 * std::sin(6.0 * p.x()) * std::cos(4.0 * p.y());
    p = Vec3(c * p.x() - s * z, p.y(), s * p.x() + c * z);
  }
  EXPECT_EQ(countSelfIntersections(cloth.mesh, wavy), 0);

  // One vertex pulled far below the sheet: its triangles form a pyramid over its convex ring and
  // meet the rest only along shared edges and corners.
  std::vector<Vec3> spike = cloth.x;
  spike[32 * 64 + 32] += Vec3(0.05, 0.0, -0.5);
  EXPECT_EQ(countSelfIntersections(cloth.mesh, spike), 0);

  // Folded in half: the right half lies mirrored over the left, 0.02 above it (the crease cells
  // stand vertical). Layers that are exactly parallel do not touch.
  std::vector<Vec3> folded = cloth.x;
  for (Vec3& p : folded) {
    if (p.x() > 0.5) p = Vec3(1.0 - p.x(), p.y(), 0.02);
  }
  EXPECT_EQ(countSelfIntersections(cloth.mesh, folded), 0);
  // Push one vertex of the top layer through the bottom one: its triangles now cross it.
  folded[32 * 64 + 48].z() = -0.01;
  EXPECT_GT(countSelfIntersections(cloth.mesh, folded), 0);
}

}  // namespace
}  // namespace weft
