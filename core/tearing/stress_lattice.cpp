#include "tearing/stress_lattice.h"

#include <algorithm>
#include <cmath>

namespace weft {

bool StressLattice::reset(long lowI, long highI, long lowJ, long highJ, std::size_t maxNodes, int hotReach) {
  hotReach_ = hotReach;
  // A place's hat reads its node and the next.
  lowI_ = lowI;
  lowJ_ = lowJ;
  countI_ = highI + 2 - lowI;
  countJ_ = highJ + 2 - lowJ;
  const double nodes = static_cast<double>(countI_) * static_cast<double>(countJ_);
  if (!(countI_ > 0 && countJ_ > 0 && nodes <= static_cast<double>(maxNodes))) {
    countI_ = countJ_ = 0;
    nodes_.clear();
    return false;
  }
  nodes_.assign(static_cast<std::size_t>(nodes), Node{});
  hotSources_.assign(static_cast<std::size_t>(nodes), 0);
  return true;
}

void StressLattice::splat(const StressKernel::Place& at, double weight, const Mat2& stress, bool hot) {
  const double wx[2] = {1.0 - at.x.fraction, at.x.fraction};
  const double wy[2] = {1.0 - at.y.fraction, at.y.fraction};
  const Node source = {weight * stress(0, 0), weight * stress(1, 1), weight * stress(0, 1), weight};
  const std::size_t first = index(at.x.node, at.y.node);
  Node* row = &nodes_[first];
  int* hotRow = &hotSources_[first];
  for (int q = 0; q < 2; ++q, row += countI_, hotRow += countI_) {
    for (int p = 0; p < 2; ++p) {
      const double w = wx[p] * wy[q];
      for (int c = 0; c < kChannels; ++c) row[p][c] += w * source[c];
      if (hot && w > 0.0) ++hotRow[p];
    }
  }
}

void StressLattice::blur(int threads) {
  constexpr int reach = StressKernel::kTapReach;
  // In place: along x row by row, then along y column by column, each line copied out first so
  // that a node's sum reads the line as it was. Each node's sum runs over the taps in the same
  // order whatever the thread count. The hot counts are summed by boxSum, in integers.
  auto blurLine = [](std::vector<Node>& line, Node* first, long count, long stride) {
    line.assign(first, first);  // emptied, capacity kept
    for (long k = 0; k < count; ++k) line.push_back(first[k * stride]);
    for (long n = 0; n < count; ++n) {
      Node sum{};
      if (n >= reach && n + reach < count) {
        // Every tap inside the line (most nodes): the same sums without the bounds tests, which
        // kept the compiler from unrolling them.
        const Node* source = &line[n - reach];
        for (int k = 0; k <= 2 * reach; ++k) {
          for (int c = 0; c < kChannels; ++c) sum[c] += StressKernel::kTaps[k] * source[k][c];
        }
      } else {
        for (int k = -reach; k <= reach; ++k) {
          if (n + k < 0 || n + k >= count) continue;
          for (int c = 0; c < kChannels; ++c) sum[c] += StressKernel::kTaps[k + reach] * line[n + k][c];
        }
      }
      first[n * stride] = sum;
    }
  };
#pragma omp parallel num_threads(std::max(1, threads))
  {
    std::vector<Node> line;
#pragma omp for schedule(static)
    for (long j = 0; j < countJ_; ++j) blurLine(line, &nodes_[static_cast<std::size_t>(j * countI_)], countI_, 1);
#pragma omp for schedule(static)
    for (long i = 0; i < countI_; ++i) blurLine(line, &nodes_[static_cast<std::size_t>(i)], countJ_, countI_);
  }
  boxSum(hotSources_, reach, hot_);
  boxSum(hotSources_, hotReach_, hotNear_);
}

void StressLattice::boxSum(const std::vector<int>& counts, long reach, std::vector<int>& out) {
  // Along x, then along y: each node the sum of the counts within `reach` nodes along both axes
  // (a running sum along each line).
  std::vector<int>& alongX = countScratch_;
  alongX.assign(counts.size(), 0);
  for (long j = 0; j < countJ_; ++j) {
    const int* in = &counts[static_cast<std::size_t>(j * countI_)];
    int* row = &alongX[static_cast<std::size_t>(j * countI_)];
    int window = 0;
    for (long k = 0; k <= std::min(reach, countI_ - 1); ++k) window += in[k];
    for (long n = 0; n < countI_; ++n) {
      row[n] = window;
      if (n + reach + 1 < countI_) window += in[n + reach + 1];
      if (n - reach >= 0) window -= in[n - reach];
    }
  }
  out.assign(counts.size(), 0);
  for (long i = 0; i < countI_; ++i) {
    int window = 0;
    for (long k = 0; k <= std::min(reach, countJ_ - 1); ++k) window += alongX[static_cast<std::size_t>(i + k * countI_)];
    for (long n = 0; n < countJ_; ++n) {
      out[static_cast<std::size_t>(i + n * countI_)] = window;
      if (n + reach + 1 < countJ_) window += alongX[static_cast<std::size_t>(i + (n + reach + 1) * countI_)];
      if (n - reach >= 0) window -= alongX[static_cast<std::size_t>(i + (n - reach) * countI_)];
    }
  }
}

StressLattice::Reading StressLattice::read(const StressKernel::Place& at) const {
  const double wx[2] = {1.0 - at.x.fraction, at.x.fraction};
  const double wy[2] = {1.0 - at.y.fraction, at.y.fraction};
  Node sum{};
  Reading reading;
  const std::size_t first = index(at.x.node, at.y.node);
  const Node* row = &nodes_[first];
  for (int q = 0; q < 2; ++q, row += countI_) {
    for (int p = 0; p < 2; ++p) {
      const double w = wx[p] * wy[q];
      for (int c = 0; c < kChannels; ++c) sum[c] += w * row[p][c];
      if (w > 0.0) {
        const std::size_t node = first + static_cast<std::size_t>(p + q * countI_);
        reading.hot = reading.hot || hot_[node] > 0;
        reading.hotNear = reading.hotNear || hotNear_[node] > 0;
      }
    }
  }
  reading.weightedStress << sum[kXX], sum[kXY], sum[kXY], sum[kYY];
  reading.weight = sum[kWeight];
  return reading;
}

}  // namespace weft
