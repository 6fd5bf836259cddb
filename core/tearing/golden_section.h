#pragma once
// Refining a sampled best line: a golden-section search on omega over [lo, hi] (the best sample's
// neighbours). omega need not be unimodal there, so the search only ever improves on `best`.
#include <cmath>

#include "tearing/tear_candidates.h"

namespace weft {

// `lineAt(angle)` evaluates the line at an angle (rad).
template <typename LineAt>
void refineByGoldenSection(double lo, double hi, int iterations, const LineAt& lineAt, TearCandidate& best) {
  const double invPhi = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    const double a = hi - invPhi * (hi - lo), b = lo + invPhi * (hi - lo);
    const TearCandidate left = lineAt(a);
    const TearCandidate right = lineAt(b);
    if (left.ratio > best.ratio) best = left;
    if (right.ratio > best.ratio) best = right;
    if (left.ratio >= right.ratio) {
      hi = b;
    } else {
      lo = a;
    }
  }
}

}  // namespace weft
