#include "tearing/strength_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <stb_image.h>

#include "mesh/material_bounds.h"
#include "tearing/tear_region.h"
#include "util/input_error.h"

namespace weft {
namespace {

constexpr int kMostPixelsASide = 8192;

// The map's continuous pixel coordinates of a material point (pixel centres at integers).
void pixelCoordinates(const TearStrengthMap& map, const Vec2& point, double& u, double& v) {
  u = (point.x() - map.lo.x()) / (map.hi.x() - map.lo.x()) * map.width - 0.5;
  v = (map.hi.y() - point.y()) / (map.hi.y() - map.lo.y()) * map.height - 0.5;
}

int clampIndex(double x, int size) {
  if (!(x > 0.0)) return 0;  // NaN too
  return x >= size - 1 ? size - 1 : static_cast<int>(x);
}

// One pass of a separable min filter of half-width k along rows (step 1) or columns (step width).
void minFilter(std::vector<float>& values, int width, int height, int k, bool alongRows) {
  const std::vector<float> in = values;
  const int count = alongRows ? width : height;
  const int lines = alongRows ? height : width;
  for (int line = 0; line < lines; ++line) {
    for (int i = 0; i < count; ++i) {
      float m = std::numeric_limits<float>::infinity();
      for (int j = std::max(0, i - k); j <= std::min(count - 1, i + k); ++j) {
        m = std::min(m, alongRows ? in[line * width + j] : in[j * width + line]);
      }
      (alongRows ? values[line * width + i] : values[i * width + line]) = m;
    }
  }
}

}  // namespace

void readStrengthImage(const std::string& path, const std::string& file, const std::string& field,
                       TearStrengthMap& map) {
  int width = 0, height = 0, channels = 0;
  // 1 channel asked: stb_image turns colour into luminance and drops alpha.
  stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 1);
  if (pixels == nullptr) {
    const char* reason = stbi_failure_reason();
    throw InputError(file, field,
                     "cannot read the strength map \"" + path + "\" as a grayscale image (" +
                         (reason != nullptr ? reason : "unknown reason") + ")");
  }
  if (width <= 0 || height <= 0 || width > kMostPixelsASide || height > kMostPixelsASide) {
    stbi_image_free(pixels);
    throw InputError(file, field,
                     "the strength map \"" + path + "\" is " + std::to_string(width) + " x " + std::to_string(height) +
                         " pixels; it must have 1 to " + std::to_string(kMostPixelsASide) + " pixels a side");
  }
  map.width = width;
  map.height = height;
  map.grey.resize(static_cast<std::size_t>(width) * height);
  for (std::size_t i = 0; i < map.grey.size(); ++i) map.grey[i] = static_cast<float>(pixels[i] / 255.0);
  stbi_image_free(pixels);
}

void prepareStrengthMap(TearStrengthMap& map, const Vec2& lo, const Vec2& hi) {
  if (!map.explicitExtent) {
    map.lo = lo;
    map.hi = hi;
  }
  // A degenerate box (a cloth one vertex wide) still samples: give it a width.
  for (int d = 0; d < 2; ++d) {
    if (!(map.hi[d] > map.lo[d])) map.hi[d] = map.lo[d] + 1e-6;
  }
  map.multiplier.resize(map.grey.size());
  map.smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < map.grey.size(); ++i) {
    map.multiplier[i] = static_cast<float>(map.black + (map.white - map.black) * map.grey[i]);
    map.smallest = std::min(map.smallest, static_cast<double>(map.multiplier[i]));
  }
  // The samples of a line within `reach` of a point use pixels at most reach / pixel + 1.5 pixels
  // from the point's nearest pixel (1 for the bilinear stencil, 0.5 for the rounding).
  const double dx = (map.hi.x() - map.lo.x()) / map.width, dy = (map.hi.y() - map.lo.y()) / map.height;
  const int kx = static_cast<int>(std::ceil(std::min(1e6, map.reach / dx + 1.5)));
  const int ky = static_cast<int>(std::ceil(std::min(1e6, map.reach / dy + 1.5)));
  map.lowest = map.multiplier;
  minFilter(map.lowest, map.width, map.height, std::min(kx, map.width), true);
  minFilter(map.lowest, map.width, map.height, std::min(ky, map.height), false);
}

void prepareStrengthMapFor(TearStrengthMap& map, const ClothMesh& mesh) {
  const MaterialBounds bounds = materialBounds(mesh);
  prepareStrengthMap(map, bounds.lo, bounds.hi);
}

