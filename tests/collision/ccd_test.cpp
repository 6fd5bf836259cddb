// Continuous collision detection (ccd.h): hand-derived vertex-face and edge-edge cases with known
// contact times (through the interior, beside, grazing an edge or a corner, on the plane at t = 0
// or t = 1, parallel and degenerate configurations, zero, huge and tiny motion, a thickness), and
// a randomized check that no contact found by dense sampling in time is ever missed or reported
// late.
#include "collision/ccd.h"

#include <array>
#include <cmath>
#include <optional>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "collision/closest_points.h"

namespace weft {
namespace {

// A vertex p and a triangle (a, b, c), each at t = 0 and t = 1.
struct VertexFaceMotion {
  Vec3 p0, a0, b0, c0, p1, a1, b1, c1;
  std::optional<VertexFaceHit> ccd(double minDistance = 0.0) const {
    return vertexFaceCcd(p0, a0, b0, c0, p1, a1, b1, c1, minDistance);
  }
  Vec3 at(const Vec3& x0, const Vec3& x1, double t) const { return (1.0 - t) * x0 + t * x1; }
  double distance(double t) const {
    return closestPointOnTriangle(at(p0, p1, t), at(a0, a1, t), at(b0, b1, t), at(c0, c1, t)).distance;
  }
};

// Edge (pa, pb) and edge (qa, qb), each at t = 0 and t = 1.
struct EdgeEdgeMotion {
  Vec3 pa0, pb0, qa0, qb0, pa1, pb1, qa1, qb1;
  std::optional<EdgeEdgeHit> ccd(double minDistance = 0.0) const {
    return edgeEdgeCcd(pa0, pb0, qa0, qb0, pa1, pb1, qa1, qb1, minDistance);
  }
  Vec3 at(const Vec3& x0, const Vec3& x1, double t) const { return (1.0 - t) * x0 + t * x1; }
  double distance(double t) const {
    return closestSegmentSegment(at(pa0, pa1, t), at(pb0, pb1, t), at(qa0, qa1, t), at(qb0, qb1, t)).distance;
  }
};

// The fixed triangle of most cases: the right triangle of legs 1 in the plane z = 0.
const Vec3 kA(0, 0, 0), kB(1, 0, 0), kC(0, 1, 0);

// A vertex moving from p0 to p1 against the fixed triangle.
VertexFaceMotion vertexAgainstStillTriangle(const Vec3& p0, const Vec3& p1) {
  return {p0, kA, kB, kC, p1, kA, kB, kC};
}

void expectUnitAndFinite(const Vec3& normal) {
  EXPECT_TRUE(normal.allFinite()) << normal.transpose();
  EXPECT_NEAR(normal.norm(), 1.0, 1e-12) << normal.transpose();
}

// A hit at a time no later than the true one, and not much earlier.
void expectHitAt(const std::optional<VertexFaceHit>& hit, double trueTime, double slack = 1e-6) {
  ASSERT_TRUE(hit.has_value()) << "missed a contact at t = " << trueTime;
  EXPECT_LE(hit->t, trueTime);
  EXPECT_GE(hit->t, trueTime - slack);
  expectUnitAndFinite(hit->normal);
  EXPECT_NEAR(hit->weights[0] + hit->weights[1] + hit->weights[2], 1.0, 1e-12);
}

void expectHitAt(const std::optional<EdgeEdgeHit>& hit, double trueTime, double slack = 1e-6) {
  ASSERT_TRUE(hit.has_value()) << "missed a contact at t = " << trueTime;
  EXPECT_LE(hit->t, trueTime);
  EXPECT_GE(hit->t, trueTime - slack);
  expectUnitAndFinite(hit->normal);
  EXPECT_GE(hit->s, 0.0);
  EXPECT_LE(hit->s, 1.0);
  EXPECT_GE(hit->u, 0.0);
  EXPECT_LE(hit->u, 1.0);
}

// ---------------------------------------------------------------------------- vertex-face

TEST(CcdVertexFace, PassesThroughTheInteriorAtTheKnownTime) {
  // z(t) = 1 - 4 t crosses the plane at t = 1/4, above (0.25, 0.25).
  const auto hit = vertexAgainstStillTriangle(Vec3(0.25, 0.25, 1), Vec3(0.25, 0.25, -3)).ccd();
  expectHitAt(hit, 0.25);
  EXPECT_NEAR(hit->weights[0], 0.5, 1e-6);
  EXPECT_NEAR(hit->weights[1], 0.25, 1e-6);
  EXPECT_NEAR(hit->weights[2], 0.25, 1e-6);
  EXPECT_NEAR(hit->normal.z(), 1.0, 1e-12);  // the vertex comes from above
}

TEST(CcdVertexFace, NormalPointsToTheVertexSideAtTheStart) {
  const auto fromBelow = vertexAgainstStillTriangle(Vec3(0.25, 0.25, -1), Vec3(0.25, 0.25, 1)).ccd();
  expectHitAt(fromBelow, 0.5);
  EXPECT_NEAR(fromBelow->normal.z(), -1.0, 1e-12);
}

TEST(CcdVertexFace, MissesBesideTheTriangle) {
  // Crosses the plane at (1, 1, 0): outside (x + y = 2 > 1).
  EXPECT_FALSE(vertexAgainstStillTriangle(Vec3(1, 1, 1), Vec3(1, 1, -1)).ccd());
  // Stays above the plane.
  EXPECT_FALSE(vertexAgainstStillTriangle(Vec3(0.2, 0.2, 1), Vec3(0.2, 0.2, 0.01)).ccd());
}

TEST(CcdVertexFace, GrazesAnEdgeOrACornerExactly) {
  // Crosses the plane exactly on the hypotenuse (0.5, 0.5, 0) at t = 1/2.
  expectHitAt(vertexAgainstStillTriangle(Vec3(1, 1, 1), Vec3(0, 0, -1)).ccd(), 0.5);
  // Crosses exactly through corner a at t = 1/2.
  expectHitAt(vertexAgainstStillTriangle(Vec3(-1, -1, 1), Vec3(1, 1, -1)).ccd(), 0.5);
  // Slides within the plane, coming in from y < 0, and reaches edge ab at t = 1/4.
  expectHitAt(vertexAgainstStillTriangle(Vec3(0.5, -1, 0), Vec3(0.5, 3, 0)).ccd(), 0.25);
  // Slides within the plane along the line of edge ab, reaching corner b at t = 1/2.
  expectHitAt(vertexAgainstStillTriangle(Vec3(2, 0, 0), Vec3(0, 0, 0)).ccd(), 0.5);
  // Just beside the corner: a miss by 1e-6.
  EXPECT_FALSE(vertexAgainstStillTriangle(Vec3(-1, -1 - 2e-6, 1), Vec3(1, 1 - 2e-6, -1)).ccd());
}

TEST(CcdVertexFace, OnThePlaneAtTheStartOrAtTheEnd) {
  // On the face at t = 0: contact at once.
  expectHitAt(vertexAgainstStillTriangle(Vec3(0.2, 0.2, 0), Vec3(0.2, 0.2, 1)).ccd(), 0.0, 0.0);
  // Arrives on the face at t = 1 exactly.
  expectHitAt(vertexAgainstStillTriangle(Vec3(0.2, 0.2, 1), Vec3(0.2, 0.2, 0)).ccd(), 1.0);
  // On the plane at t = 0 but outside the face, leaving it: no contact.
  EXPECT_FALSE(vertexAgainstStillTriangle(Vec3(2, 2, 0), Vec3(2, 2, 1)).ccd());
  // On the face at t = 0 with no side to keep: the normal opposes the motion.
  const auto goingDown = vertexAgainstStillTriangle(Vec3(0.2, 0.2, 0), Vec3(0.3, 0.2, -1)).ccd();
  expectHitAt(goingDown, 0.0, 0.0);
  EXPECT_NEAR(goingDown->normal.z(), 1.0, 1e-12);
  const auto goingUp = vertexAgainstStillTriangle(Vec3(0.2, 0.2, 0), Vec3(0.3, 0.2, 1)).ccd();
  EXPECT_NEAR(goingUp->normal.z(), -1.0, 1e-12);
}

TEST(CcdVertexFace, ZeroMotion) {
  const auto touching = vertexAgainstStillTriangle(Vec3(0.3, 0.3, 0), Vec3(0.3, 0.3, 0)).ccd();
  expectHitAt(touching, 0.0, 0.0);
  EXPECT_FALSE(vertexAgainstStillTriangle(Vec3(0.3, 0.3, 1e-3), Vec3(0.3, 0.3, 1e-3)).ccd());
  // Everything collapsed to one still point: touching, with a unit normal all the same.
  const Vec3 o(1, 2, 3);
  const auto collapsed = VertexFaceMotion{o, o, o, o, o, o, o, o}.ccd();
  expectHitAt(collapsed, 0.0, 0.0);
}

TEST(CcdVertexFace, VeryLargeMotion) {
  // 1e4 m in one step, through the interior at t = 1/2.
  expectHitAt(vertexAgainstStillTriangle(Vec3(0.25, 0.25, 5e3), Vec3(0.25, 0.25, -5e3)).ccd(), 0.5);
  // The same, 1 m beside the face.
  EXPECT_FALSE(vertexAgainstStillTriangle(Vec3(2, 0.25, 5e3), Vec3(2, 0.25, -5e3)).ccd());
  // A 1e4 m triangle sweeping over a still vertex at t = 0.3 (triangle at z = 3e3 - 1e4 t).
  const Vec3 down(0, 0, -1e4), start(0, 0, 3e3);
  const VertexFaceMotion sweep{Vec3(0.2, 0.2, 0), kA + start, kB + start, kC + start,
                               Vec3(0.2, 0.2, 0), kA + start + down, kB + start + down, kC + start + down};
  expectHitAt(sweep.ccd(), 0.3);
}

// With unit-size coordinates, rounding blurs positions by ~1e-14 m, which a 1e-9 m step covers in
// ~1e-5 of the step: the reported time may be that much early (never late).
constexpr double kTinyStepSlack = 1e-4;

TEST(CcdVertexFace, TinyMotion) {
  // 1e-9 m steps: crosses at t = 1/2, or stops 1e-10 m short.
  expectHitAt(vertexAgainstStillTriangle(Vec3(0.3, 0.3, 0.5e-9), Vec3(0.3, 0.3, -0.5e-9)).ccd(), 0.5, kTinyStepSlack);
  EXPECT_FALSE(vertexAgainstStillTriangle(Vec3(0.3, 0.3, 1.1e-9), Vec3(0.3, 0.3, 0.1e-9)).ccd());
}

TEST(CcdVertexFace, BothMoving) {
  // The face rises from z = -1 to z = 1 while the vertex falls from 1 to -3: they meet at 1/3.
  const Vec3 up(0, 0, 1);
  const VertexFaceMotion motion{Vec3(0.1, 0.1, 1), kA - up, kB - up, kC - up,
                                Vec3(0.1, 0.1, -3), kA + up, kB + up, kC + up};
  expectHitAt(motion.ccd(), 1.0 / 3.0);
  // A rotating face: corner c swings from z = -1 to z = 1 while the vertex waits at height 0.1 above
  // (0.25, 0.5). The face's plane is z = z_c y, z_c(t) = -1 + 2t: it reaches the vertex when
  // z_c / 2 = 0.1, at t = 0.6.
  const VertexFaceMotion swing{Vec3(0.25, 0.5, 0.1), kA, kB, Vec3(0, 1, -1),
                               Vec3(0.25, 0.5, 0.1), kA, kB, Vec3(0, 1, 1)};
  expectHitAt(swing.ccd(), 0.6);
}

TEST(CcdVertexFace, MinDistanceCountsAsContact) {
  // The vertex glides 1 mm above the face, entering over edge x = 0 at t = 1/4.
  const VertexFaceMotion glide = vertexAgainstStillTriangle(Vec3(-0.5, 0.25, 1e-3), Vec3(1.5, 0.25, 1e-3));
  EXPECT_FALSE(glide.ccd(0.0));
  EXPECT_FALSE(glide.ccd(0.5e-3));
  // With 2 mm it is in contact once it is 2 mm from edge x = 0: sqrt(2^2 - 1^2) mm before x = 0.
  const double entry = 0.25 - std::sqrt(3.0) * 1e-3 / 2.0;
  expectHitAt(glide.ccd(2e-3), entry);
  // Already within minDistance at t = 0: contact at t = 0.
  expectHitAt(vertexAgainstStillTriangle(Vec3(0.2, 0.2, 1e-3), Vec3(0.2, 0.2, 1)).ccd(2e-3), 0.0, 0.0);
  // Coming within 2 mm of edge x = 0 from the side, in the face's plane: the normal is the direction
  // between the closest points (-x), not the face's.
  const auto sideways = vertexAgainstStillTriangle(Vec3(-0.5, 0.25, 0), Vec3(0.5, 0.25, 0)).ccd(2e-3);
  expectHitAt(sideways, (0.5 - 2e-3) / 1.0);
  EXPECT_NEAR(sideways->normal.x(), -1.0, 1e-9);
}

// ---------------------------------------------------------------------------- edge-edge

TEST(CcdEdgeEdge, CrossingEdgesAtTheKnownTime) {
  // Edge along x at z = 0; an edge along y falls from z = 1 to z = -1, crossing it at t = 1/2.
  const EdgeEdgeMotion motion{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, 1), Vec3(0.5, 1, 1),
                              Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, -1), Vec3(0.5, 1, -1)};
  const auto hit = motion.ccd();
  expectHitAt(hit, 0.5);
  EXPECT_NEAR(hit->s, 0.75, 1e-6);
  EXPECT_NEAR(hit->u, 0.5, 1e-6);
  // From the second edge towards the first edge's side at t = 0 (below it).
  EXPECT_NEAR(hit->normal.z(), -1.0, 1e-12);
}

