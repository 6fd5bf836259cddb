#include "tearing/tear_candidates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <span>
#include <numbers>

#include "tearing/golden_section.h"
#include "tearing/separation_strength.h"
#include "tearing/strength_map.h"

namespace weft {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

// omega of the line at `angle` whose separation strength is `zeta`.
TearCandidate evaluateLine(double angle, double zeta, const TearTable& table, double weftAngleRad,
                           const StrengthScale& scale) {
  TearCandidate line;
  line.angle = angle;
  line.separation = zeta;
  line.alphaDeg = angleFromWarpDeg(angle, weftAngleRad);
  line.required = scale.of(angle) * requiredStrength(table, line.alphaDeg);
  line.ratio = zeta / line.required;
  return line;
}

// Replaces `best` by the line at `angle` if its omega is higher. omega <= zeta / (the weakest
// strength), so a line whose zeta cannot beat `best` skips the direction and table lookups (the
// margin covers rounding: the result is the same as evaluating everything).
void keepIfBetter(const StressFan& fan, double angle, const TearTable& table, double weakest, double weftAngleRad,
                  const StrengthScale& scale, TearCandidate& best) {
  const double zeta = separationStrength(fan, angle);
  if (zeta < best.ratio * weakest * (1.0 - 1e-12)) return;
  const TearCandidate trial = evaluateLine(angle, zeta, table, weftAngleRad, scale);
  if (trial.ratio > best.ratio) best = trial;
}

// The thesis' lines: both edges and the bisector of each incident corner. On an open fan the
// border edges are skipped (a ray along the border separates nothing).
TearCandidate bestThesisLine(const StressFan& fan, const TearTable& table, double weakest, double weftAngleRad,
                             const StrengthScale& scale, TearSearchCounts& counts) {
  TearCandidate best;
  for (const FanSector& sector : fan.sectors) {
    for (const double angle : {sector.start, sector.start + 0.5 * sector.span, sector.start + sector.span}) {
      ++counts.linesEvaluated;
      keepIfBetter(fan, angle, table, weakest, weftAngleRad, scale, best);
    }
  }
  return best;
}

// Dense sampling of the fan, then a golden-section search on omega between the best sample's
// neighbours (omega need not be unimodal there; the search only improves on the sample).
// The directions sampled: a line's half turn, or a ray's open fan, at most maxTurnRad either side
// of its middle (for a crack tip: straight on).
void sampledRange(const StressFan& fan, double maxTurnRad, double& from, double& range) {
  from = fan.closed ? 0.0 : fan.openStart;
  range = fan.closed ? std::numbers::pi : fan.openSpan;
  if (!fan.closed && 2.0 * maxTurnRad < range) {
    from += 0.5 * range - maxTurnRad;
    range = 2.0 * maxTurnRad;
  }
}

TearCandidate bestDenseLine(const StressFan& fan, const TearTable& table, double weakest, double weftAngleRad,
                            const StrengthScale& scale, int samples, double maxTurnRad, TearSearchCounts& counts) {
  double from = 0.0, range = 0.0;
  sampledRange(fan, maxTurnRad, from, range);
  const double step = range / samples;
  TearCandidate best;
  for (int k = 0; k < samples; ++k) {
    ++counts.linesEvaluated;
    // Rays sit at the middle of their sample interval, so none lies along the open fan's border.
    keepIfBetter(fan, from + (fan.closed ? k : k + 0.5) * step, table, weakest, weftAngleRad, scale, best);
  }
  if (!(best.ratio > 0.0)) return best;
  const double lo = fan.closed ? best.angle - step : std::max(from, best.angle - step);
  const double hi = fan.closed ? best.angle + step : std::min(from + range, best.angle + step);
  refineByGoldenSection(lo, hi, 20, [&](double angle) {
    ++counts.linesEvaluated;
    return evaluateLine(angle, separationStrength(fan, angle), table, weftAngleRad, scale);
  }, best);
  return best;
}

}  // namespace

TearCandidate bestLineAt(const StressFan& fan, const TearTable& table, double weftAngleRad,
                         const TearSearchSettings& settings, const StrengthScale& strengthScale,
                         TearSearchCounts& counts, double maxTurnRad) {
  const double weakest = strengthScale.lowestStrength(table);
  return settings.lines == CandidateLines::Thesis
             ? bestThesisLine(fan, table, weakest, weftAngleRad, strengthScale, counts)
             : bestDenseLine(fan, table, weakest, weftAngleRad, strengthScale, settings.denseDirections, maxTurnRad,
                             counts);
}

