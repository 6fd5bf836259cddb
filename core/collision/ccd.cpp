// Continuous collision detection (ccd.h) by conservative narrowing of the step.
//
// The thesis (§2.6) finds a contact as a root of the coplanarity cubic, Eq. 2.65 (AP(t) . N(t) = 0,
// vertex-face) or Eq. 2.67 ((AB(t) x CD(t)) . AC(t) = 0, edge-edge), followed by the inside test of
// Eq. 2.66 or 2.68. Solving the cubic in floating point misses roots that graze t = 0 or t = 1 or
// that come from a (nearly) vanishing cubic, and a thickness (minDistance > 0) is not a root at
// all. So we never solve it. We only rule out parts of the step where a contact is impossible,
// with two tests that hold up to a written bound on floating-point rounding:
//  1. plane clip: over a span [ta, tb] the cubic lies in the convex hull of its Bernstein control
//     points; where that hull stays beyond +-minDistance |N(t)|, the vertex is farther than
//     minDistance from the face's plane (the edges' lines from each other). This rules out
//     whole spans away from the cubic's roots (the common case ends here, on the whole step) and
//     clips spans down to the roots;
//  2. axis advancement: along a fixed axis k (the direction between the closest points at the
//     span's start) the separation of the primitives is a minimum of linear functions of t, which
//     bounds their distance from below; it rules out the span up to where it could reach
//     minDistance (exactly where a head-on approach makes contact).
// Spans are handled earliest first; what is left of a span is narrowed again while that halves
// it, halved otherwise. A contact is reported at the start of what is left once the primitives
// are within minDistance there (plus a tiny tolerance), or once the span is too short to matter.
// Everything before the reported time was ruled out, so it is never later than the true one.
#include "collision/ccd.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "collision/closest_points.h"

