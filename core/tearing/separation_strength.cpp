#include "tearing/separation_strength.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace weft {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// `angle` moved by whole turns into [from, from + 2 pi). The angles met here lie within a few
// turns of each other, so a few additions are cheaper than std::fmod (the inner loop's cost).
double wrapFrom(double angle, double from) {
  if (!std::isfinite(angle) || !std::isfinite(from)) return from;
  double a = angle;
  while (a < from) a += kTwoPi;
  while (a >= from + kTwoPi) a -= kTwoPi;
  return a;
}

Vec2 gAt(double theta) { return Vec2(std::sin(theta), -std::cos(theta)); }

double tractionAcross(const StressFan& fan, double angle) { return weft::tractionAcross(fan.uniformStress, angle); }

bool readsUniformly(const StressFan& fan) { return fan.uniform && fan.closed; }

}  // namespace

double tractionAcross(const Mat2& stress, double angle) { return (stress * gAt(angle)).norm(); }

namespace {

// The traction force on the vertex from the part of the fan inside the arc [from, from + length]
// (length <= 2 pi), with g at the arc's ends given: each sector's overlap with the arc is at most
// two pieces (the second when it wraps past the arc's start), and each piece ends at a sector edge
// or at an arc end, where g is known.
Vec2 arcForce(const StressFan& fan, double from, double length, const Vec2& gFrom, const Vec2& gTo) {
  Vec2 force = Vec2::Zero();
  const double to = from + length;
  for (const FanSector& sector : fan.sectors) {
    const double a = wrapFrom(sector.start, from);
    const double b = a + sector.span;
    if (a < to) force += sector.stress * ((b <= to ? sector.gEnd : gTo) - sector.gStart);
    if (b - kTwoPi > from) force += sector.stress * ((b - kTwoPi <= to ? sector.gEnd : gTo) - gFrom);
  }
  return force;
}

}  // namespace

double spectralNorm(const Mat2& s) {
  const double mean = 0.5 * (s(0, 0) + s(1, 1));
  const double half = 0.5 * (s(0, 0) - s(1, 1));
  return std::abs(mean) + std::sqrt(half * half + s(0, 1) * s(0, 1));
}

namespace {

// Eq. 2.70-2.71 for the two sides' forces.
double balancedPull(const Vec2& q1, const Vec2& q2) {
  const double n1 = q1.norm(), n2 = q2.norm();
  if (!(n1 > 0.0) || !(n2 > 0.0) || !(q1.dot(q2) < 0.0)) return 0.0;
  const Vec2 direction = (q1 / n1 - q2 / n2).normalized();
  return std::min(q1.dot(direction), -q2.dot(direction));
}

}  // namespace

FanSector cornerSector(const Triangle& tri, int k) {
  const Vec2 first = tri.rest[(k + 1) % 3] - tri.rest[k];
  const Vec2 second = tri.rest[(k + 2) % 3] - tri.rest[k];
  FanSector sector;
  sector.start = std::atan2(first.y(), first.x());
  // Counter-clockwise triangles: the second edge is the first turned by the corner's angle.
  sector.span = std::atan2(first.x() * second.y() - first.y() * second.x(), first.dot(second));
  sector.gStart = normalIntegral(first.normalized());
  sector.gEnd = normalIntegral(second.normalized());
  return sector;
}

void updateTriangleCorners(const ClothMesh& mesh, const std::vector<int>& triangles, std::vector<TriangleCorners>& corners) {
  corners.resize(mesh.tris.size());
  for (int t : triangles) {
    for (int k = 0; k < 3; ++k) corners[t][k] = cornerSector(mesh.tris[t], k);
  }
}

