#include "average_ranks.h"

#include <algorithm>
#include <numeric>

namespace weft::study {

RankedValues averageRanks(const std::vector<double>& values) {
  const std::size_t n = values.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  RankedValues out;
  out.ranks.assign(n, 0.0);
  for (std::size_t first = 0; first < n;) {
    std::size_t last = first;
    while (last + 1 < n && values[order[last + 1]] == values[order[first]]) ++last;
    const double sharedRank = 0.5 * static_cast<double>(first + last) + 1.0;
    for (std::size_t i = first; i <= last; ++i) out.ranks[order[i]] = sharedRank;
    const double tied = static_cast<double>(last - first + 1);
    out.tieSum += tied * tied * tied - tied;
    first = last + 1;
  }
  return out;
}

}  // namespace weft::study
