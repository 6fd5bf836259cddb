#include "tearing/crack_tip_stress.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tearing/golden_section.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

// The sharpest turn a crack takes at its tip: 70.5 degrees, the kink of the maximum hoop stress
// criterion under pure shear (Erdogan & Sih 1963, "On the crack extension in plates under plane
// loading and transverse shear"), the largest any loading gives. Rays further back run beside the
// crack's own lips, through the few triangles that took up the crack's opening: they read a shear
// of the discretization, not a load (measured: three times the load straight ahead).
constexpr double kMaxKink = 70.5 * std::numbers::pi / 180.0;

// Where the ray origin + s d leaves triangle t, entered at s = entered: the largest parameter at
// which it crosses one of the triangle's sides (kNone side when it leaves through none, i.e. it
// only grazed a corner).
struct Exit {
  double s = 0.0;
  int side = kNone;
};

Exit exitOf(const Triangle& t, const Vec2& origin, const Vec2& d, double entered) {
  Exit exit{entered, kNone};
  for (int k = 0; k < 3; ++k) {
    const Vec2 a = t.rest[k];
    const Vec2 ab = t.rest[(k + 1) % 3] - a;
    const double denominator = cross2(d, ab);
    if (std::abs(denominator) < 1e-300) continue;
    const Vec2 toA = a - origin;
    const double s = cross2(toA, ab) / denominator;
    const double u = cross2(toA, d) / denominator;
    if (u < -1e-9 || u > 1.0 + 1e-9) continue;
    if (s > exit.s + 1e-12) exit = {s, k};
  }
  return exit;
}

// The open fan's angular range: from its clockwise border spoke, counter-clockwise (rad).
void openRange(const ClothMesh& mesh, const VertexFan& fan, double& start, double& span) {
  const Triangle& first = mesh.tris[fan.triangles.front()];
  const Triangle& last = mesh.tris[fan.triangles.back()];
  const int k0 = fan.corners.front(), k1 = fan.corners.back();
  const Vec2 from = first.rest[(k0 + 1) % 3] - first.rest[k0];
  const Vec2 to = last.rest[(k1 + 2) % 3] - last.rest[k1];
  start = std::atan2(from.y(), from.x());
  span = std::atan2(to.y(), to.x()) - start;
  while (span <= 0.0) span += 2.0 * std::numbers::pi;
  if (fan.closed) span = 2.0 * std::numbers::pi;
}

TearCandidate evaluateRay(const ClothMesh& mesh, const VertexFan& fan, const std::vector<Mat2>& stress,
                          const TearTable& table, double weftAngleRad, const StrengthScale& scale, double length,
                          double angle) {
  TearCandidate line;
  line.angle = angle;
  line.separation = meanTractionAhead(mesh, fan, stress, Vec2(std::cos(angle), std::sin(angle)), length).norm();
  line.alphaDeg = angleFromWarpDeg(angle, weftAngleRad);
  line.required = scale.of(angle) * requiredStrength(table, line.alphaDeg);
  line.ratio = line.separation / line.required;
  line.ray = true;
  line.crackTip = true;
  return line;
}

std::vector<TearCandidate> sampleRays(const ClothMesh& mesh, const VertexFan& fan, const std::vector<Mat2>& stress,
                                      const TearTable& table, double weftAngleRad, const StrengthScale& scale, double length,
                                      int samples, double& start, double& step) {
  double span = 0.0;
  openRange(mesh, fan, start, span);
  // A crack turns by at most kMaxKink from straight on (the middle of the tip's open fan, away
  // from its lips).
  const double middle = start + 0.5 * span;
  const double half = std::min(0.5 * span, kMaxKink);
  start = middle - half;
  span = 2.0 * half;
  samples = std::max(samples, 4);
  step = span / samples;
  std::vector<TearCandidate> rays;
  rays.reserve(samples);
  // Rays at the middle of their sample intervals, so none runs along a lip.
  for (int k = 0; k < samples; ++k) {
    rays.push_back(evaluateRay(mesh, fan, stress, table, weftAngleRad, scale, length, start + (k + 0.5) * step));
  }
  return rays;
}

}  // namespace

Vec2 meanTractionAhead(const ClothMesh& mesh, const VertexFan& fan, const std::vector<Mat2>& triangleStress,
                       const Vec2& direction, double length) {
  const int first = fanTriangleHitBy(mesh, fan, direction);
  if (first == kNone || !(length > 0.0)) return Vec2::Zero();
  const Vec2 normal(-direction.y(), direction.x());
  int t = fan.triangles[first];
  const Vec2 origin = mesh.tris[t].rest[fan.corners[first]];
  Vec2 sum = Vec2::Zero();
  double covered = 0.0;
  // A segment crosses about length / (element size) triangles; the cap only guards a broken mesh.
  for (int crossed = 0; crossed < 100000 && t != kNone; ++crossed) {
    const Triangle& triangle = mesh.tris[t];
    const Exit exit = exitOf(triangle, origin, direction, covered);
    if (exit.side == kNone) break;
    const double until = std::min(exit.s, length);
    sum += (until - covered) * (triangleStress[t] * normal);
    covered = until;
    if (covered >= length) break;
    const Edge& side = mesh.edges[triangle.edge[exit.side]];
    if (side.torn || side.cut) break;  // a crack's flank: no material beyond
    t = triangleAcross(side, t);
  }
  return covered > 0.0 ? Vec2(sum / covered) : Vec2::Zero();
}

TearCandidate bestTipLine(const ClothMesh& mesh, const VertexFan& fan, const std::vector<Mat2>& triangleStress,
                          const TearTable& table, double weftAngleRad, const StrengthScale& strengthScale, double length,
                          int samples) {
  if (fan.triangles.empty()) return TearCandidate{};
  double start = 0.0, step = 0.0;
  const std::vector<TearCandidate> rays =
      sampleRays(mesh, fan, triangleStress, table, weftAngleRad, strengthScale, length, samples, start, step);
  TearCandidate best = *std::max_element(rays.begin(), rays.end(), [](const TearCandidate& a, const TearCandidate& b) {
    return a.ratio < b.ratio;
  });
  if (!(best.ratio > 0.0)) return best;
  const double lo = std::max(start, best.angle - step), hi = std::min(start + step * rays.size(), best.angle + step);
  refineByGoldenSection(lo, hi, 16, [&](double angle) {
    return evaluateRay(mesh, fan, triangleStress, table, weftAngleRad, strengthScale, length, angle);
  }, best);
  return best;
}

std::vector<TearCandidate> tipLinesAboveOne(const ClothMesh& mesh, const VertexFan& fan,
                                            const std::vector<Mat2>& triangleStress, const TearTable& table,
                                            double weftAngleRad, const StrengthScale& strengthScale, double length, int samples) {
  if (fan.triangles.empty()) return {};
  double start = 0.0, step = 0.0;
  const std::vector<TearCandidate> rays =
      sampleRays(mesh, fan, triangleStress, table, weftAngleRad, strengthScale, length, samples, start, step);
  std::vector<TearCandidate> lines;
  const int n = static_cast<int>(rays.size());
  for (int k = 0; k < n; ++k) {
    const double before = k > 0 ? rays[k - 1].ratio : -1.0;
    const double after = k + 1 < n ? rays[k + 1].ratio : -1.0;
    if (rays[k].ratio > 1.0 && rays[k].ratio >= before && rays[k].ratio > after) lines.push_back(rays[k]);
  }
  std::stable_sort(lines.begin(), lines.end(),
                   [](const TearCandidate& a, const TearCandidate& b) { return a.ratio > b.ratio; });
  return lines;
}

}  // namespace weft