TEST(CcdEdgeEdge, PassingBesideIsAMiss) {
  // The same, but the falling edge ends short of the first one (y in [0.1, 2]).
  const EdgeEdgeMotion motion{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.1, 1), Vec3(0.5, 2, 1),
                              Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.1, -1), Vec3(0.5, 2, -1)};
  EXPECT_FALSE(motion.ccd());
}

TEST(CcdEdgeEdge, ParallelEdges) {
  // Parallel edges in the plane z = 0; the second moves from y = 1 to y = -1 (meets at t = 1/2).
  const Vec3 y(0, 1, 0);
  const EdgeEdgeMotion overlapping{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, 0) + y, Vec3(1.5, 0, 0) + y,
                                   Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, 0) - y, Vec3(1.5, 0, 0) - y};
  expectHitAt(overlapping.ccd(), 0.5);
  // Same motion, no overlap along x: a miss.
  const EdgeEdgeMotion apart{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1.5, 0, 0) + y, Vec3(2.5, 0, 0) + y,
                             Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1.5, 0, 0) - y, Vec3(2.5, 0, 0) - y};
  EXPECT_FALSE(apart.ccd());
  // Parallel, 1 above, sliding along: never closer than 1.
  const Vec3 z(0, 0, 1);
  const EdgeEdgeMotion sliding{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(-2, 0, 0) + z, Vec3(-1, 0, 0) + z,
                               Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0) + z, Vec3(3, 0, 0) + z};
  EXPECT_FALSE(sliding.ccd());
  // With minDistance 1.001: in contact once the gap g along x has sqrt(1 + g^2) = 1.001. (A pair
  // within a millionth of minDistance more may count as touching: about 6e-6 of the step here.)
  const double gap = std::sqrt(1.001 * 1.001 - 1.0);
  expectHitAt(sliding.ccd(1.001), (1.0 - gap) / 4.0, 1e-5);
  // Collinear, sliding into each other end to end at t = 1/2.
  const EdgeEdgeMotion collinear{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0),
                                 Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)};
  expectHitAt(collinear.ccd(), 0.5);
}

