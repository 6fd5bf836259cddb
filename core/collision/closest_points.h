#pragma once
// Closest points between a point and a triangle and between two segments, with the barycentric or
// segment parameters of the closest points. Used by the proximity pass and to validate CCD hits.
// Degenerate inputs (a zero-length segment, a triangle collapsed to a segment or a point) give
// the correct distance, never NaN.
#include "util/types.h"

namespace weft {

struct PointTriangleClosest {
  double distance = 0.0;
  double weights[3] = {1.0, 0.0, 0.0};  // closest point = w0 a + w1 b + w2 c, w >= 0, sum 1
  Vec3 point = Vec3::Zero();             // the closest point on the triangle
};
PointTriangleClosest closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

struct SegmentSegmentClosest {
  double distance = 0.0;
  double s = 0.0;  // closest point on the first segment  = p0 + s (p1 - p0), s in [0, 1]
  double t = 0.0;  // closest point on the second segment = q0 + t (q1 - q0), t in [0, 1]
};
SegmentSegmentClosest closestSegmentSegment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

}  // namespace weft