double strengthMultiplierAt(const TearStrengthMap& map, const Vec2& point) {
  double u = 0.0, v = 0.0;
  pixelCoordinates(map, point, u, v);
  u = std::clamp(u, 0.0, static_cast<double>(map.width - 1));
  v = std::clamp(v, 0.0, static_cast<double>(map.height - 1));
  const int i0 = clampIndex(std::floor(u), map.width), j0 = clampIndex(std::floor(v), map.height);
  const int i1 = std::min(i0 + 1, map.width - 1), j1 = std::min(j0 + 1, map.height - 1);
  const double fu = u - i0, fv = v - j0;
  auto at = [&](int i, int j) { return static_cast<double>(map.multiplier[static_cast<std::size_t>(j) * map.width + i]); };
  return (1.0 - fv) * ((1.0 - fu) * at(i0, j0) + fu * at(i1, j0)) + fv * ((1.0 - fu) * at(i0, j1) + fu * at(i1, j1));
}

double strengthMultiplierAlong(const TearStrengthMap& map, const Vec2& point, double angle, bool ray) {
  constexpr int kIntervals = 8;
  const Vec2 direction(std::cos(angle), std::sin(angle));
  const double from = ray ? 0.0 : -map.reach;
  const double step = (ray ? map.reach : 2.0 * map.reach) / kIntervals;
  double sum = 0.0;
  for (int k = 0; k <= kIntervals; ++k) {
    const double weight = k == 0 || k == kIntervals ? 0.5 : 1.0;
    sum += weight * strengthMultiplierAt(map, point + (from + k * step) * direction);
  }
  return sum / kIntervals;
}

double lowestStrengthMultiplierNear(const TearStrengthMap& map, const Vec2& point) {
  double u = 0.0, v = 0.0;
  pixelCoordinates(map, point, u, v);
  const int i = clampIndex(std::round(u), map.width), j = clampIndex(std::round(v), map.height);
  return map.lowest[static_cast<std::size_t>(j) * map.width + i];
}

StrengthScale::StrengthScale(double factorIn, const TearStrengthMap* mapIn, const Vec2& pointIn, bool rayIn)
    : StrengthScale(factorIn, mapIn, nullptr, nullptr, 0.0, pointIn, rayIn) {}

StrengthScale::StrengthScale(double factorIn, const TearStrengthMap* mapIn, const TearRegion* regionIn,
                             const TearTable* ownIn, double weftAngleRadIn, const Vec2& pointIn, bool rayIn)
    : factor(factorIn),
      map(mapIn),
      region(ownIn != nullptr ? regionIn : nullptr),
      own(ownIn),
      weftAngleRad(weftAngleRadIn),
      point(pointIn),
      ray(rayIn),
      lowestUnblended(factorIn) {
  // The margin covers the rounding of the bilinear means (float pixels summed in double).
  if (map != nullptr) lowestUnblended *= lowestStrengthMultiplierNear(*map, point);
  if (map != nullptr || region != nullptr) lowestUnblended *= 1.0 - 1e-9;
  if (region != nullptr) regionShare = 1.0 - std::clamp(lowestStrengthMultiplierNear(region->outside, point), 0.0, 1.0);
}

double StrengthScale::lowest() const {
  return region != nullptr ? lowestUnblended * lowestRegionFactorNear(*region, *own, point) : lowestUnblended;
}

double StrengthScale::lowestStrengthBetween(const TearTable& table, double fromDeg, double toDeg) const {
  const double ownWeakest = weakestStrengthBetween(table, fromDeg, toDeg);
  if (region == nullptr) return lowestUnblended * ownWeakest;
  // (1 - w) R_own + w R_region over the interval, w in [0, regionShare]: at least its value at
  // either end of w with each table at its own weakest (lowestUnblended's margin covers the
  // rounding here too).
  const double regionWeakest = weakestStrengthBetween(region->table, fromDeg, toDeg);
  const double blend = std::min(ownWeakest, (1.0 - regionShare) * ownWeakest + regionShare * regionWeakest);
  return lowestUnblended * blend;
}

double StrengthScale::painted(double angle) const {
  double scale = factor;
  if (map != nullptr) scale *= strengthMultiplierAlong(*map, point, angle, ray);
  if (region != nullptr) scale *= regionFactorAlong(*region, *own, weftAngleRad, point, angle, ray);
  return scale;
}

}  // namespace weft