namespace {

// A piece of a fan's lines: those within halfWidth of the line at `angle`.
struct LinePiece {
  double bound = 0.0;  // no line of the piece has a higher omega
  double angle = 0.0;  // rad, material space
  double halfWidth = 0.0;
  double omega = 0.0;  // of the line at `angle` itself
  double edge = 0.0;   // a sector edge inside the piece (rad), NaN when there is none: split there
};

LinePiece boundPiece(const StressFan& fan, const TearTable& table, double weftAngleRad, const StrengthScale& scale,
                     double angle, double halfWidth) {
  LinePiece piece;
  piece.angle = angle;
  piece.halfWidth = halfWidth;
  const LinePieceBound lines = separationOverPiece(fan, angle, halfWidth);
  const double alpha = angleFromWarpDeg(angle, weftAngleRad);
  piece.omega = lines.zeta / (scale.of(angle) * requiredStrength(table, alpha));
  const double halfWidthDeg = halfWidth * kRadToDeg;
  piece.bound = lines.bound / scale.lowestStrengthBetween(table, alpha - halfWidthDeg, alpha + halfWidthDeg);
  piece.edge = lines.edge;
  return piece;
}

// The pieces a fan's lines (a closed fan's half turn, an open fan's rays) start as: cut at every
// sector edge, so each piece has the explicit bound of second order in its width
// (separationOverPiece), then cut into equal parts no wider than this. On a regular grid a vertex
// has three edge directions modulo a half turn, so most fans start as 4 pieces, not the 18 equal
// ones of 10 degrees that ignored the edges (measured on the pulled sheet's tearing steps: 147,000
// lines against 209,000; 22.5-degree parts took 155,000, 15-degree ones 174,000).
constexpr double kWidestFirstPiece = std::numbers::pi / 4;  // 45 degrees
// omegaBoundAt's pieces are narrower: its bound decides whether a vertex's full search can be
// skipped, and a looser bound sends more vertices to it (with 45-degree pieces the one-pass mode's
// search took 5,953 lines per step against 2,635).
constexpr double kWidestBoundPiece = std::numbers::pi / 18;  // 10 degrees
// Fans with more sectors than this (rare) start as equal pieces of that width, edges ignored.
constexpr int kMostEdgesCut = 62;

template <typename Visit>
int forEachFirstPiece(const StressFan& fan, double widest, const Visit& visit) {
  double from = 0.0, range = 0.0;
  sampledRange(fan, kNoTurnLimit, from, range);
  if (!(range > 0.0)) return 0;
  // The cuts, as offsets from `from`: the range's ends, then each sector edge inside it (a line's
  // sectors repeat every half turn).
  std::array<double, kMostEdgesCut + 2> cuts;
  int count = 0;
  cuts[count++] = 0.0;
  cuts[count++] = range;
  // A closed uniform fan reads no sector (its zeta is |S n|): nothing to cut at.
  if (!(fan.uniform && fan.closed) && static_cast<int>(fan.sectors.size()) <= kMostEdgesCut) {
    const double period = fan.closed ? std::numbers::pi : 2.0 * std::numbers::pi;
    for (const FanSector& sector : fan.sectors) {
      double offset = std::fmod(sector.start - from, period);
      if (offset < 0.0) offset += period;
      if (offset > 0.0 && offset < range) cuts[count++] = offset;
    }
  }
  std::sort(cuts.begin(), cuts.begin() + count);
  int pieces = 0;
  for (int k = 0; k + 1 < count; ++k) {
    const double width = cuts[k + 1] - cuts[k];
    if (!(width > 1e-12)) continue;  // two edges along one line
    const int parts = static_cast<int>(std::ceil(width / widest - 1e-9));
    const double part = width / parts;
    for (int j = 0; j < parts; ++j) visit(from + cuts[k] + (j + 0.5) * part, 0.5 * part);
    pieces += parts;
  }
  return pieces;
}

}  // namespace

double omegaBoundAt(const StressFan& fan, const TearTable& table, double weftAngleRad,
                    const StrengthScale& strengthScale, TearSearchCounts& counts) {
  double bound = 0.0;
  forEachFirstPiece(fan, kWidestBoundPiece, [&](double angle, double halfWidth) {
    ++counts.linesEvaluated;
    bound = std::max(bound, boundPiece(fan, table, weftAngleRad, strengthScale, angle, halfWidth).bound);
  });
  return bound;
}