TEST(CcdEdgeEdge, CrossingExactlyAtAnEndpoint) {
  // The falling edge x = 1 crosses the end (1, 0, 0) of the first edge at t = 1/2.
  const EdgeEdgeMotion atEnd{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, -1, 1), Vec3(1, 1, 1),
                             Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, -1, -1), Vec3(1, 1, -1)};
  const auto hit = atEnd.ccd();
  expectHitAt(hit, 0.5);
  EXPECT_NEAR(hit->s, 1.0, 1e-6);
  // End against end: the falling edge starts at (1, 0, z) and touches the first edge's end.
  const EdgeEdgeMotion endToEnd{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(1, 2, 1),
                                Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, -1), Vec3(1, 2, -1)};
  expectHitAt(endToEnd.ccd(), 0.5);
  // A hair beyond the end: a miss.
  const double past = 1.0 + 1e-7;
  const EdgeEdgeMotion beyond{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(past, -1, 1), Vec3(past, 1, 1),
                              Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(past, -1, -1), Vec3(past, 1, -1)};
  EXPECT_FALSE(beyond.ccd());
}

TEST(CcdEdgeEdge, TouchingAtTheStartNormalOpposesTheMotion) {
  // Crossing at t = 0, the second edge moving down: it came from above, so the normal from the
  // second edge towards the first points down.
  const EdgeEdgeMotion down{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 1, 0),
                            Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, -1), Vec3(0, 1, -1)};
  const auto hit = down.ccd();
  expectHitAt(hit, 0.0, 0.0);
  EXPECT_NEAR(hit->normal.z(), -1.0, 1e-12);
}

