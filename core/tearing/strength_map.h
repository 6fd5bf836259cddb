#pragma once
// A painted tear strength: a multiplier on the tear table's required strength R(alpha) over the
// cloth's material space, read from a grayscale image (a perforation line, a worn knee, a
// reinforced hem).
//
// The image covers a rectangle of material space (its `extent`; by default the cloth's
// material-space bounding box): column 0 at the rectangle's smallest x, row 0 at its LARGEST y
// (the image as seen, with material y up). Pixel centres sit at the middle of their cells; between
// them the multiplier is bilinear, beyond the outer centres it is the edge pixel's (clamped).
// A grey level g in [0, 1] (8 bits / 255; colour images are turned to luminance, alpha ignored)
// gives the multiplier black + (white - black) * g.
//
// A line through a vertex reads the map's mean along itself over `reach` metres either side of
// the vertex (a ray, at a border or a crack tip: over `reach` ahead of it), so a line along a
// painted weak band is weaker than one across it, and the result does not depend on the mesh.
// Every bound of the search uses the smallest multiplier any such line can read
// (lowestNear: a lower bound of the map over the disc of radius `reach`), so no skip hides a weak
// painted line.
#include <string>
#include <vector>

#include "tearing/tear_table.h"
#include "util/types.h"

namespace weft {

struct ClothMesh;
struct TearRegion;
struct TearTable;

struct TearStrengthMap {
  std::string image;       // the file as named in the scene (for messages)
  int width = 0, height = 0;
  std::vector<float> grey;  // row-major, row 0 at the top (largest material y), in [0, 1]
  double black = 0.25;     // multiplier where the image is black (> 0)
  double white = 1.0;      // multiplier where the image is white (> 0)
  double reach = 0.04;     // m of material a line reads either side of its vertex
  bool explicitExtent = false;
  Vec2 lo = Vec2::Zero(), hi = Vec2::Ones();  // the image's rectangle in material space (m)
  // Filled by prepare():
  std::vector<float> multiplier;  // per pixel
  std::vector<float> lowest;      // per pixel: the smallest multiplier within reach (+1.5 px) of it
  double smallest = 1.0;          // the smallest multiplier anywhere

  friend bool operator==(const TearStrengthMap&, const TearStrengthMap&) = default;
};

// Reads `path` (PNG or anything stb_image decodes) as grey levels into `map` (image, width,
// height, grey). Throws InputError naming `file` and `field` when it cannot be read.
void readStrengthImage(const std::string& path, const std::string& file, const std::string& field,
                       TearStrengthMap& map);

// Fixes the extent (when not explicit: [lo, hi], the cloth's material bounding box) and computes
// the multipliers and their lower bounds.
void prepareStrengthMap(TearStrengthMap& map, const Vec2& lo, const Vec2& hi);

// prepareStrengthMap over the mesh's material bounding box (where a cloth's map lies by default).
void prepareStrengthMapFor(TearStrengthMap& map, const ClothMesh& mesh);

// The multiplier at a material point (bilinear).
double strengthMultiplierAt(const TearStrengthMap& map, const Vec2& point);
// The mean multiplier along the line through `point` at `angle` (rad, material space), over
// `reach` either side (a ray: over `reach` ahead), by the trapezoidal rule on 9 samples.
double strengthMultiplierAlong(const TearStrengthMap& map, const Vec2& point, double angle, bool ray);
// At most every multiplier strengthMultiplierAlong can return at `point`.
double lowestStrengthMultiplierNear(const TearStrengthMap& map, const Vec2& point);

// The strength scale of one vertex's lines: a factor (a crack tip's propagation factor, or 1) times,
// when the cloth has a map, the map's mean along each line, and when it has a tear region
// (tear_region.h), the region's blend of its table with the cloth's own. Implicit from a plain
// factor, so the search's callers without either pass 1.0 or the propagation factor as before.
struct StrengthScale {
  StrengthScale(double factorIn) : factor(factorIn), lowestUnblended(factorIn) {}  // NOLINT: implicit
  StrengthScale(double factorIn, const TearStrengthMap* mapIn, const Vec2& pointIn, bool rayIn);
  // With a region too (`own`: the cloth's table, whose strengths the scale multiplies).
  StrengthScale(double factorIn, const TearStrengthMap* mapIn, const TearRegion* regionIn, const TearTable* ownIn,
                double weftAngleRadIn, const Vec2& pointIn, bool rayIn);
  // The scale of the line (or ray) at `angle` (rad, material space).
  double of(double angle) const { return map == nullptr && region == nullptr ? factor : painted(angle); }
  // At most of(angle) for every angle (computed when asked: the search divides by
  // lowestStrengthBetween instead).
  double lowest() const;
  // At most of(angle) * requiredStrength(table, alpha) for every alpha in [fromDeg, toDeg] (a half
  // turn or more: every alpha), `table` the cloth's own. What the search's bounds divide by: with a
  // region it bounds the blend's two tables each by its own weakest in the interval, where
  // lowest() times the own table's weakest multiplies the smallest ratio of the two (at one
  // direction) by the own table's weakest (at another) — on a bias panel weak at 45 degrees in a
  // sheet weak at 90, a fifth of the real floor, and every fan of the sheet was then searched in
  // full (tear_region.h's blend, linear in the region's share w: its least value for w in
  // [0, w_max] is at an end).
  double lowestStrengthBetween(const TearTable& table, double fromDeg, double toDeg) const;
  double lowestStrength(const TearTable& table) const { return lowestStrengthBetween(table, 0.0, 180.0); }

  double factor = 1.0;
  const TearStrengthMap* map = nullptr;
  const TearRegion* region = nullptr;
  const TearTable* own = nullptr;
  double weftAngleRad = 0.0;
  Vec2 point = Vec2::Zero();  // the vertex (material space)
  bool ray = false;
  double lowestUnblended = 1.0;  // factor times the map's lowest multiplier near the point (margin included)
  double regionShare = 0.0;      // the region image's largest share of a line near the point (w_max)

 private:
  double painted(double angle) const;
};

}  // namespace weft
