#include "friedman_test.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <cassert>

#include "average_ranks.h"

namespace weft::study {

FriedmanResult friedmanTest(const std::vector<std::vector<double>>& scores) {
  assert(!scores.empty() && scores.front().size() >= 2);
  FriedmanResult result;
  result.blocks = static_cast<int>(scores.size());
  result.conditions = static_cast<int>(scores.front().size());
  result.degreesOfFreedom = result.conditions - 1;
  const double n = result.blocks;
  const double k = result.conditions;

  std::vector<double> rankSums(scores.front().size(), 0.0);
  double tieSum = 0.0;
  for (const auto& row : scores) {
    assert(row.size() == rankSums.size());
    const RankedValues ranked = averageRanks(row);
    for (std::size_t j = 0; j < row.size(); ++j) rankSums[j] += ranked.ranks[j];
    tieSum += ranked.tieSum;
  }
  double squaredRankSums = 0.0;
  for (double sum : rankSums) {
    result.meanRanks.push_back(sum / n);
    squaredRankSums += sum * sum;
  }
  result.uncorrectedStatistic = 12.0 / (n * k * (k + 1.0)) * squaredRankSums - 3.0 * n * (k + 1.0);
  // The tie correction divides by the share of the rank variance left once ties are averaged.
  const double untiedShare = 1.0 - tieSum / (n * k * (k * k - 1.0));
  if (untiedShare <= 0.0) return result;  // every row all ties: nothing to compare
  result.statistic = result.uncorrectedStatistic / untiedShare;
  if (result.statistic < 0.0) result.statistic = 0.0;  // rounding of an exact 0
  const boost::math::chi_squared distribution(result.degreesOfFreedom);
  result.asymptoticP = boost::math::cdf(boost::math::complement(distribution, result.statistic));
  return result;
}

}  // namespace weft::study
