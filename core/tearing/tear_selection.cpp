#include "tearing/tear_selection.h"

#include <algorithm>

namespace weft {

std::vector<TearCandidate> selectTears(std::vector<TearCandidate> candidates, const TearSelectionSettings& settings) {
  std::sort(candidates.begin(), candidates.end(), [](const TearCandidate& a, const TearCandidate& b) {
    if (a.ratio != b.ratio) return a.ratio > b.ratio;
    if (a.vertex != b.vertex) return a.vertex < b.vertex;
    return a.angle < b.angle;
  });
  std::vector<TearCandidate> chosen;
  if (settings.maxTearsPerStep <= 0) return chosen;
  std::vector<Vec2> taken;
  for (const TearCandidate& c : candidates) {
    if (!(c.ratio > 1.0)) break;
    if (settings.maxTearsPerStep == 1) return {c};
    const Vec2& at = c.restPosition;
    const bool farEnough = std::all_of(taken.begin(), taken.end(), [&](const Vec2& p) {
      return (p - at).norm() >= settings.minSpacing;
    });
    if (!farEnough) continue;
    chosen.push_back(c);
    taken.push_back(at);
    if (static_cast<int>(chosen.size()) == settings.maxTearsPerStep) break;
  }
  return chosen;
}

}  // namespace weft
