#include "tearing/tear_candidates.h"

#include <cmath>
#include <numbers>

#include "tearing/separation_strength.h"

namespace weft {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

// omega of one line at a vertex, filled into `candidate`.
void evaluate(const VertexFan& fan, double angle, const TearTable& table, double weftAngleRad,
              TearCandidate& candidate) {
  candidate.angle = angle;
  candidate.separation = separationStrength(fan, angle);
  candidate.alphaDeg = angleFromWarpDeg(angle, weftAngleRad);
  candidate.required = requiredStrength(table, candidate.alphaDeg);
  candidate.ratio = candidate.separation / candidate.required;
}

// The thesis' lines: both edges and the bisector of each incident corner. On an open fan the
// border edges are skipped (a ray along the border separates nothing).
TearCandidate bestThesisLine(const VertexFan& fan, const TearTable& table, double weftAngleRad,
                             TearSearchCounts& counts) {
  TearCandidate best, trial;
  for (const FanSector& sector : fan.sectors) {
    for (const double angle : {sector.start, sector.start + 0.5 * sector.span, sector.start + sector.span}) {
      ++counts.linesEvaluated;
      evaluate(fan, angle, table, weftAngleRad, trial);
      if (trial.ratio > best.ratio) best = trial;
    }
  }
  return best;
}

// Dense sampling of the fan, then a golden-section search on omega between the best sample's
// neighbours (omega need not be unimodal there; the search only improves on the sample).
TearCandidate bestDenseLine(const VertexFan& fan, const TearTable& table, double weftAngleRad, int samples,
                            TearSearchCounts& counts) {
  const double from = fan.closed ? 0.0 : fan.openStart;
  const double range = fan.closed ? std::numbers::pi : fan.openSpan;
  const double step = range / samples;
  TearCandidate best, trial;
  for (int k = 0; k < samples; ++k) {
    ++counts.linesEvaluated;
    // Rays sit at the middle of their sample interval, so none lies along the open fan's border.
    evaluate(fan, from + (fan.closed ? k : k + 0.5) * step, table, weftAngleRad, trial);
    if (trial.ratio > best.ratio) best = trial;
  }
  if (!(best.ratio > 0.0)) return best;
  const double invPhi = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = fan.closed ? best.angle - step : std::max(from, best.angle - step);
  double hi = fan.closed ? best.angle + step : std::min(from + range, best.angle + step);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const double a = hi - invPhi * (hi - lo), b = lo + invPhi * (hi - lo);
    TearCandidate left, right;
    counts.linesEvaluated += 2;
    evaluate(fan, a, table, weftAngleRad, left);
    evaluate(fan, b, table, weftAngleRad, right);
    if (left.ratio > best.ratio) best = left;
    if (right.ratio > best.ratio) best = right;
    if (left.ratio >= right.ratio) {
      hi = b;
    } else {
      lo = a;
    }
  }
  return best;
}

}  // namespace

double angleFromWarpDeg(double angle, double weftAngleRad) {
  const Vec2 C(std::cos(angle), std::sin(angle));
  const Vec2 V(-std::sin(weftAngleRad), std::cos(weftAngleRad));  // U turned by +90 degrees
  const double determinant = C.x() * V.y() - V.x() * C.y();         // Eq. 3.1
  const double alpha = std::atan2(determinant, C.dot(V)) * kRadToDeg;  // Eq. 3.2
  return std::fmod(alpha + 360.0, 180.0);                            // Eq. 3.3
}

void findTearCandidates(const ClothMesh& mesh, const std::vector<Mat2>& triangleStress, const TearTable& table,
                        double weftAngleRad, const TearSearchSettings& settings, std::vector<TearCandidate>& out,
                        TearSearchCounts& counts) {
  out.clear();
  const std::vector<std::vector<int>> around = vertexTriangles(mesh);
  const double weakest = weakestStrength(table);
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    if (around[v].empty()) continue;
    ++counts.vertices;
    const VertexFan fan = vertexFan(mesh, v, around[v], triangleStress);
    // The margin covers the rounding of the bound itself, so the skip never changes a result.
    if (settings.skipByBound && separationStrengthBound(fan) * (1.0 + 1e-9) < weakest) {
      ++counts.skipped;
      continue;
    }
    TearCandidate best = settings.lines == CandidateLines::Thesis
                             ? bestThesisLine(fan, table, weftAngleRad, counts)
                             : bestDenseLine(fan, table, weftAngleRad, settings.denseDirections, counts);
    if (!(best.ratio > 1.0)) continue;
    best.vertex = v;
    best.ray = !fan.closed;
    out.push_back(best);
  }
}

}  // namespace weft