TEST(CcdEdgeEdge, ZeroMotion) {
  const EdgeEdgeMotion crossing{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 1, 0),
                                Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 1, 0)};
  expectHitAt(crossing.ccd(), 0.0, 0.0);
  const EdgeEdgeMotion apart{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 1e-4), Vec3(0, 1, 1e-4),
                             Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 1e-4), Vec3(0, 1, 1e-4)};
  EXPECT_FALSE(apart.ccd());
  // Both edges collapsed to the same still point.
  const Vec3 o(4, 5, 6);
  expectHitAt(EdgeEdgeMotion{o, o, o, o, o, o, o, o}.ccd(), 0.0, 0.0);
}

TEST(CcdEdgeEdge, VeryLargeAndTinyMotion) {
  const EdgeEdgeMotion large{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 2e3), Vec3(0, 1, 2e3),
                             Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, -8e3), Vec3(0, 1, -8e3)};
  expectHitAt(large.ccd(), 0.2);
  const EdgeEdgeMotion largeMiss{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(2, -1, 2e3), Vec3(2, 1, 2e3),
                                 Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(2, -1, -8e3), Vec3(2, 1, -8e3)};
  EXPECT_FALSE(largeMiss.ccd());
  const EdgeEdgeMotion tiny{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0.2e-9), Vec3(0, 1, 0.2e-9),
                            Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, -0.8e-9), Vec3(0, 1, -0.8e-9)};
  expectHitAt(tiny.ccd(), 0.2, kTinyStepSlack);
  const EdgeEdgeMotion tinyMiss{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 1.2e-9), Vec3(0, 1, 1.2e-9),
                                Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0.2e-9), Vec3(0, 1, 0.2e-9)};
  EXPECT_FALSE(tinyMiss.ccd());
}

