#include "tearing/box_counts.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace weft {

long BoxCounts::cellOf(double coordinate, double origin) const {
  return static_cast<long>(std::floor((coordinate - origin) / cell_));
}

void BoxCounts::build(const std::vector<Vec2>& points, double cell, std::size_t maxCells) {
  summed_.clear();
  countX_ = countY_ = 0;
  if (points.empty()) return;
  Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const Vec2& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const Vec2 extent = high - low;
  cell_ = std::max({cell, std::sqrt(extent.x() * extent.y() / static_cast<double>(std::max<std::size_t>(1, maxCells))),
                    std::max(extent.x(), extent.y()) / static_cast<double>(std::max<std::size_t>(1, maxCells)), 1e-12});
  origin_ = low;
  countX_ = cellOf(high.x(), low.x()) + 1;
  countY_ = cellOf(high.y(), low.y()) + 1;
  const long stride = countX_ + 1;
  summed_.assign(static_cast<std::size_t>(stride * (countY_ + 1)), 0);
  for (const Vec2& p : points) {
    const long i = std::clamp(cellOf(p.x(), origin_.x()), 0L, countX_ - 1);
    const long j = std::clamp(cellOf(p.y(), origin_.y()), 0L, countY_ - 1);
    ++summed_[static_cast<std::size_t>((i + 1) + (j + 1) * stride)];
  }
  for (long j = 1; j <= countY_; ++j) {
    for (long i = 1; i <= countX_; ++i) {
      summed_[static_cast<std::size_t>(i + j * stride)] += summed_[static_cast<std::size_t>(i - 1 + j * stride)] +
                                                          summed_[static_cast<std::size_t>(i + (j - 1) * stride)] -
                                                          summed_[static_cast<std::size_t>(i - 1 + (j - 1) * stride)];
    }
  }
}

bool BoxCounts::anyWithin(const Vec2& centre, double halfWidth) const {
  if (summed_.empty()) return false;
  const long i0 = std::max(0L, cellOf(centre.x() - halfWidth, origin_.x()));
  const long j0 = std::max(0L, cellOf(centre.y() - halfWidth, origin_.y()));
  const long i1 = std::min(countX_ - 1, cellOf(centre.x() + halfWidth, origin_.x()));
  const long j1 = std::min(countY_ - 1, cellOf(centre.y() + halfWidth, origin_.y()));
  if (i0 > i1 || j0 > j1) return false;
  const long stride = countX_ + 1;
  const auto at = [&](long i, long j) { return summed_[static_cast<std::size_t>(i + j * stride)]; };
  return at(i1 + 1, j1 + 1) - at(i0, j1 + 1) - at(i1 + 1, j0) + at(i0, j0) > 0;
}

}  // namespace weft