namespace weft {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// A span whose relative motion is below this fraction of the query's size is not halved further:
// a reported contact may be a near miss by about that much (a false positive costs only work).
constexpr double kResolution = 1e-11;
constexpr double kTimeResolution = 1e-6;  // and not before it is this short: the reported time's accuracy
// A pair hovering just outside minDistance for the whole step (resting contact) would otherwise
// cost the full work cap: within this fraction of minDistance more, it counts as a contact.
constexpr double kRelativeContactTolerance = 1e-6;
constexpr double kShortestSpan = 0x1p-48;  // halving stops here whatever the motion
constexpr int kMaxSpans = 500;             // work cap: beyond it, the earliest open span is reported
constexpr double kClipMargin = 1e-9;       // widening of a plane clip, as a fraction of the span
// Below this sin^2 of the angle between the spanning vectors, a cross product is no normal.
constexpr double kDegenerateSin2 = 1e-16;
// Closest points farther apart than this fraction of the query's size give a contact normal with
// a direction error below ~1e-8 rad; closer, they are touching and the plane gives the normal.
constexpr double kReliableDirection = 1e-8;

// A vector that moves linearly over the step, from at0 (t = 0) to at1 (t = 1).
struct LinearVec {
  Vec3 at0 = Vec3::Zero();
  Vec3 at1 = Vec3::Zero();
  Vec3 at(double t) const { return (1.0 - t) * at0 + t * at1; }
  Vec3 motion() const { return at1 - at0; }
  double l1Spread() const { return at0.lpNorm<1>() + at1.lpNorm<1>(); }
};

LinearVec difference(const Vec3& to0, const Vec3& from0, const Vec3& to1, const Vec3& from1) {
  return {to0 - from0, to1 - from1};
}

// A query in relative terms: only differences of its points, so that large absolute coordinates
// add no rounding to the bounds. "First" is the face (vertex-face) or the first edge (edge-edge).
struct RelativeMotion {
  // Coplanarity cubic f(t) = det[u(t), v(t), w(t)] = N(t) . w(t), N = u x v (Eq. 2.65, Eq. 2.67).
  LinearVec u, v, w;
  // From each point of the first primitive to each point of the second.
  std::array<LinearVec, 4> gaps;
  int gapCount = 0;
  double minDistance = 0.0;
  double cubicError = 0.0;   // bound on the rounding of any value of f (setCubicBounds)
  double normalError = 0.0;  // bound on the rounding of any |N(t)|
};

// Rounding bounds, derived from: every interpolated difference carries a componentwise error of
// at most 4 eps (|x(0)| + |x(1)|); a determinant's perturbation is bounded through Hadamard's
// inequality and its evaluation by 8 eps times its permanent (<= the product of the l1 norms).
// That gives about 26 eps |u|_1 |v|_1 |w|_1 for f and 12 eps |u|_1 |v|_1 for N; the constants
// keep a factor of two or more on top.
void setCubicBounds(RelativeMotion& m) {
  const double uSpread = m.u.l1Spread();
  const double vSpread = m.v.l1Spread();
  m.cubicError = 64.0 * kEps * uSpread * vSpread * m.w.l1Spread();
  m.normalError = 16.0 * kEps * uSpread * vSpread;
}

// What the search over spans needs beyond the plane test; only computed once that test fails.
struct SearchScales {
  double gapError = 0.0;    // bound on the rounding of k . gap(t), per unit of |k|_1 (about 12 eps
                            // times the largest gap component; the factor keeps a margin)
  double motion = 0.0;      // largest relative displacement of two points over the step
  double resolution = 0.0;  // kResolution times the query's size
  // Distance beyond minDistance that counts as contact at the start of a span: the resolution and
  // a millionth of minDistance, or less when the motion is so small that a gap of this size takes
  // over kTimeResolution of the step to close.
  double contactTolerance = 0.0;
};

SearchScales searchScales(const RelativeMotion& m) {
  SearchScales scales;
  double largestComponent = 0.0;
  double size = std::max({m.u.at0.norm(), m.u.at1.norm(), m.v.at0.norm(), m.v.at1.norm()});
  for (int i = 0; i < m.gapCount; ++i) {
    const LinearVec& gap = m.gaps[i];
    largestComponent =
        std::max({largestComponent, gap.at0.lpNorm<Eigen::Infinity>(), gap.at1.lpNorm<Eigen::Infinity>()});
    size = std::max({size, gap.at0.norm(), gap.at1.norm()});
    scales.motion = std::max(scales.motion, gap.motion().norm());
  }
  scales.gapError = 32.0 * kEps * largestComponent;
  scales.resolution = kResolution * size;
  scales.contactTolerance =
      std::min(scales.resolution + kRelativeContactTolerance * m.minDistance, kTimeResolution * scales.motion);
  return scales;
}

// The spanning vectors u, v, w at the two ends a, b of a span.
struct SpanEnds {
  Vec3 ua, ub, va, vb, wa, wb;
};

SpanEnds spanEnds(const RelativeMotion& m, double ta, double tb) {
  return {m.u.at(ta), m.u.at(tb), m.v.at(ta), m.v.at(tb), m.w.at(ta), m.w.at(tb)};
}

// The part of a span where the plane test cannot rule a contact out, as fractions [lo, hi] of the
// span (empty when it rules out all of it).
struct PlaneClip {
  bool empty = true;
  double lo = 1.0, hi = 0.0;
};

// Fractions of the segment from (s0, y0) to (s1, y1) where |y| <= band, merged into `clip`.
void clipSegmentToBand(double s0, double y0, double s1, double y1, double band, PlaneClip& clip) {
  double from = 0.0, to = 1.0;  // along the segment
  if (y1 != y0) {
    const double first = (-band - y0) / (y1 - y0), second = (band - y0) / (y1 - y0);
    from = std::max(from, std::min(first, second));
    to = std::min(to, std::max(first, second));
    if (from > to) return;
  } else if (std::abs(y0) > band) {
    return;
  }
  clip.empty = false;
  clip.lo = std::min(clip.lo, s0 + from * (s1 - s0));
  clip.hi = std::max(clip.hi, s0 + to * (s1 - s0));
}

// Plane test: where on the span f(t) can come within +-minDistance |N(t)| of zero. The distance
// between the primitives is at least |f| / |N|, the distance from the vertex to the face's plane
// (between the edges' lines), so a contact needs that. On the span f is a cubic whose graph lies
// in the convex hull of its Bernstein control points (i/3, b_i); the hull meets the band
// |y| <= minDistance |N| + rounding only at fractions that some segment between two control points
// reaches inside the band (the hull's extreme points in the band lie on such segments). Away from
// a root the hull clears the band and the span is ruled out; near a simple root it clips the span
// quadratically fast.
PlaneClip clipToPlane(const RelativeMotion& m, const SpanEnds& e) {
  // N = u x v with u, v each at one end of the span.
  const Vec3 nAA = e.ua.cross(e.va), nAB = e.ua.cross(e.vb), nBA = e.ub.cross(e.va), nBB = e.ub.cross(e.vb);
  // Bernstein coefficients of the cubic on the span: its blossom at the span's ends, which for a
  // determinant of linear vectors is the mean of the determinants mixing their end values.
  const std::array<double, 4> b = {
      nAA.dot(e.wa),
      (nBA.dot(e.wa) + nAB.dot(e.wa) + nAA.dot(e.wb)) / 3.0,
      (nAB.dot(e.wb) + nBA.dot(e.wb) + nBB.dot(e.wa)) / 3.0,
      nBB.dot(e.wb),
  };
  double band = m.cubicError;
  if (m.minDistance > 0.0) {
    // |N(t)| is at most the largest norm of N's three Bernstein coefficients (N is quadratic).
    const double largestSquared = std::max({nAA.squaredNorm(), (0.5 * (nAB + nBA)).squaredNorm(), nBB.squaredNorm()});
    const double normalBound = std::sqrt(largestSquared) * (1.0 + 4.0 * kEps) + m.normalError;
    band += m.minDistance * normalBound * (1.0 + 4.0 * kEps);
  }
  PlaneClip clip;
  if (!std::isfinite(b[0] + b[1] + b[2] + b[3] + band)) return {false, 0.0, 1.0};  // overflow: rule nothing out
  const auto [lowest, highest] = std::minmax_element(b.begin(), b.end());
  if (*lowest > band || *highest < -band) return clip;  // the whole span is off the plane
  if (std::abs(b[0]) <= band && std::abs(b[3]) <= band) return {false, 0.0, 1.0};  // nothing to clip
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) clipSegmentToBand(i / 3.0, b[i], j / 3.0, b[j], band, clip);
  }
  // Widen by far more than the rounding of the fractions above.
  clip.lo = std::max(0.0, clip.lo - kClipMargin);
  clip.hi = std::min(1.0, clip.hi + kClipMargin);
  return clip;
}

