#pragma once
// Statistics the benchmarks share: shared machines are noisy, so they report medians.
#include <algorithm>
#include <vector>

namespace weft::app {

// The median of the samples (0 for none).
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace weft::app
