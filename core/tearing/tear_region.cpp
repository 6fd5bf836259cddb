#include "tearing/tear_region.h"

#include <algorithm>
#include <cmath>
#include <limits>


namespace weft {
namespace {

// The smallest R_region / R_own over all directions: at the directions of both tables (see the
// header).
double lowestRatio(const TearRegion& region, const TearTable& own) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const TearTable* table : {&region.table, &own}) {
    for (int k = 0; k < static_cast<int>(table->strength.size()); ++k) {
      const double alpha = tableDirectionDeg(*table, k);
      lowest = std::min(lowest, requiredStrength(region.table, alpha) / requiredStrength(own, alpha));
    }
  }
  return lowest;
}

// The blend's smallest value when the own share is at least `outsideLow`: the blend
// outside + (1 - outside) * ratio grows with `outside` when ratio < 1.
double lowestBlend(double outsideLow, double ratioLow) {
  if (ratioLow >= 1.0) return 1.0;
  const double outside = std::clamp(outsideLow, 0.0, 1.0);
  return outside + (1.0 - outside) * ratioLow;
}

}  // namespace

TearRegion makeTearRegion(const std::string& path, const std::string& file, const std::string& field,
                          const TearTable& table, double reach) {
  TearRegion region;
  region.outside.image = path;
  region.outside.black = 1.0;
  region.outside.white = 0.0;
  region.outside.reach = reach;
  readStrengthImage(path, file, field, region.outside);
  region.table = table;
  return region;
}

double regionFactorAlong(const TearRegion& region, const TearTable& own, double weftAngleRad, const Vec2& point,
                         double angle, bool ray) {
  const double outside = strengthMultiplierAlong(region.outside, point, angle, ray);
  if (outside >= 1.0) return 1.0;
  const double alpha = angleFromWarpDeg(angle, weftAngleRad);
  return outside + (1.0 - outside) * requiredStrength(region.table, alpha) / requiredStrength(own, alpha);
}

double lowestRegionFactorNear(const TearRegion& region, const TearTable& own, const Vec2& point) {
  return lowestBlend(lowestStrengthMultiplierNear(region.outside, point), lowestRatio(region, own));
}

double lowestRegionFactor(const TearRegion& region, const TearTable& own) {
  return lowestBlend(region.outside.smallest, lowestRatio(region, own));
}

}  // namespace weft