// Axis test: along a fixed axis k (pointing from the first primitive to the second), the gap
// k . gap_i(t) between a corner of each is linear in t, and the smallest one, over |k|, bounds
// their distance from below. Returns the time up to which every such gap stays above
// minDistance |k| (plus rounding), starting from ta: ta itself when that fails at once, and
// nothing when it holds over the whole span (which is then ruled out). With k the direction
// between the closest points at ta this is a conservative advancement: exact for a head-on
// approach, and never past the first contact.
std::optional<double> advanceAlong(const RelativeMotion& m, const SearchScales& scales, const Vec3& k, double ta,
                                   double tb) {
  const double length = k.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return ta;
  const double needed = m.minDistance * length * (1.0 + 4.0 * kEps) + scales.gapError * k.lpNorm<1>();
  double cleared = 1.0;  // fraction of the span over which every gap stays above `needed`
  bool wholeSpan = true;
  for (int i = 0; i < m.gapCount; ++i) {
    const double atStart = k.dot(m.gaps[i].at(ta)), atEnd = k.dot(m.gaps[i].at(tb));
    if (!(atStart > needed)) return ta;
    if (atEnd > needed) continue;
    wholeSpan = false;
    cleared = std::min(cleared, (atStart - needed) / (atStart - atEnd));  // the line's crossing of `needed`
  }
  if (wholeSpan) return std::nullopt;
  // Pulled back by far more than the rounding of the fraction and of the time.
  return std::max(ta, ta + cleared * (1.0 - 8.0 * kEps) * (tb - ta) - 4.0 * kEps);
}