bool anyLineAboveOneAt(const StressFan& fan, const TearTable& table, double weftAngleRad, double hintAngle,
                       double& angle, TearSearchCounts& counts, const StrengthScale& scale) {
  // A ray must lie inside its open fan (separationStrength's precondition).
  const double intoFan = fan.closed ? 0.0 : std::remainder(hintAngle - fan.openStart - 0.5 * fan.openSpan, 2.0 * std::numbers::pi);
  if (std::isfinite(hintAngle) && std::abs(intoFan) < 0.5 * fan.openSpan) {
    ++counts.linesEvaluated;
    if (separationStrength(fan, hintAngle) /
            (scale.of(hintAngle) * requiredStrength(table, angleFromWarpDeg(hintAngle, weftAngleRad))) >
        1.0) {
      angle = hintAngle;
      return true;
    }
  }
  // Branch and bound over the fan's lines: the piece with the highest bound is split until a line
  // above 1 is found or every piece's bound is at most 1. A piece narrower than kNarrowest whose
  // bound still exceeds 1 holds lines within a hair of 1 (the bound tends to omega): left undecided
  // as not above 1, as is a fan still undecided after kMostPieces pieces.
  constexpr double kNarrowest = 1e-5;  // rad
  constexpr int kMostPieces = 600;
  std::vector<LinePiece> open;
  auto order = [](const LinePiece& a, const LinePiece& b) { return a.bound < b.bound; };
  bool found = false;
  auto consider = [&](double at, double halfWidth) {
    if (found) return;
    ++counts.linesEvaluated;
    const LinePiece piece = boundPiece(fan, table, weftAngleRad, scale, at, halfWidth);
    if (piece.omega > 1.0) {
      angle = at;
      found = true;
    } else if (piece.bound > 1.0 && halfWidth > kNarrowest) {
      open.push_back(piece);
      std::push_heap(open.begin(), open.end(), order);
    }
  };
  for (int pieces = forEachFirstPiece(fan, kWidestFirstPiece, consider); !found && !open.empty() && pieces < kMostPieces; pieces += 2) {
    std::pop_heap(open.begin(), open.end(), order);
    const LinePiece widest = open.back();
    open.pop_back();
    // Split at the sector edge inside, if any (both halves then have the explicit bound), else
    // in the middle.
    const double lo = widest.angle - widest.halfWidth, hi = widest.angle + widest.halfWidth;
    const double cut = std::isfinite(widest.edge) ? widest.edge : widest.angle;
    consider(0.5 * (lo + cut), 0.5 * (cut - lo));
    consider(0.5 * (cut + hi), 0.5 * (hi - cut));
  }
  return found;
}

std::vector<TearCandidate> linesAboveOneAt(const StressFan& fan, const TearTable& table, double weftAngleRad,
                                           const TearSearchSettings& settings,
                                           const StrengthScale& strengthScale, double maxTurnRad) {
  std::vector<TearCandidate> lines;
  if (settings.lines == CandidateLines::Thesis) {
    for (const FanSector& sector : fan.sectors) {
      for (const double angle : {sector.start, sector.start + 0.5 * sector.span, sector.start + sector.span}) {
        lines.push_back(evaluateLine(angle, separationStrength(fan, angle), table, weftAngleRad, strengthScale));
      }
    }
  } else {
    // The dense samples' local maxima: each a different way the vertex could open.
    double from = 0.0, range = 0.0;
    sampledRange(fan, maxTurnRad, from, range);
    const int n = std::max(4, settings.denseDirections);
    std::vector<TearCandidate> samples;
    for (int k = 0; k < n; ++k) {
      const double angle = from + (fan.closed ? k : k + 0.5) * range / n;
      samples.push_back(evaluateLine(angle, separationStrength(fan, angle), table, weftAngleRad, strengthScale));
    }
    for (int k = 0; k < n; ++k) {
      const bool wraps = fan.closed;
      const double before = k > 0 ? samples[k - 1].ratio : wraps ? samples[n - 1].ratio : -1.0;
      const double after = k + 1 < n ? samples[k + 1].ratio : wraps ? samples[0].ratio : -1.0;
      if (samples[k].ratio >= before && samples[k].ratio > after) lines.push_back(samples[k]);
    }
  }
  std::erase_if(lines, [](const TearCandidate& c) { return !(c.ratio > 1.0); });
  std::stable_sort(lines.begin(), lines.end(),
                   [](const TearCandidate& a, const TearCandidate& b) { return a.ratio > b.ratio; });
  return lines;
}

