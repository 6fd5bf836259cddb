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

double StageProfile::totalWithPrefix(const std::string& prefix) const {
  double ms = 0.0;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names[k].rfind(prefix, 0) == 0) ms += totalMs[k];
  }
  return ms;
}

}  // namespace weft
