#pragma once
// A second tear table over part of a cloth: a seam weak across and strong along, a hem that tears
// only along its fold. Where the region's image is white the region's table gives a line's
// required strength, where it is black the cloth's own; in between, and for a line that crosses
// the region's edge, the two blend by the image's mean along the line (read as the strength map
// reads its image: tearing/strength_map.h, over `reach` either side of the vertex).
//
// As a factor on the cloth's own table, so it composes with the strength map and the search's
// bounds: a line at alpha through a point reads
//   (1 - w) + w * R_region(alpha) / R_own(alpha),   w = the region image's mean along the line,
// and every bound uses the smallest such factor near the point. R_region / R_own is a ratio of
// two functions linear between the tables' directions, so on each interval between neighbouring
// directions of either table it is monotonic and its smallest value lies at a direction of one
// of them.
//
// A crack tip in the region needs the own table's propagation factor times the blend (the region's
// own factor is not read: one cloth, one ratio of propagation to initiation).
#include <string>

#include "tearing/strength_map.h"
#include "tearing/tear_table.h"
#include "util/types.h"

namespace weft {

struct TearRegion {
  // The region's image as a strength map whose multiplier is the own table's share: black 1
  // (outside the region), white 0 (inside).
  TearStrengthMap outside;
  TearTable table;

  friend bool operator==(const TearRegion&, const TearRegion&) = default;
};

// The region's image read from `path` (as readStrengthImage reads a strength map), with the
// multipliers of a region (black 1, white 0) and `reach` m.
TearRegion makeTearRegion(const std::string& path, const std::string& file, const std::string& field,
                          const TearTable& table, double reach);

// The factor on the own table's required strength for the line (ray) through `point` at `angle`
// (rad, material space).
double regionFactorAlong(const TearRegion& region, const TearTable& own, double weftAngleRad, const Vec2& point,
                         double angle, bool ray);
// At most every factor regionFactorAlong can return at `point` (any angle, line or ray).
double lowestRegionFactorNear(const TearRegion& region, const TearTable& own, const Vec2& point);
// At most every factor anywhere on the cloth.
double lowestRegionFactor(const TearRegion& region, const TearTable& own);

}  // namespace weft