TEST(CcdEdgeEdge, BothMovingAndMinDistance) {
  // First edge rises from z = -1 to 1, second falls from 1 to -1, crossing in projection: t = 1/2.
  const EdgeEdgeMotion motion{Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(0, -1, 1), Vec3(0, 1, 1),
                              Vec3(-1, 0, 1), Vec3(1, 0, 1), Vec3(0, -1, -1), Vec3(0, 1, -1)};
  const auto hit = motion.ccd();
  expectHitAt(hit, 0.5);
  EXPECT_NEAR(hit->normal.z(), -1.0, 1e-12);  // the first edge starts below
  // Gap 2 - 4t: within 2 mm at t = (2 - 2e-3) / 4.
  expectHitAt(motion.ccd(2e-3), (2.0 - 2e-3) / 4.0);
  // The second edge stops 1 mm above the first: seen with 2 mm, not with 0.5 mm.
  const EdgeEdgeMotion stops{Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 1), Vec3(0, 1, 1),
                             Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 1e-3), Vec3(0, 1, 1e-3)};
  EXPECT_FALSE(stops.ccd(0.5e-3));
  expectHitAt(stops.ccd(2e-3), (1.0 - 2e-3) / (1.0 - 1e-3));
}

TEST(CcdEdgeEdge, StrongRotationNearTangentialContact) {
  // The first edge turns by 1 rad about an oblique axis (its ends moving on chords) under a still
  // edge hovering 1 mm (+ 1e-5 of it) above: the distance grazes minDistance = 1 mm. Such contacts
  // take the most work; the answer must still come no later than the sampled first contact.
  const Eigen::AngleAxisd turn(1.0, Vec3(0.3, 0.2, 1.0).normalized());
  const double height = 1e-3 * (1.0 + 1e-5);
  const Vec3 pa(-0.05, 0, 0), pb(0.05, 0, 0), qa(0, -0.05, height), qb(0, 0.05, height);
  const EdgeEdgeMotion m{pa, pb, qa, qb, turn * pa, turn * pb, qa, qb};
  double firstContact = -1.0;
  for (int i = 0; i <= 200000 && firstContact < 0.0; ++i) {
    if (m.distance(i / 200000.0) <= 1e-3) firstContact = i / 200000.0;
  }
  ASSERT_GT(firstContact, 0.0);
  const auto hit = m.ccd(1e-3);
  ASSERT_TRUE(hit.has_value());
  EXPECT_LE(hit->t, firstContact);
  expectUnitAndFinite(hit->normal);
}

