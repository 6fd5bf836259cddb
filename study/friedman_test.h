#pragma once
// The Friedman test: do k related conditions (the fabrics) differ, judged on n blocks (the
// participants), without assuming normality? Each participant's k scores are ranked among
// themselves; the statistic compares the conditions' rank sums.
//
// The statistic is the tie-corrected one, as SPSS prints it: the thesis' Table 4.13 (1.366,
// p = 0.714 from Table 4.11) is reproduced only with the correction (without it: 1.093, p = 0.779).
// Its p is asymptotic: chi-squared with k − 1 degrees of freedom (Boost.Math).
#include <vector>

namespace weft::study {

struct FriedmanResult {
  int blocks = 0;                     // N: participants (rows)
  int conditions = 0;                 // k: fabrics (columns)
  std::vector<double> meanRanks;      // per condition, in column order
  double statistic = 0.0;             // chi-squared, tie-corrected (what SPSS reports)
  double uncorrectedStatistic = 0.0;  // the textbook 12/(nk(k+1)) ΣR² − 3n(k+1), for comparison
  int degreesOfFreedom = 0;           // k − 1
  double asymptoticP = 1.0;           // P(chi-squared(k − 1) ≥ statistic)
};

// scores[participant][condition]; every row must have the same k ≥ 2 entries and n ≥ 1. When every
// participant scores every condition alike the statistic is undefined; it is reported as 0, p = 1.
FriedmanResult friedmanTest(const std::vector<std::vector<double>>& scores);

}  // namespace weft::study