// Earliest time at which the primitives may be within minDistance, or nothing when they never are.
// Kind supplies the closest points, the one thing in which the two kinds of query differ:
//   static Vec3 axis(const RelativeMotion&, double t): from the closest point of the first
//   primitive to that of the second at time t (its length is their distance).
template <class Kind>
std::optional<double> earliestContact(const RelativeMotion& m) {
  // The common case: f keeps its sign over the whole step.
  if (clipToPlane(m, {m.u.at0, m.u.at1, m.v.at0, m.v.at1, m.w.at0, m.w.at1}).empty) return std::nullopt;
  const SearchScales scales = searchScales(m);

  struct Span {
    double ta, tb;
  };
  // Depth-first, earliest span on top: the stack holds disjoint spans in time order, at most one
  // per halving level. Each span is first narrowed from both sides (the plane clip, then the
  // advancement along the closest-point direction at its start); what is left is clipped again
  // if it shrank by half, halved otherwise.
  std::array<Span, 64> stack;
  int size = 0;
  stack[size++] = {0.0, 1.0};
  for (int visited = 0; size > 0; ++visited) {
    const Span span = stack[--size];
    const double width = span.tb - span.ta;
    const PlaneClip clip = clipToPlane(m, spanEnds(m, span.ta, span.tb));
    if (clip.empty) continue;
    // Outward rounding: t in [0, 1], so an absolute 4 eps covers the rounding of ta + s width.
    Span kept = {std::max(span.ta, span.ta + clip.lo * width - 4.0 * kEps),
                 std::min(span.tb, span.ta + clip.hi * width + 4.0 * kEps)};
    const Vec3 apart = Kind::axis(m, kept.ta);
    if (apart.norm() <= m.minDistance + scales.contactTolerance) return kept.ta;  // within reach already
    const std::optional<double> advanced = advanceAlong(m, scales, apart, kept.ta, kept.tb);
    if (!advanced) continue;
    kept.ta = *advanced;
    const double keptWidth = kept.tb - kept.ta;
    if (visited >= kMaxSpans) return kept.ta;
    if (keptWidth < 0.5 * width) {
      stack[size++] = kept;  // narrowing pays: narrow what is left again
      continue;
    }
    // Narrowing stalls: a contact is near. Halve, unless the span is too short to matter.
    const bool resolved =
        (keptWidth * scales.motion <= scales.resolution && keptWidth <= kTimeResolution) || keptWidth <= kShortestSpan;
    if (resolved) return kept.ta;
    const double middle = 0.5 * (kept.ta + kept.tb);
    stack[size++] = {middle, kept.tb};
    stack[size++] = {kept.ta, middle};
  }
  return std::nullopt;
}

// `direction` scaled to unit length, or nothing when it has none (zero, or not finite).
std::optional<Vec3> unitAlong(const Vec3& direction) {
  const double largest = direction.lpNorm<Eigen::Infinity>();
  if (!(largest > 0.0) || !std::isfinite(largest)) return std::nullopt;
  const Vec3 scaled = direction / largest;  // no underflow or overflow in the norm
  return scaled / scaled.norm();
}

// The first candidate with a direction; +z when none has (all points coincide and stay still).
Vec3 firstUnit(std::initializer_list<Vec3> candidates) {
  for (const Vec3& candidate : candidates) {
    if (const std::optional<Vec3> unit = unitAlong(candidate)) return *unit;
  }
  return Vec3::UnitZ();
}

// N(t) = u(t) x v(t) when it is a usable plane normal (the spanning vectors not parallel).
std::optional<Vec3> planeNormal(const RelativeMotion& m, double t) {
  const Vec3 u = m.u.at(t), v = m.v.at(t);
  const Vec3 n = u.cross(v);
  if (!(n.squaredNorm() > kDegenerateSin2 * u.squaredNorm() * v.squaredNorm())) return std::nullopt;
  return unitAlong(n);
}

// The normal of a contact at t, pointing from the first primitive towards the second.
// - Apart (within minDistance but not touching): the direction between their closest points at t.
// - Touching: the plane normal N(t), turned towards the side the second primitive is on at t = 0
//   (the sign of the cubic at 0), or when that sign is lost in rounding, against its approach.
// - Touching without a plane (degenerate face, parallel edges): the direction between the closest
//   points at t, at 0, or against the approach, whichever first has one.
// `approach` is the motion over the step of the second primitive's contact point relative to the
// first's; `apartAt0`, `apartAtT` go from the first primitive's closest point to the second's.
Vec3 contactNormal(const RelativeMotion& m, double t, const Vec3& approach, const Vec3& apartAt0,
                   const Vec3& apartAtT) {
  const double size = std::max({m.u.at0.norm(), m.u.at1.norm(), m.v.at0.norm(), m.v.at1.norm(),
                                m.w.at0.norm(), m.w.at1.norm()});
  if (apartAtT.norm() > kReliableDirection * size) return apartAtT.normalized();
  if (const std::optional<Vec3> n = planeNormal(m, t)) {
    const double cubicAt0 = m.u.at0.cross(m.v.at0).dot(m.w.at0);
    double side = std::abs(cubicAt0) > m.cubicError ? cubicAt0 : -n->dot(approach);
    if (side == 0.0) side = n->dot(apartAtT);
    return side < 0.0 ? Vec3(-*n) : *n;
  }
  return firstUnit({apartAtT, apartAt0, -approach});
}