// ---------------------------------------------------------------------------- randomized

// Dense sampling in time: the first sampled time at which the primitives are within minDistance
// (or nothing). The true first contact is no later, so the CCD must report a time no later.
template <class Motion>
std::optional<double> firstSampledContact(const Motion& motion, double minDistance, int samples = 2000) {
  for (int i = 0; i <= samples; ++i) {
    const double t = double(i) / samples;
    if (motion.distance(t) <= minDistance) return t;
  }
  return std::nullopt;
}

Vec3 randomVec(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> coordinate(-scale, scale);
  return {coordinate(rng), coordinate(rng), coordinate(rng)};
}

// Random corners in a box of half-side 1, each moving by up to `reach` per coordinate, and a
// thickness of 0.05: a good share of the cases come into contact.
TEST(CcdRandomized, VertexFaceNeverMissesASampledContact) {
  std::mt19937 rng(2024);
  constexpr double kThickness = 0.05;
  int contacts = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const double reach = trial % 3 == 0 ? 0.1 : 1.0;
    VertexFaceMotion m;
    m.a0 = randomVec(rng, 1.0), m.b0 = randomVec(rng, 1.0), m.c0 = randomVec(rng, 1.0);
    m.p0 = (m.a0 + m.b0 + m.c0) / 3.0 + randomVec(rng, 0.5);  // near the face, to meet it often
    m.p1 = m.p0 + randomVec(rng, reach), m.a1 = m.a0 + randomVec(rng, reach);
    m.b1 = m.b0 + randomVec(rng, reach), m.c1 = m.c0 + randomVec(rng, reach);
    const std::optional<double> sampled = firstSampledContact(m, kThickness);
    const std::optional<VertexFaceHit> hit = m.ccd(kThickness);
    if (!sampled) continue;
    ++contacts;
    ASSERT_TRUE(hit.has_value()) << "trial " << trial << ": missed a contact sampled at t = " << *sampled;
    EXPECT_LE(hit->t, *sampled) << "trial " << trial;
    expectUnitAndFinite(hit->normal);
  }
  EXPECT_GT(contacts, 100);  // the test exercises contacts at all
}

