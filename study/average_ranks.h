#pragma once
// Ranks 1..n of a list of values, tied values sharing the mean of the ranks they span (the
// "average" or "mid-rank" method that SPSS, R and SciPy use for the Friedman and Wilcoxon tests).
// Ties are exact equality: study scores are multiples of 0.5 and counts, so no tolerance is needed.
#include <vector>

namespace weft::study {

struct RankedValues {
  std::vector<double> ranks;  // ranks[i] belongs to values[i]
  double tieSum = 0.0;        // Σ (t³ − t) over the groups of t tied values, for the tie corrections
};

RankedValues averageRanks(const std::vector<double>& values);

}  // namespace weft::study
