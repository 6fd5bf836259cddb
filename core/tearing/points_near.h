#pragma once
// Whether any of a set of points lies within a given distance of a centre, exactly: the points
// bucketed by square cells as wide as that distance, so a question reads the 3 x 3 cells around
// its centre. For a few hundred points asked about many times (BoxCounts answers conservatively
// in constant time; this one answers exactly those it lets through).
#include <vector>

#include "util/types.h"

namespace weft {

class PointsNear {
 public:
  // The points, for questions about `distance` (> 0).
  void build(const std::vector<Vec2>& points, double distance);
  // Some point p has |p - centre| <= distance.
  bool anyWithin(const Vec2& centre) const;

 private:
  double distance_ = 0.0;
  Vec2 origin_ = Vec2::Zero();
  long countX_ = 0, countY_ = 0;
  std::vector<int> start_;    // per cell (x fastest), its first point in sorted_; one more at the end
  std::vector<Vec2> sorted_;  // the points, cell by cell
  long cellOf(double coordinate, double origin, long count) const;
};

}  // namespace weft