TEST(CcdRandomized, EdgeEdgeNeverMissesASampledContact) {
  std::mt19937 rng(99);
  constexpr double kThickness = 0.05;
  int contacts = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const double reach = trial % 3 == 0 ? 0.1 : 1.0;
    EdgeEdgeMotion m;
    m.pa0 = randomVec(rng, 1.0), m.pb0 = randomVec(rng, 1.0), m.qa0 = randomVec(rng, 1.0), m.qb0 = randomVec(rng, 1.0);
    m.pa1 = m.pa0 + randomVec(rng, reach), m.pb1 = m.pb0 + randomVec(rng, reach);
    m.qa1 = m.qa0 + randomVec(rng, reach), m.qb1 = m.qb0 + randomVec(rng, reach);
    const std::optional<double> sampled = firstSampledContact(m, kThickness);
    const std::optional<EdgeEdgeHit> hit = m.ccd(kThickness);
    if (!sampled) continue;
    ++contacts;
    ASSERT_TRUE(hit.has_value()) << "trial " << trial << ": missed a contact sampled at t = " << *sampled;
    EXPECT_LE(hit->t, *sampled) << "trial " << trial;
    expectUnitAndFinite(hit->normal);
  }
  EXPECT_GT(contacts, 100);
}

// Exact touches (minDistance = 0) built on purpose: pick a time t* and make the vertex pass through
// a random point of the face at t*, or the edges through a common point. The CCD must report a
// time no later than t* (up to the rounding of the construction).
TEST(CcdRandomized, ConstructedTouchesAreFoundNoLater) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    const double tStar = trial % 10 == 0 ? 0.0 : trial % 10 == 1 ? 1.0 : unit(rng);
    VertexFaceMotion vf;
    vf.a0 = randomVec(rng, 1.0), vf.b0 = randomVec(rng, 1.0), vf.c0 = randomVec(rng, 1.0);
    vf.a1 = randomVec(rng, 1.0), vf.b1 = randomVec(rng, 1.0), vf.c1 = randomVec(rng, 1.0);
    double w1 = unit(rng), w2 = unit(rng);
    if (w1 + w2 > 1.0) w1 = 1.0 - w1, w2 = 1.0 - w2;
    const Vec3 target = (1.0 - w1 - w2) * vf.at(vf.a0, vf.a1, tStar) + w1 * vf.at(vf.b0, vf.b1, tStar) +
                        w2 * vf.at(vf.c0, vf.c1, tStar);
    const Vec3 p0 = randomVec(rng, 1.0), p1 = randomVec(rng, 1.0);
    const Vec3 shift = target - vf.at(p0, p1, tStar);
    vf.p0 = p0 + shift, vf.p1 = p1 + shift;
    const auto vfHit = vf.ccd();
    ASSERT_TRUE(vfHit.has_value()) << "vertex-face trial " << trial << ", t* = " << tStar;
    EXPECT_LE(vfHit->t, tStar + 1e-12) << "vertex-face trial " << trial;
    expectUnitAndFinite(vfHit->normal);

    EdgeEdgeMotion ee;
    ee.pa0 = randomVec(rng, 1.0), ee.pb0 = randomVec(rng, 1.0);
    ee.pa1 = randomVec(rng, 1.0), ee.pb1 = randomVec(rng, 1.0);
    const double s = unit(rng), u = unit(rng);
    const Vec3 meet = (1.0 - s) * ee.at(ee.pa0, ee.pa1, tStar) + s * ee.at(ee.pb0, ee.pb1, tStar);
    const Vec3 qa0 = randomVec(rng, 1.0), qb0 = randomVec(rng, 1.0);
    const Vec3 qa1 = randomVec(rng, 1.0), qb1 = randomVec(rng, 1.0);
    const Vec3 offset = meet - ((1.0 - u) * ee.at(qa0, qa1, tStar) + u * ee.at(qb0, qb1, tStar));
    ee.qa0 = qa0 + offset, ee.qb0 = qb0 + offset, ee.qa1 = qa1 + offset, ee.qb1 = qb1 + offset;
    const auto eeHit = ee.ccd();
    ASSERT_TRUE(eeHit.has_value()) << "edge-edge trial " << trial << ", t* = " << tStar;
    EXPECT_LE(eeHit->t, tStar + 1e-12) << "edge-edge trial " << trial;
    expectUnitAndFinite(eeHit->normal);
  }
}

