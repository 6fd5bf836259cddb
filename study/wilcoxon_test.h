#pragma once
// The Wilcoxon signed-rank test for two related samples (each participant scored twice), with the
// large-sample normal approximation as SPSS reports it: differences are second − first, zero
// differences are dropped, |differences| get average ranks, the variance is tie-corrected and
// there is no continuity correction. "Test statistic" in the thesis' Tables 4.16-4.27 is the sum
// of the positive differences' ranks; Z = (W+ − n'(n'+1)/4) / σ and the p is two-sided.
#include <vector>

namespace weft::study {

struct WilcoxonResult {
  int pairs = 0;                 // N: participants
  int positive = 0;              // second > first
  int negative = 0;              // second < first
  int ties = 0;                  // second == first (dropped from the ranking)
  double positiveRankSum = 0.0;  // W+: the thesis' "test statistic"
  double negativeRankSum = 0.0;  // W−
  double z = 0.0;                // standardized W+ (SPSS's legacy output prints −|z|)
  double asymptoticP = 1.0;      // two-sided, from the standard normal (Boost.Math)
};

// first[i] and second[i] belong to participant i; both the same length. With no non-zero
// difference there is nothing to rank: z = 0, p = 1.
WilcoxonResult wilcoxonSignedRankTest(const std::vector<double>& first, const std::vector<double>& second);

}  // namespace weft::study
