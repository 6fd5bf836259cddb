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
  return true;
}

void StressLattice::splat(const StressKernel::Place& at, double weight, const Mat2& stress, bool hot) {
  const double wx[2] = {1.0 - at.x.fraction, at.x.fraction};
  const double wy[2] = {1.0 - at.y.fraction, at.y.fraction};
  const Node source = {weight * stress(0, 0), weight * stress(1, 1), weight * stress(0, 1), weight, hot ? 1.0 : 0.0,
                       hot ? 1.0 : 0.0};
  Node* row = &nodes_[index(at.x.node, at.y.node)];
  for (int q = 0; q < 2; ++q, row += countI_) {
    for (int p = 0; p < 2; ++p) {
      const double w = wx[p] * wy[q];
      for (int c = 0; c < kChannels; ++c) row[p][c] += w * source[c];
    }
  }
}

void StressLattice::blur(int threads) {
  constexpr int reach = StressKernel::kTapReach;
  // In place: along x row by row, then along y column by column, each line copied out first so
  // that a node's sum reads the line as it was. Each node's sum runs over the taps in the same
  // order whatever the thread count.
  // The near-hot count is summed over hotReach_ nodes each way with equal taps (it only tells
  // whether any is there).
  const long hotReach = hotReach_;
  auto blurLine = [hotReach](std::vector<Node>& line, Node* first, long count, long stride) {
    line.assign(first, first);  // emptied, capacity kept
    for (long k = 0; k < count; ++k) line.push_back(first[k * stride]);
    for (long n = 0; n < count; ++n) {
      Node sum{};
      if (n >= reach && n + reach < count) {
        // Every tap inside the line (most nodes): the same sums without the bounds tests, which
        // kept the compiler from unrolling them.
        const Node* source = &line[n - reach];
        for (int k = 0; k <= 2 * reach; ++k) {
          for (int c = 0; c < kHotNear; ++c) sum[c] += StressKernel::kTaps[k] * source[k][c];
        }
      } else {
        for (int k = -reach; k <= reach; ++k) {
          if (n + k < 0 || n + k >= count) continue;
          for (int c = 0; c < kHotNear; ++c) sum[c] += StressKernel::kTaps[k + reach] * line[n + k][c];
        }
      }
      for (long k = std::max(-hotReach, -n); k <= hotReach && n + k < count; ++k) sum[kHotNear] += line[n + k][kHotNear];
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
}

StressLattice::Reading StressLattice::read(const StressKernel::Place& at) const {
  const double wx[2] = {1.0 - at.x.fraction, at.x.fraction};
  const double wy[2] = {1.0 - at.y.fraction, at.y.fraction};
  Node sum{};
  const Node* row = &nodes_[index(at.x.node, at.y.node)];
  for (int q = 0; q < 2; ++q, row += countI_) {
    for (int p = 0; p < 2; ++p) {
      const double w = wx[p] * wy[q];
      for (int c = 0; c < kChannels; ++c) sum[c] += w * row[p][c];
    }
  }
  Reading reading;
  reading.weightedStress << sum[kXX], sum[kXY], sum[kXY], sum[kYY];
  reading.weight = sum[kWeight];
  reading.hot = sum[kHot] > 0.0;
  reading.hotNear = sum[kHotNear] > 0.0;
  return reading;
}

}  // namespace weft
