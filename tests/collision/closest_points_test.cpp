// Closest points (closest_points.h): against brute-force sampling of the primitives on random
// cases, against the optimality condition of a closest point on a convex set, and on degenerate
// inputs (collapsed triangles, zero-length and parallel segments) whose answer is known by hand.
#include "collision/closest_points.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace weft {
namespace {

Vec3 randomPoint(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> coordinate(-scale, scale);
  return {coordinate(rng), coordinate(rng), coordinate(rng)};
}

// Smallest distance from p to a grid of n x n barycentric samples of the triangle.
double sampledTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int n) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double w1 = double(i) / n, w2 = double(j) / n;
      best = std::min(best, (p - ((1.0 - w1 - w2) * a + w1 * b + w2 * c)).norm());
    }
  }
  return best;
}

double sampledSegmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, int n) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double s = double(i) / n, t = double(j) / n;
      best = std::min(best, ((p0 + s * (p1 - p0)) - (q0 + t * (q1 - q0))).norm());
    }
  }
  return best;
}

// The result describes a point of the triangle at the stated distance.
void expectConsistent(const PointTriangleClosest& r, const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  ASSERT_TRUE(std::isfinite(r.distance));
  for (double w : r.weights) EXPECT_GE(w, 0.0);
  EXPECT_NEAR(r.weights[0] + r.weights[1] + r.weights[2], 1.0, 1e-12);
  EXPECT_LT((r.point - (r.weights[0] * a + r.weights[1] * b + r.weights[2] * c)).norm(), 1e-12);
  EXPECT_NEAR(r.distance, (p - r.point).norm(), 1e-12);
}

// q is the closest point of a convex set to p exactly when (p - q) . (x - q) <= 0 for every x of
// the set; for a triangle it is enough to check the corners.
void expectOptimalOnTriangle(const PointTriangleClosest& r, const Vec3& p, const Vec3& a, const Vec3& b,
                             const Vec3& c) {
  for (const Vec3& corner : {a, b, c}) EXPECT_LE((p - r.point).dot(corner - r.point), 1e-12);
}

TEST(ClosestPointTriangle, RandomCasesMatchSamplingAndAreOptimal) {
  std::mt19937 rng(7);
  constexpr int kSamples = 120;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 a = randomPoint(rng), b = randomPoint(rng), c = randomPoint(rng), p = randomPoint(rng, 2.0);
    const PointTriangleClosest r = closestPointOnTriangle(p, a, b, c);
    expectConsistent(r, p, a, b, c);
    expectOptimalOnTriangle(r, p, a, b, c);
    // Sampling only finds points of the triangle: never closer, and at most a grid step farther.
    const double sampled = sampledTriangleDistance(p, a, b, c, kSamples);
    const double gridStep = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / kSamples;
    EXPECT_LE(r.distance, sampled + 1e-12);
    EXPECT_GE(r.distance, sampled - gridStep);
  }
}

TEST(ClosestPointTriangle, PointAboveTheInteriorProjectsOntoIt) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0), p(0.5, 0.5, 3);
  const PointTriangleClosest r = closestPointOnTriangle(p, a, b, c);
  EXPECT_NEAR(r.distance, 3.0, 1e-15);
  EXPECT_NEAR(r.weights[0], 0.5, 1e-15);
  EXPECT_NEAR(r.weights[1], 0.25, 1e-15);
  EXPECT_NEAR(r.weights[2], 0.25, 1e-15);
  EXPECT_TRUE(r.point.isApprox(Vec3(0.5, 0.5, 0)));
}

TEST(ClosestPointTriangle, TriangleCollapsedToASegment) {
  // c lies on segment ab: the triangle is that segment.
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(1, 0, 0);
  for (const Vec3& p : {Vec3(0.5, 1, 0), Vec3(3, 0, 1), Vec3(-1, -1, -1), Vec3(1.2, 0, 0)}) {
    const PointTriangleClosest r = closestPointOnTriangle(p, a, b, c);
    const double expected = (p - Vec3(std::clamp(p.x(), 0.0, 2.0), 0, 0)).norm();
    EXPECT_NEAR(r.distance, expected, 1e-14) << p.transpose();
    expectConsistent(r, p, a, b, c);
  }
}

TEST(ClosestPointTriangle, TriangleCollapsedToAPoint) {
  const Vec3 a(1, 2, 3);
  const Vec3 p(4, 6, 3);
  const PointTriangleClosest r = closestPointOnTriangle(p, a, a, a);
  EXPECT_DOUBLE_EQ(r.distance, 5.0);
  expectConsistent(r, p, a, a, a);
}

TEST(ClosestPointTriangle, NearlyCollapsedTrianglesStayAccurate) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = randomPoint(rng), b = randomPoint(rng);
    // c a hair off the segment ab: the triangle is a sliver of width ~1e-9.
    const Vec3 c = a + 0.3 * (b - a) + 1e-9 * randomPoint(rng);
    const Vec3 p = randomPoint(rng, 2.0);
    const PointTriangleClosest r = closestPointOnTriangle(p, a, b, c);
    expectConsistent(r, p, a, b, c);
    expectOptimalOnTriangle(r, p, a, b, c);
    EXPECT_LE(r.distance, sampledTriangleDistance(p, a, b, c, 60) + 1e-12);
  }
}

TEST(ClosestPointTriangle, PointOnTheTriangleIsAtDistanceZero) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(closestPointOnTriangle(Vec3(0.25, 0.25, 0), a, b, c).distance, 0.0);
  EXPECT_EQ(closestPointOnTriangle(b, a, b, c).distance, 0.0);
  EXPECT_EQ(closestPointOnTriangle(Vec3(0.5, 0, 0), a, b, c).distance, 0.0);
}