// Degenerate configurations on purpose: corners on a half-unit grid (so coplanar, collinear,
// parallel, collapsed and coincident cases are exact), some kinds forced (everything in one plane,
// a collapsed face or edge, parallel edges, no motion, pure translation), scaled by powers of two
// (exact) from 2^-20 to 2^13 and moved far from the origin. Sampled at 1024 exact times; wherever a
// sample is within minDistance (or touching, for minDistance = 0) the CCD must report a hit no later.
TEST(CcdRandomized, DegenerateGridConfigurationsNeverMissASampledContact) {
  std::mt19937 rng(123);
  std::uniform_int_distribution<int> grid(-2, 2), kind(0, 7);
  int contacts = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::array<Vec3, 8> x;  // the four points at t = 0, then at t = 1
    for (Vec3& point : x) point = 0.5 * Vec3(grid(rng), grid(rng), grid(rng));
    switch (kind(rng)) {
      case 1:  // coplanar throughout
        for (Vec3& point : x) point.z() = 0.0;
        break;
      case 2:  // a face collapsed to a segment (c = a); edges sharing an end (qb = pb)
        x[3] = x[1], x[7] = x[5];
        break;
      case 3:  // a face collapsed to a segment (c midway between a and b); qb midway between pb and qa
        x[3] = 0.5 * (x[1] + x[2]), x[7] = 0.5 * (x[5] + x[6]);
        break;
      case 4:  // no motion
        for (int j = 0; j < 4; ++j) x[j + 4] = x[j];
        break;
      case 5:  // parallel edges (qb - qa = pb - pa); for a face, a parallelogram's corner
        x[3] = x[2] + (x[1] - x[0]), x[7] = x[6] + (x[5] - x[4]);
        break;
      case 6:  // pure translation
        for (int j = 0; j < 4; ++j) x[j + 4] = x[j] + (x[4] - x[0]);
        break;
      default:
        break;
    }
    const double scale = std::array<double, 3>{1.0, 0x1p-20, 0x1p13}[trial % 3];
    const Vec3 offset = (trial / 3) % 2 ? Vec3(1024, -2048, 512) : Vec3::Zero();
    for (Vec3& point : x) point = (point + offset) * scale;
    const double minDistance = (trial / 6) % 2 ? 0.0 : 0.1 * scale;
    const double touching = minDistance > 0.0 ? minDistance : 1e-13 * scale;  // distance computations round

    const bool edgeEdge = trial % 2 == 1;
    const VertexFaceMotion vf{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]};
    const EdgeEdgeMotion ee{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]};
    std::optional<double> sampled;
    for (int i = 0; i <= 1024 && !sampled; ++i) {
      const double t = i / 1024.0;
      if ((edgeEdge ? ee.distance(t) : vf.distance(t)) <= touching) sampled = t;
    }
    std::optional<double> reported;
    if (edgeEdge) {
      const auto hit = ee.ccd(minDistance);
      if (hit) reported = hit->t, expectUnitAndFinite(hit->normal);
    } else {
      const auto hit = vf.ccd(minDistance);
      if (hit) reported = hit->t, expectUnitAndFinite(hit->normal);
    }
    if (!sampled) continue;
    ++contacts;
    ASSERT_TRUE(reported.has_value()) << "trial " << trial << ": missed a contact sampled at t = " << *sampled;
    EXPECT_LE(*reported, *sampled) << "trial " << trial;
  }
  EXPECT_GT(contacts, 2000);
}

}  // namespace
}  // namespace weft
