#include "sim/stage_profile.h"

#include <numeric>

namespace weft {

void StageProfile::add(const std::string& name, double ms) {
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) {
      totalMs[i] += ms;
      return;
    }
  }
  names.push_back(name);
  totalMs.push_back(ms);
}

double StageProfile::total() const { return std::accumulate(totalMs.begin(), totalMs.end(), 0.0); }

}  // namespace weft