// Vertex-face: first = the face (0, u, v) relative to its corner a; second = the vertex at w.
struct VertexFace {
  static PointTriangleClosest closest(const RelativeMotion& m, double t) {
    return closestPointOnTriangle(m.w.at(t), Vec3::Zero(), m.u.at(t), m.v.at(t));
  }
  static Vec3 axis(const RelativeMotion& m, double t) { return m.w.at(t) - closest(m, t).point; }
};

// Edge-edge: first = the first edge (0, u) relative to its end pa; second = (w, w + v).
struct EdgeEdge {
  static SegmentSegmentClosest closest(const RelativeMotion& m, double t) {
    const Vec3 w = m.w.at(t);
    return closestSegmentSegment(Vec3::Zero(), m.u.at(t), w, w + m.v.at(t));
  }
  static Vec3 axis(const RelativeMotion& m, double t) {
    const SegmentSegmentClosest c = closest(m, t);
    return m.w.at(t) + c.t * m.v.at(t) - c.s * m.u.at(t);
  }
};

}  // namespace

std::optional<VertexFaceHit> vertexFaceCcd(const Vec3& p0, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                                           const Vec3& p1, const Vec3& a1, const Vec3& b1, const Vec3& c1,
                                           double minDistance) {
  RelativeMotion m;
  m.u = difference(b0, a0, b1, a1);
  m.v = difference(c0, a0, c1, a1);
  m.w = difference(p0, a0, p1, a1);
  m.gaps = {m.w, difference(p0, b0, p1, b1), difference(p0, c0, p1, c1)};
  m.gapCount = 3;
  m.minDistance = std::max(minDistance, 0.0);
  setCubicBounds(m);

  const std::optional<double> t = earliestContact<VertexFace>(m);
  if (!t) return std::nullopt;
  VertexFaceHit hit;
  hit.t = *t;
  const PointTriangleClosest atT = VertexFace::closest(m, hit.t);
  std::copy(std::begin(atT.weights), std::end(atT.weights), std::begin(hit.weights));
  // The vertex's motion over the step relative to the face point with the contact's barycentric
  // coordinates (relative to corner a, that point is weights[1] u + weights[2] v).
  const Vec3 approach = m.w.motion() - (atT.weights[1] * m.u.motion() + atT.weights[2] * m.v.motion());
  hit.normal = contactNormal(m, hit.t, approach, VertexFace::axis(m, 0.0), m.w.at(hit.t) - atT.point);
  return hit;
}

std::optional<EdgeEdgeHit> edgeEdgeCcd(const Vec3& pa0, const Vec3& pb0, const Vec3& qa0, const Vec3& qb0,
                                       const Vec3& pa1, const Vec3& pb1, const Vec3& qa1, const Vec3& qb1,
                                       double minDistance) {
  RelativeMotion m;
  m.u = difference(pb0, pa0, pb1, pa1);
  m.v = difference(qb0, qa0, qb1, qa1);
  m.w = difference(qa0, pa0, qa1, pa1);
  m.gaps = {m.w, difference(qb0, pa0, qb1, pa1), difference(qa0, pb0, qa1, pb1), difference(qb0, pb0, qb1, pb1)};
  m.gapCount = 4;
  m.minDistance = std::max(minDistance, 0.0);
  setCubicBounds(m);

  const std::optional<double> t = earliestContact<EdgeEdge>(m);
  if (!t) return std::nullopt;
  EdgeEdgeHit hit;
  hit.t = *t;
  const SegmentSegmentClosest atT = EdgeEdge::closest(m, hit.t);
  hit.s = atT.s;
  hit.u = atT.t;
  // contactNormal works from the first edge towards the second, like the axes and `approach` (the
  // motion over the step of the second edge's contact point relative to the first's); ccd.h wants
  // it from the second edge towards the first, hence the minus sign.
  const Vec3 approach = m.w.motion() + hit.u * m.v.motion() - hit.s * m.u.motion();
  hit.normal = -contactNormal(m, hit.t, approach, EdgeEdge::axis(m, 0.0), EdgeEdge::axis(m, hit.t));
  return hit;
}

}  // namespace weft
