// Closest points between a point and a triangle and between two segments (closest_points.h).
//
// Both take the best of a few candidates, each of which is a true point of the primitives: the
// interior solution when the configuration is well conditioned, otherwise (or as well) the
// boundary, which reduces to point-segment problems that are well posed even for zero lengths.
// So a degenerate triangle (a segment or a point) or a zero-length or parallel segment still
// gives the correct distance, and no division by a vanishing quantity can produce NaN.
#include "collision/closest_points.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace weft {
namespace {

// Below this sin^2 of the angle between the two spanning vectors, the interior solution's
// division loses too many digits to be trusted alone, and the boundary is checked as well.
constexpr double kIllConditionedSin2 = 1e-8;

// Parameter in [0, 1] of the point of segment [x, x + d] closest to p (0 for a zero-length one).
double closestParameterOnSegment(const Vec3& p, const Vec3& x, const Vec3& d) {
  const double lengthSquared = d.squaredNorm();
  if (!(lengthSquared > 0.0)) return 0.0;
  return std::clamp((p - x).dot(d) / lengthSquared, 0.0, 1.0);
}

// Keeps the candidate point of the triangle (corner a + offset, barycentric w) if it is closer to
// p (at a + r) than the best so far.
// Both keepIfCloser compare squared distances (best.distance holds the square until the caller
// takes its root once, on return): the candidates are many and the root is the costly part.
void keepIfCloser(const Vec3& r, const Vec3& offset, double w0, double w1, double w2,
                  PointTriangleClosest& best) {
  const double squared = (r - offset).squaredNorm();
  if (squared >= best.distance) return;
  best.distance = squared;
  best.weights[0] = w0;
  best.weights[1] = w1;
  best.weights[2] = w2;
  best.point = offset;  // made absolute by the caller
}

void keepIfCloser(const Vec3& p0, const Vec3& d1, double s, const Vec3& q0, const Vec3& d2, double t,
                  SegmentSegmentClosest& best) {
  const double squared = ((p0 + s * d1) - (q0 + t * d2)).squaredNorm();
  if (squared >= best.distance) return;
  best.distance = squared;
  best.s = s;
  best.t = t;
}

}  // namespace

PointTriangleClosest closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Everything relative to corner a: the triangle is (0, e0, e1) and the point is r.
  const Vec3 e0 = b - a;
  const Vec3 e1 = c - a;
  const Vec3 r = p - a;
  PointTriangleClosest best;
  best.distance = std::numeric_limits<double>::infinity();

  // Interior: the projection of r onto the plane, when it falls inside. Its barycentric
  // coordinates are ratios of signed areas: w1 = ((r x e1) . n) / |n|^2, w2 = ((e0 x r) . n) / |n|^2.
  const Vec3 n = e0.cross(e1);
  const double nn = n.squaredNorm();
  if (nn > 0.0) {
    const double w1 = r.cross(e1).dot(n) / nn;
    const double w2 = e0.cross(r).dot(n) / nn;
    if (w1 >= 0.0 && w2 >= 0.0 && w1 + w2 <= 1.0) {
      keepIfCloser(r, w1 * e0 + w2 * e1, 1.0 - w1 - w2, w1, w2, best);
      const bool wellConditioned = nn > kIllConditionedSin2 * e0.squaredNorm() * e1.squaredNorm();
      if (wellConditioned) {
        best.point += a;
        best.distance = std::sqrt(best.distance);
        return best;
      }
    }
  }

  // Boundary: the closest point lies on one of the edges (always, for a collapsed triangle).
  const Vec3 e2 = e1 - e0;  // edge b -> c
  const double sAB = closestParameterOnSegment(r, Vec3::Zero(), e0);
  keepIfCloser(r, sAB * e0, 1.0 - sAB, sAB, 0.0, best);
  const double sBC = closestParameterOnSegment(r, e0, e2);
  keepIfCloser(r, e0 + sBC * e2, 0.0, 1.0 - sBC, sBC, best);
  const double sCA = closestParameterOnSegment(r, e1, -e1);
  keepIfCloser(r, (1.0 - sCA) * e1, sCA, 0.0, 1.0 - sCA, best);
  best.point += a;
  best.distance = std::sqrt(best.distance);
  return best;
}

SegmentSegmentClosest closestSegmentSegment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0;
  const Vec3 d2 = q1 - q0;
  const Vec3 r = p0 - q0;
  SegmentSegmentClosest best;
  best.distance = std::numeric_limits<double>::infinity();

  // Interior: the stationary point of |r + s d1 - t d2|^2, from the 2x2 normal equations
  //   a s - b t = -c,  b s - e t = -f  (a = d1.d1, b = d1.d2, e = d2.d2, c = d1.r, f = d2.r).
  // The squared distance is convex in (s, t), so when that point lies in [0,1]^2 it is the minimum.
  const double a = d1.squaredNorm();
  const double b = d1.dot(d2);
  const double e = d2.squaredNorm();
  const double c = d1.dot(r);
  const double f = d2.dot(r);
  const double denominator = a * e - b * b;  // = |d1 x d2|^2 >= 0: zero when parallel or degenerate
  if (denominator > 0.0) {
    const double s = (b * f - c * e) / denominator;
    const double t = (a * f - b * c) / denominator;
    if (s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0) {
      keepIfCloser(p0, d1, s, q0, d2, t, best);
      if (denominator > kIllConditionedSin2 * a * e) {
        best.distance = std::sqrt(best.distance);
        return best;
      }
    }
  }

  // Boundary of [0,1]^2: each end of one segment against the other segment. Parallel segments
  // have a whole line of minima, which meets this boundary.
  keepIfCloser(p0, d1, 0.0, q0, d2, closestParameterOnSegment(p0, q0, d2), best);
  keepIfCloser(p0, d1, 1.0, q0, d2, closestParameterOnSegment(p1, q0, d2), best);
  keepIfCloser(p0, d1, closestParameterOnSegment(q0, p0, d1), q0, d2, 0.0, best);
  keepIfCloser(p0, d1, closestParameterOnSegment(q1, p0, d1), q0, d2, 1.0, best);
  best.distance = std::sqrt(best.distance);
  return best;
}

}  // namespace weft
