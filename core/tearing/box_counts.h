#pragma once
// Whether any of a set of points lies within a square box, in constant time per question: the
// points counted per cell of a square grid, the counts summed (a summed-area table), so a box of
// cells is four reads. Conservative: a box is widened to the whole cells it meets.
#include <cstddef>
#include <vector>

#include "util/types.h"

namespace weft {

class BoxCounts {
 public:
  // The grid over the points' bounding box, cells of side `cell` (larger where that would need
  // more than `maxCells` cells).
  void build(const std::vector<Vec2>& points, double cell, std::size_t maxCells);
  // Some point (perhaps) lies within `halfWidth` of `centre` along both axes; never false when one does.
  bool anyWithin(const Vec2& centre, double halfWidth) const;

 private:
  double cell_ = 1.0;
  Vec2 origin_ = Vec2::Zero();
  long countX_ = 0, countY_ = 0;
  std::vector<int> summed_;  // (countX_ + 1) x (countY_ + 1): points in the cells below and left
  long cellOf(double coordinate, double origin) const;
};

}  // namespace weft
