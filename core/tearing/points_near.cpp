#include "tearing/points_near.h"

#include <algorithm>
#include <cmath>

namespace weft {

long PointsNear::cellOf(double coordinate, double origin, long count) const {
  const double cell = std::floor((coordinate - origin) / distance_);
  return static_cast<long>(std::clamp(cell, 0.0, static_cast<double>(count - 1)));
}

void PointsNear::build(const std::vector<Vec2>& points, double distance) {
  distance_ = distance;
  sorted_.clear();
  countX_ = countY_ = 0;
  if (points.empty() || !(distance > 0.0)) return;
  Vec2 low = points.front(), high = points.front();
  for (const Vec2& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  origin_ = low;
  countX_ = static_cast<long>((high.x() - low.x()) / distance) + 1;
  countY_ = static_cast<long>((high.y() - low.y()) / distance) + 1;
  start_.assign(static_cast<std::size_t>(countX_ * countY_ + 1), 0);
  std::vector<long> cellOfPoint(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    cellOfPoint[k] = cellOf(points[k].x(), origin_.x(), countX_) + countX_ * cellOf(points[k].y(), origin_.y(), countY_);
    ++start_[cellOfPoint[k] + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  sorted_.resize(points.size());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < points.size(); ++k) sorted_[fill[cellOfPoint[k]]++] = points[k];
}

bool PointsNear::anyWithin(const Vec2& centre) const {
  if (sorted_.empty()) return false;
  const double distance2 = distance_ * distance_;
  // Cells are as wide as the distance: every point within it lies in the centre's cell or a
  // neighbour (the clamped cells at the grid's edges hold the points beyond them too).
  const double fx = std::floor((centre.x() - origin_.x()) / distance_);
  const double fy = std::floor((centre.y() - origin_.y()) / distance_);
  if (fx < -1.0 || fy < -1.0 || fx > static_cast<double>(countX_) || fy > static_cast<double>(countY_)) return false;
  const long cx = static_cast<long>(fx), cy = static_cast<long>(fy);
  for (long y = std::max(0L, cy - 1); y <= std::min(countY_ - 1, cy + 1); ++y) {
    for (long x = std::max(0L, cx - 1); x <= std::min(countX_ - 1, cx + 1); ++x) {
      const long cell = x + countX_ * y;
      for (int k = start_[cell]; k < start_[cell + 1]; ++k) {
        if ((sorted_[k] - centre).squaredNorm() <= distance2) return true;
      }
    }
  }
  return false;
}

}  // namespace weft
