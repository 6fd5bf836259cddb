#include "wilcoxon_test.h"

#include <boost/math/distributions/normal.hpp>
#include <cassert>
#include <cmath>

#include "average_ranks.h"

namespace weft::study {

WilcoxonResult wilcoxonSignedRankTest(const std::vector<double>& first, const std::vector<double>& second) {
  assert(first.size() == second.size());
  WilcoxonResult result;
  result.pairs = static_cast<int>(first.size());
  std::vector<double> differences;
  for (std::size_t i = 0; i < first.size(); ++i) {
    const double d = second[i] - first[i];
    if (d == 0.0) {
      ++result.ties;
      continue;
    }
    ++(d > 0.0 ? result.positive : result.negative);
    differences.push_back(d);
  }
  if (differences.empty()) return result;

  std::vector<double> magnitudes;
  for (double d : differences) magnitudes.push_back(std::abs(d));
  const RankedValues ranked = averageRanks(magnitudes);
  for (std::size_t i = 0; i < differences.size(); ++i) {
    (differences[i] > 0.0 ? result.positiveRankSum : result.negativeRankSum) += ranked.ranks[i];
  }
  const double n = static_cast<double>(differences.size());
  const double mean = n * (n + 1.0) / 4.0;
  const double variance = n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - ranked.tieSum / 48.0;
  if (variance <= 0.0) return result;
  result.z = (result.positiveRankSum - mean) / std::sqrt(variance);
  const boost::math::normal standardNormal;
  result.asymptoticP = 2.0 * boost::math::cdf(boost::math::complement(standardNormal, std::abs(result.z)));
  return result;
}

}  // namespace weft::study