std::vector<TriangleCorners> triangleCorners(const ClothMesh& mesh) {
  std::vector<int> all(mesh.tris.size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
  std::vector<TriangleCorners> corners;
  updateTriangleCorners(mesh, all, corners);
  return corners;
}

void stressFan(const ClothMesh& mesh, int vertex, std::span<const int> around,
               const std::vector<TriangleCorners>& corners, const std::vector<Mat2>& triangleStress, StressFan& fan) {
  fan.sectors.clear();
  fan.closed = true;
  fan.uniform = false;
  fan.openStart = 0.0;
  fan.openSpan = 0.0;
  for (int t : around) {
    const Triangle& tri = mesh.tris[t];
    const int k = tri.v[0] == vertex ? 0 : tri.v[1] == vertex ? 1 : 2;
    FanSector sector = corners[t][k];
    sector.stress = triangleStress[t];
    fan.sectors.push_back(sector);
    // The corner's first edge runs from v[k] to v[k+1] (Triangle::edge[k]); on a boundary, the
    // fan starts here.
    if (mesh.edges[tri.edge[k]].isBoundary()) {
      fan.closed = false;
      fan.openStart = sector.start;
    }
    fan.openSpan += sector.span;
  }
  if (fan.closed) fan.openSpan = kTwoPi;
}

void makeUniform(StressFan& fan, const Mat2& stress) {
  for (FanSector& sector : fan.sectors) sector.stress = stress;
  fan.uniform = true;
  fan.uniformStress = stress;
}

Mat2 meanStress(const StressFan& fan) {
  Mat2 sum = Mat2::Zero();
  double spans = 0.0;
  for (const FanSector& sector : fan.sectors) {
    sum += sector.span * sector.stress;
    spans += sector.span;
  }
  return spans > 0.0 ? Mat2(sum / spans) : Mat2::Zero();
}

FanSector makeSector(double start, double span, const Mat2& stress) {
  FanSector sector;
  sector.start = start;
  sector.span = span;
  sector.gStart = gAt(start);
  sector.gEnd = gAt(start + span);
  sector.stress = stress;
  return sector;
}

namespace {

// lineSides with g(angle) given.
LineSides lineSidesWith(const StressFan& fan, double angle, const Vec2& gLine) {
  if (fan.closed) {
    // Side 1 lies counter-clockwise of the line's direction, side 2 clockwise (Figure 2.9);
    // g(angle + pi) = -g(angle).
    return {arcForce(fan, angle, std::numbers::pi, gLine, -gLine),
            arcForce(fan, angle + std::numbers::pi, std::numbers::pi, -gLine, gLine)};
  }
  const double ray = wrapFrom(angle, fan.openStart);
  const double before = std::min(ray - fan.openStart, fan.openSpan);
  const Vec2 gStart = gAt(fan.openStart), gEnd = gAt(fan.openStart + fan.openSpan);
  return {arcForce(fan, fan.openStart, before, gStart, gLine),
          arcForce(fan, fan.openStart + before, fan.openSpan - before, gLine, gEnd)};
}

}  // namespace

LineSides lineSides(const StressFan& fan, double angle) { return lineSidesWith(fan, angle, gAt(angle)); }

double separationFromSides(const StressFan& fan, const LineSides& sides) {
  return (fan.closed ? 0.5 : 1.0) * balancedPull(sides.q1, sides.q2);
}

double separationStrength(const StressFan& fan, double angle) {
  if (readsUniformly(fan)) return tractionAcross(fan, angle);
  return separationFromSides(fan, lineSides(fan, angle));
}

double sideForceRate(const StressFan& fan) {
  double largest = 0.0;
  for (const FanSector& sector : fan.sectors) largest = std::max(largest, spectralNorm(sector.stress));
  return (fan.closed ? 2.0 : 1.0) * largest;
}

double separationBoundNear(const StressFan& fan, const LineSides& sides, double drift) {
  const double a = sides.q1.norm(), b = sides.q2.norm();
  const double shortest = std::min(a, b) + drift;
  // How far each side's direction may turn; a side shorter than the drift may point anywhere.
  auto turn = [&](double length) { return drift < length ? std::asin(drift / length) : std::numbers::pi; };
  const double apart = a > 0.0 && b > 0.0 ? std::acos(std::clamp(-sides.q1.dot(sides.q2) / (a * b), -1.0, 1.0))
                                          : std::numbers::pi;  // phi, between q1 and -q2
  const double closest = std::max(0.0, apart - turn(a) - turn(b));
  const double bound = closest >= 0.5 * std::numbers::pi ? 0.0 : shortest * std::cos(0.5 * closest);
  // The margin covers rounding, so the bound never settles a line that would tear.
  return (fan.closed ? 0.5 : 1.0) * bound * (1.0 + 1e-9) + 1e-12 * drift;
}

namespace {

// Third bound, for an open fan as wide as a straight border's, or nearly: byMean below is loose
// there by the chord of a quarter circle (a factor of 1.41), which let every vertex of a loaded
// border through to the search. With a = q1, b = -q2 and phi the angle between them, zeta =
// min(|a|, |b|) cos(phi / 2) <= sqrt((|a||b| + a.b) / 2). For one stress S over a fan of angle pi,
// a = S (u - w) and b = S (u + w) (u = g(ray), w = g(first spoke)), so |a||b| <= (|a|^2 + |b|^2) / 2
// = |Su|^2 + |Sw|^2 (the parallelogram law) and a.b = |Su|^2 - |Sw|^2: zeta <= |S u| = |S n| <= |S|,
// the traction across the ray. The sectors' own stresses move each side's force by at most D (their
// deviation from S times their angles, each chord being shorter than its arc), and a fan of angle
// F moves b by at most |S| |pi - F| more: with d their sum, zeta^2 <= |S|^2 + d (|a| + |b|) + d^2
// <= |S|^2 + 2 sqrt(2) d |S| + d^2.
double straightFanBound(double largestOfMean, double deviation, double openSpan) {
  const double d = deviation + largestOfMean * std::abs(std::numbers::pi - openSpan);
  return std::sqrt(largestOfMean * largestOfMean + 2.0 * std::numbers::sqrt2 * d * largestOfMean + d * d);
}

// separationStrengthBound over `count` sectors, sector k read through stressOf(k), largestOf(k)
// (its spectral norm) and spanOf(k): one body for a built fan and for a closed fan's triangles,
// so both give the same bound to the last bit.
template <typename StressOf, typename LargestOf, typename SpanOf>
double fanStrengthBound(std::size_t count, const StressOf& stressOf, const LargestOf& largestOf, const SpanOf& spanOf,
                        bool closed, double openSpan) {
  // sigma+ is positive semi-definite: its spectral norm is its largest principal stress.
  double weighted = 0.0, totalSpan = 0.0;
  Mat2 mean = Mat2::Zero();
  for (std::size_t k = 0; k < count; ++k) {
    weighted += largestOf(k) * spanOf(k);
    mean += stressOf(k) * spanOf(k);
    totalSpan += spanOf(k);
  }
  if (!(totalSpan > 0.0)) return 0.0;
  mean /= totalSpan;
  double deviation = 0.0;  // D
  for (std::size_t k = 0; k < count; ++k) deviation += spectralNorm(stressOf(k) - mean) * spanOf(k);
  // First bound: |q1| + |q2| <= weighted; zeta <= min(|q1|, |q2|) <= weighted / 2, halved again
  // at an interior vertex.
  const double byArcs = (closed ? 0.25 : 0.5) * weighted;
  // Second bound: min(|q1|, |q2|) <= |S| max chord + D / 2. A closed fan's sides are half circles
  // (chord 2, then zeta is halved); an open fan of angle F split anywhere has a side whose chord
  // is at most 2 sin(F / 4).
  const double byMean = closed ? spectralNorm(mean) + 0.25 * deviation
                               : 2.0 * std::sin(0.25 * openSpan) * spectralNorm(mean) + 0.5 * deviation;
  if (closed) return std::min(byArcs, byMean);
  return std::min({byArcs, byMean, straightFanBound(spectralNorm(mean), deviation, openSpan)});
}

}  // namespace

double separationStrengthBound(const StressFan& fan) {
  // |S n| <= the largest principal stress of S (positive semi-definite: an average of sigma+).
  if (readsUniformly(fan)) return spectralNorm(fan.uniformStress);
  const auto& sectors = fan.sectors;
  return fanStrengthBound(
      sectors.size(), [&](std::size_t k) -> const Mat2& { return sectors[k].stress; },
      [&](std::size_t k) { return spectralNorm(sectors[k].stress); }, [&](std::size_t k) { return sectors[k].span; },
      fan.closed, fan.openSpan);
}

double closedFanStrengthBound(std::span<const int> triangles, std::span<const double> spans,
                              const std::vector<Mat2>& stress, const std::vector<double>& largestPrincipal) {
  return fanStrengthBound(
      triangles.size(), [&](std::size_t k) -> const Mat2& { return stress[triangles[k]]; },
      [&](std::size_t k) { return largestPrincipal[triangles[k]]; }, [&](std::size_t k) { return spans[k]; }, true,
      0.0);
}

namespace {

// The largest |x + M (g(middle + Delta) - g(middle))| over |Delta| <= halfWidth (see the header),
// with r the middle line's direction and g = g(middle); sin and cos of halfWidth given.
double largestAlongPiece(const Vec2& x, const Mat2& m, const Vec2& r, const Vec2& g, double sinHalf, double cosHalf) {
  const Vec2 turn = sinHalf * (m * r);
  return std::max((x + turn).norm(), (x - turn).norm()) + (1.0 - cosHalf) * (m * g).norm();
}

// The sector holding the direction `angle`, or -1 (a gap left by rounding).
int sectorAt(const StressFan& fan, double angle) {
  for (std::size_t k = 0; k < fan.sectors.size(); ++k) {
    const FanSector& sector = fan.sectors[k];
    if (wrapFrom(angle, sector.start) - sector.start < sector.span) return static_cast<int>(k);
  }
  return -1;
}

}  // namespace

namespace {

// separationOverPiece on a closed uniform fan. With n = (-sin, cos) and M = S^2,
// |S n|^2 = n^T M n = (M00 + M11) / 2 + (M11 - M00) / 2 cos 2theta - M01 sin 2theta
//         = mean + amplitude cos(2 theta - peak).
LinePieceBound uniformPiece(const StressFan& fan, double middle, double halfWidth) {
  LinePieceBound piece;
  piece.edge = std::numeric_limits<double>::quiet_NaN();
  piece.zeta = tractionAcross(fan, middle);
  const Mat2 m = fan.uniformStress * fan.uniformStress;
  const double mean = 0.5 * (m(0, 0) + m(1, 1));
  const double amplitude = std::hypot(0.5 * (m(1, 1) - m(0, 0)), m(0, 1));
  const double peak = 0.5 * std::atan2(-m(0, 1), 0.5 * (m(1, 1) - m(0, 0)));  // the largest |S n|, mod pi
  const double lo = middle - halfWidth, hi = middle + halfWidth;
  const double firstPeak = peak + std::ceil((lo - peak) / std::numbers::pi) * std::numbers::pi;
  double largest2;
  if (firstPeak <= hi) {
    largest2 = mean + amplitude;
  } else {
    const double atLo = tractionAcross(fan, lo), atHi = tractionAcross(fan, hi);
    largest2 = std::max(atLo * atLo, atHi * atHi);
  }
  // The margin covers rounding (of the peak's angle too), so the bound never settles a line that
  // would tear.
  piece.bound = std::sqrt(std::max(largest2, 0.0)) * (1.0 + 1e-9) + 1e-12 * spectralNorm(fan.uniformStress);
  piece.bound = std::max(piece.bound, piece.zeta);
  return piece;
}

}  // namespace

LinePieceBound separationOverPiece(const StressFan& fan, double middle, double halfWidth) {
  if (readsUniformly(fan)) return uniformPiece(fan, middle, halfWidth);
  LinePieceBound piece;
  const Vec2 g = gAt(middle);
  const LineSides sides = lineSidesWith(fan, middle, g);
  piece.zeta = separationFromSides(fan, sides);
  piece.bound = separationBoundNear(fan, sides, sideForceRate(fan) * halfWidth);
  piece.edge = std::numeric_limits<double>::quiet_NaN();
  // A sector edge inside the piece: for a line, an edge at either end of it (so modulo pi).
  const double period = fan.closed ? std::numbers::pi : kTwoPi;
  for (const FanSector& sector : fan.sectors) {
    // The edge's offset from the middle, within half a period (a few additions: the angles met
    // here lie within a few turns of each other, and std::remainder was much of a piece's cost).
    double offset = sector.start - middle;
    while (offset > 0.5 * period) offset -= period;
    while (offset < -0.5 * period) offset += period;
    if (std::abs(offset) < halfWidth * (1.0 - 1e-12)) {
      piece.edge = middle + offset;
      return piece;
    }
  }
  const int at = sectorAt(fan, middle);
  const int across = fan.closed ? sectorAt(fan, middle + std::numbers::pi) : at;
  if (at < 0 || across < 0) return piece;
  const Vec2 r(-g.y(), g.x());  // (cos, sin) of the middle, from g = (sin, -cos): the same bits
  const double sinHalf = std::sin(halfWidth), cosHalf = std::cos(halfWidth);
  // q1' = -(sigma(theta) + sigma(theta + pi)) r(theta) for a line, and q2 = total - q1 turns the
  // other way; for a ray q1' = sigma(theta) r(theta), q2' = -q1'.
  const Mat2 m = fan.closed ? Mat2(-(fan.sectors[at].stress + fan.sectors[across].stress))
                            : Mat2(fan.sectors[at].stress);
  // The largest |q1| and |q2| over the piece.
  const double a = largestAlongPiece(sides.q1, m, r, g, sinHalf, cosHalf);
  const double b = largestAlongPiece(sides.q2, -m, r, g, sinHalf, cosHalf);
  // zeta <= min(|q1|, |q2|) (halved at an interior vertex); the margin covers rounding.
  const double explicitBound = (fan.closed ? 0.5 : 1.0) * std::min(a, b) * (1.0 + 1e-9);
  piece.bound = std::min(piece.bound, explicitBound);
  return piece;
}

}  // namespace weft
