#pragma once
// Which candidates tear this step (thesis §3.2). The thesis tears one line per cloth per step, the
// one with the highest ratio omega above 1, and lets the next step re-evaluate (its relaxation):
// a tear moves stress to its neighbours, so their candidates are stale until the cloth responds.
// For large scenes, several tears per step may be allowed when they are far enough apart that
// none can have changed another's stress within the step.
#include <vector>

#include "tearing/tear_candidates.h"

namespace weft {

struct TearSelectionSettings {
  int maxTearsPerStep = 1;      // the thesis' 1; more only for well-separated candidates
  double minSpacing = 0.0;      // m, material space: tears in one step are at least this far apart
};

// Orders by omega (highest first; equal ratios by vertex id, then angle, so the choice never
// depends on anything but the candidates), keeps those above 1 and takes them greedily while they
// keep `minSpacing` from every one already taken, up to maxTearsPerStep.
std::vector<TearCandidate> selectTears(std::vector<TearCandidate> candidates, const TearSelectionSettings& settings);

}  // namespace weft