void findTearCandidates(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                        const std::vector<Mat2>& triangleStress, const TearTable& table,
                        double weftAngleRad, const TearSearchSettings& settings, std::vector<TearCandidate>& out,
                        TearSearchCounts& counts, const TearStrengthMap* strengthMap, const TearRegion* region) {
  out.clear();
  // The triangles around each vertex in compressed rows (one allocation, not one per vertex).
  const int n = mesh.vertexCount();
  std::vector<int> rowStart(n + 1, 0), around(3 * mesh.tris.size());
  for (const Triangle& t : mesh.tris) {
    for (int v : t.v) ++rowStart[v + 1];
  }
  for (int v = 0; v < n; ++v) rowStart[v + 1] += rowStart[v];
  std::vector<int> fill(rowStart.begin(), rowStart.end() - 1);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    for (int v : mesh.tris[t].v) around[fill[v]++] = t;
  }
  auto fanOf = [&](int v, StressFan& fan) {
    stressFan(mesh, v, std::span<const int>(around.data() + rowStart[v], around.data() + rowStart[v + 1]), corners,
              triangleStress, fan);
    if (settings.closedFanAsOne && fan.closed) makeUniform(fan, meanStress(fan));
  };
  auto restPositionOf = [&](int v) {
    const Triangle& first = mesh.tris[around[rowStart[v]]];
    return first.rest[first.v[0] == v ? 0 : first.v[1] == v ? 1 : 2];
  };
  auto scaleOf = [&](int v, const StressFan& fan) {
    return strengthMap != nullptr || region != nullptr
               ? StrengthScale(1.0, strengthMap, region, &table, weftAngleRad, restPositionOf(v), !fan.closed)
               : StrengthScale(1.0);
  };
  auto bestLineOf = [&](int v, const StressFan& fan) {
    return bestLineAt(fan, table, weftAngleRad, settings, scaleOf(v, fan), counts);
  };
  auto candidateOf = [&](int v, const StressFan& fan, TearCandidate best) {
    best.vertex = v;
    best.restPosition = restPositionOf(v);
    best.ray = !fan.closed;
    return best;
  };
  // The vertices that may reach omega = 1 (all of them without the bound), with their bounds.
  // The margin covers the rounding of the bound itself, so the skip never changes a result.
  StressFan fan;
  std::vector<std::pair<double, int>> open;  // (bound on omega, vertex)
  for (int v = 0; v < n; ++v) {
    if (rowStart[v] == rowStart[v + 1]) continue;
    ++counts.vertices;
    double bound = std::numeric_limits<double>::infinity();
    if (settings.skipByBound) {
      fanOf(v, fan);
      // The map lowers a line's strength at most to its lowest multiplier near the vertex.
      bound = separationStrengthBound(fan) * (1.0 + 1e-9) / scaleOf(v, fan).lowestStrength(table);
      if (bound < 1.0) {
        ++counts.skipped;
        continue;
      }
    }
    open.emplace_back(bound, v);
  }
  if (settings.onlyTheBest && settings.skipByBound) {
    // Branch and bound: in order of decreasing bound, until no vertex left can beat the best
    // found (ties are still evaluated, so the winner is the one selectTears would pick).
    std::sort(open.begin(), open.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    TearCandidate winner;
    for (const auto& [bound, v] : open) {
      if (bound < winner.ratio) {
        ++counts.skipped;
        continue;
      }
      fanOf(v, fan);
      const TearCandidate best = candidateOf(v, fan, bestLineOf(v, fan));
      if (best.ratio > winner.ratio || (best.ratio == winner.ratio && best.vertex < winner.vertex)) winner = best;
    }
    if (winner.ratio > 1.0) out.push_back(winner);
    return;
  }
  for (const auto& [bound, v] : open) {
    fanOf(v, fan);
    const TearCandidate best = bestLineOf(v, fan);
    if (best.ratio > 1.0) out.push_back(candidateOf(v, fan, best));
  }
}

}  // namespace weft