void expectOptimalOnSegments(const SegmentSegmentClosest& r, const Vec3& p0, const Vec3& p1, const Vec3& q0,
                             const Vec3& q1) {
  ASSERT_TRUE(std::isfinite(r.distance));
  EXPECT_GE(r.s, 0.0);
  EXPECT_LE(r.s, 1.0);
  EXPECT_GE(r.t, 0.0);
  EXPECT_LE(r.t, 1.0);
  const Vec3 x = p0 + r.s * (p1 - p0), y = q0 + r.t * (q1 - q0);
  EXPECT_NEAR(r.distance, (x - y).norm(), 1e-12);
  // Optimality of the pair on the convex set P - Q: each point is the closest to the other.
  for (const Vec3& end : {p0, p1}) EXPECT_GE((x - y).dot(end - x), -1e-12);
  for (const Vec3& end : {q0, q1}) EXPECT_GE((y - x).dot(end - y), -1e-12);
}

TEST(ClosestSegmentSegment, RandomCasesMatchSamplingAndAreOptimal) {
  std::mt19937 rng(3);
  constexpr int kSamples = 300;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 p0 = randomPoint(rng), p1 = randomPoint(rng), q0 = randomPoint(rng), q1 = randomPoint(rng);
    const SegmentSegmentClosest r = closestSegmentSegment(p0, p1, q0, q1);
    expectOptimalOnSegments(r, p0, p1, q0, q1);
    const double sampled = sampledSegmentDistance(p0, p1, q0, q1, kSamples);
    const double gridStep = std::max((p1 - p0).norm(), (q1 - q0).norm()) / kSamples;
    EXPECT_LE(r.distance, sampled + 1e-12);
    EXPECT_GE(r.distance, sampled - gridStep);
  }
}

TEST(ClosestSegmentSegment, CrossingSegmentsTouch) {
  const SegmentSegmentClosest r =
      closestSegmentSegment(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, 0), Vec3(0.5, 3, 0));
  EXPECT_NEAR(r.distance, 0.0, 1e-15);
  EXPECT_NEAR(r.s, 0.75, 1e-15);
  EXPECT_NEAR(r.t, 0.25, 1e-15);
}

TEST(ClosestSegmentSegment, SkewSegmentsAtKnownDistance) {
  const SegmentSegmentClosest r =
      closestSegmentSegment(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 2), Vec3(0, 1, 2));
  EXPECT_NEAR(r.distance, 2.0, 1e-15);
  EXPECT_NEAR(r.s, 0.5, 1e-15);
  EXPECT_NEAR(r.t, 0.5, 1e-15);
}

TEST(ClosestSegmentSegment, ParallelSegments) {
  const Vec3 p0(0, 0, 0), p1(1, 0, 0);
  struct Case {
    Vec3 q0, q1;
    double distance;
  };
  const Case cases[] = {
      {Vec3(0.5, 1, 0), Vec3(3, 1, 0), 1.0},                // overlapping in x, 1 apart
      {Vec3(3, 1, 0), Vec3(0.5, 1, 0), 1.0},                // the same, reversed
      {Vec3(2, 1, 0), Vec3(3, 1, 0), std::sqrt(2.0)},       // disjoint in x: end to end
      {Vec3(-3, 0, 0), Vec3(-2, 0, 0), 2.0},                // collinear, apart
      {Vec3(0.25, 0, 0), Vec3(0.75, 0, 0), 0.0},            // collinear, nested
      {Vec3(-1, 0, 2), Vec3(2, 0, 2), 2.0},                 // one covering the other
  };
  for (const Case& c : cases) {
    const SegmentSegmentClosest r = closestSegmentSegment(p0, p1, c.q0, c.q1);
    EXPECT_NEAR(r.distance, c.distance, 1e-14) << c.q0.transpose() << " / " << c.q1.transpose();
    expectOptimalOnSegments(r, p0, p1, c.q0, c.q1);
  }
}

TEST(ClosestSegmentSegment, NearlyParallelSegmentsStayAccurate) {
  // Crossing (in projection) at a tiny angle, 1e-3 apart: the interior answer is the true one.
  for (double angle : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const Vec3 p0(-1, 0, 0), p1(1, 0, 0);
    const Vec3 q0(-1, -angle, 1e-3), q1(1, angle, 1e-3);
    const SegmentSegmentClosest r = closestSegmentSegment(p0, p1, q0, q1);
    EXPECT_NEAR(r.distance, 1e-3, 1e-12) << angle;
    expectOptimalOnSegments(r, p0, p1, q0, q1);
  }
}

TEST(ClosestSegmentSegment, ZeroLengthSegments) {
  const Vec3 p(0.5, 2, 0);
  // Point against segment.
  SegmentSegmentClosest r = closestSegmentSegment(p, p, Vec3(0, 0, 0), Vec3(1, 0, 0));
  EXPECT_NEAR(r.distance, 2.0, 1e-15);
  EXPECT_NEAR(r.t, 0.5, 1e-15);
  // Segment against point.
  r = closestSegmentSegment(Vec3(0, 0, 0), Vec3(1, 0, 0), p, p);
  EXPECT_NEAR(r.distance, 2.0, 1e-15);
  EXPECT_NEAR(r.s, 0.5, 1e-15);
  // Point against point.
  r = closestSegmentSegment(p, p, Vec3(0.5, 2, 3), Vec3(0.5, 2, 3));
  EXPECT_DOUBLE_EQ(r.distance, 3.0);
  // The same point twice.
  r = closestSegmentSegment(p, p, p, p);
  EXPECT_EQ(r.distance, 0.0);
}

}  // namespace
}  // namespace weft
