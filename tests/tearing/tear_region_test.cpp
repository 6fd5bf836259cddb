// A second tear table over part of a cloth (tearing/tear_region.h): the blend of the two tables by
// the region's image, its bounds, where a pulled sheet tears with a seam that is weak along its
// length, and the scene file's errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include "mesh/grid.h"
#include "scene/scene_json.h"
#include "sim/live_edit.h"
#include "sim/world.h"
#include "support/tear_scenes.h"
#include "support/input_error_checks.h"
#include "support/painted_search.h"
#include "support/temp_dir.h"
#include "tearing/tear_candidates.h"
#include "tearing/tear_region.h"
#include "util/input_error.h"

namespace weft {
namespace {

using nlohmann::json;

// A region over the unit square: the band |y - bandY| < halfWidth is white (the region's table),
// the rest black (the cloth's own).
TearRegion bandRegion(double bandY, double halfWidth, const TearTable& table, int pixels = 200) {
  TearRegion region;
  region.outside.image = "band";
  region.outside.black = 1.0;
  region.outside.white = 0.0;
  region.outside.width = region.outside.height = pixels;
  region.outside.grey.assign(static_cast<std::size_t>(pixels) * pixels, 0.0f);
  for (int j = 0; j < pixels; ++j) {
    const double y = 1.0 - (j + 0.5) / pixels;  // row 0 at the top
    if (std::abs(y - bandY) < halfWidth) {
      for (int i = 0; i < pixels; ++i) region.outside.grey[static_cast<std::size_t>(j) * pixels + i] = 1.0f;
    }
  }
  region.table = table;
  return region;
}

// A seam: as strong as the cloth across it, a third as strong along it (alpha = 90: a line along
// material x, the weft, when the weft angle is 0).
const TearTable kOwn = test::tearTable({1.0}, 1000.0);
const TearTable kSeam = test::tearTable({1.0, 1.0, 0.3, 1.0}, 1000.0);

TEST(TearRegion, TheFactorBlendsTheTwoTablesByTheImageAndItsBoundsHold) {
  TearRegion region = bandRegion(0.5, 0.05, kSeam);
  prepareStrengthMap(region.outside, Vec2(0, 0), Vec2(1, 1));
  // Inside the band, along it: the seam's table alone (0.3 of the own one).
  EXPECT_NEAR(regionFactorAlong(region, kOwn, 0.0, Vec2(0.5, 0.5), 0.0, false), 0.3, 1e-6);
  // Across it, the line reads the band over its middle and the own cloth beyond (reach 4 cm each
  // side, band 5 cm each side): all band, at alpha 0, where both tables give 1000.
  EXPECT_NEAR(regionFactorAlong(region, kOwn, 0.0, Vec2(0.5, 0.5), 0.5 * std::numbers::pi, false), 1.0, 1e-6);
  // Far from the band: the own table.
  EXPECT_EQ(regionFactorAlong(region, kOwn, 0.0, Vec2(0.5, 0.1), 0.0, false), 1.0);
  // At the band's edge, along it: a blend.
  const double edge = regionFactorAlong(region, kOwn, 0.0, Vec2(0.5, 0.55), 0.3, false);
  EXPECT_GT(edge, 0.3);
  EXPECT_LT(edge, 1.0);
  // The bounds hold for every line and ray through random points.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double anywhere = lowestRegionFactor(region, kOwn);
  EXPECT_NEAR(anywhere, 0.3, 1e-6);
  for (int k = 0; k < 2000; ++k) {
    const Vec2 p(unit(rng), unit(rng));
    const double near = lowestRegionFactorNear(region, kOwn, p);
    EXPECT_LE(anywhere, near + 1e-12);
    for (bool ray : {false, true}) {
      const double angle = 2.0 * std::numbers::pi * unit(rng);
      const double weft = 2.0 * std::numbers::pi * unit(rng);
      EXPECT_LE(near, regionFactorAlong(region, kOwn, weft, p, angle, ray) + 1e-12) << p.transpose() << " " << angle;
    }
  }
}

// The floor the search's bounds divide by (StrengthScale::lowestStrengthBetween): at most the
// strength of every line and ray at the point whose direction lies in the interval, with a map and
// a region, at any weft, for a crack tip's factor too; and, for a bias panel in a sheet weak
// elsewhere, well above lowest() times the own table's weakest (the old floor, which multiplied the
// two tables' smallest ratio at one direction by the own table's weakest at another).
TEST(TearRegion, TheSearchsStrengthFloorHoldsForEveryLineInItsIntervalAndIsTighter) {
  const TearTable own = test::tearTable({1.0, 1.0, 0.3, 1.0}, 1000.0);   // weak at 90
  const TearTable bias = test::tearTable({1.0, 0.2, 1.0, 0.2}, 1000.0);  // weak at 45 and 135
  TearRegion region = bandRegion(0.5, 0.05, bias);
  prepareStrengthMap(region.outside, Vec2(0, 0), Vec2(1, 1));
  TearStrengthMap map = bandRegion(0.3, 0.1, own).outside;  // a second band, as a map: 1 outside, 0.5 inside
  map.white = 0.5;
  prepareStrengthMap(map, Vec2(0, 0), Vec2(1, 1));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tighter = 0, pointsInBand = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec2 p(unit(rng), unit(rng));
    const double weft = 2.0 * std::numbers::pi * unit(rng);
    const double factor = k % 2 == 0 ? 1.0 : 0.5;
    for (bool ray : {false, true}) {
      const StrengthScale scale(factor, &map, &region, &own, weft, p, ray);
      const double from = 180.0 * unit(rng) - 20.0, width = 60.0 * unit(rng);
      const double floor = scale.lowestStrengthBetween(own, from, from + width);
      for (int j = 0; j <= 40; ++j) {
        const double alpha = from + width * j / 40.0;
        // The line whose angle from the warp is alpha (angleFromWarpDeg's inverse).
        const double angle = weft + (90.0 - alpha) * std::numbers::pi / 180.0;
        EXPECT_LE(floor, scale.of(angle) * requiredStrength(own, angleFromWarpDeg(angle, weft)) * (1.0 + 1e-12))
            << p.transpose() << " alpha " << alpha;
      }
      const double whole = scale.lowestStrength(own);
      EXPECT_GE(whole, scale.lowest() * weakestStrength(own) * (1.0 - 1e-12));
      if (whole > 1.5 * scale.lowest() * weakestStrength(own)) ++tighter;
      pointsInBand += std::abs(p.y() - 0.5) < 0.05;
    }
  }
  EXPECT_GT(pointsInBand, 0);
  EXPECT_GT(tighter, 50);  // near the band the old floor was 0.2 / 1.0 x 300 = 60 N/m; the blend's is 200
}

// Under a uniform stress the cloth's own table holds everywhere (omega 0.6); in the seam the lines
// along it need 0.3 of that: the reference search finds only vertices in the seam, each with a line
// along it at omega 2, the same with and without the bounds that skip vertices.
TEST(TearRegion, UnderUniformStressOnlyTheSeamTearsAndAlongIt) {
  GridSpec spec;
  spec.resolutionX = spec.resolutionY = 25;  // a row of vertices at y = 0.5, in the seam
  const ClothMesh mesh = makeGrid(spec);
  TearRegion region = bandRegion(0.5, 0.03, kSeam);
  prepareStrengthMap(region.outside, Vec2(0, 0), Vec2(1, 1));
  const std::vector<Mat2> stress(mesh.tris.size(), 600.0 * Mat2::Identity());
  const test::PaintedSearch search = test::paintedSearch(mesh, stress, kOwn, nullptr, &region);
  EXPECT_TRUE(search.unpaintedFindsNone);
  test::expectTheBoundSkipsNothing(search);
  ASSERT_FALSE(search.withBound.empty());
  for (const TearCandidate& c : search.withBound) {
    EXPECT_LT(std::abs(c.restPosition.y() - 0.5), 0.03) << "vertex " << c.vertex;
    EXPECT_LT(std::abs(std::sin(c.angle)), std::sin(5.0 * std::numbers::pi / 180.0)) << "vertex " << c.vertex;
    // 600 / 300 inside; a border vertex's ray into the sheet separates less than a line does
    // (its fan is half a turn), so there only above 1.
    if (c.ray) {
      EXPECT_GT(c.ratio, 1.0);
    } else {
      EXPECT_NEAR(c.ratio, 2.0, 1e-6) << "vertex " << c.vertex;
    }
  }
}

// A sheet pulled equally in all directions, the cloth's own table isotropic, a seam weak along
// its length across the middle: the sheet tears in the seam, along it, and the stage's bounds skip
// none of its lines (the same tears with the bound off).
TEST(TearRegion, APulledSheetTearsAlongItsSeam) {
  const TearTable own = test::tearTable({1.0}, 450.0);
  const TearTable seam = test::tearTable({1.0, 1.0, 0.15, 1.0}, 450.0);
  std::vector<std::vector<TearRecord>> logs;
  for (bool skip : {true, false}) {
    Scene scene = test::biaxialSheet(24, own, 0.0, true);
    scene.cloths[0].tearRegion = bandRegion(0.3, 0.03, seam);
    scene.tearing.skipByBound = skip;
    World world(scene);
    for (int s = 0; s < 56; ++s) world.step();
    EXPECT_TRUE(world.metrics().finite);
    logs.push_back(world.tearLog());
  }
  ASSERT_FALSE(logs[0].empty());
  ASSERT_EQ(logs[0].size(), logs[1].size());
  int inSeamAlongIt = 0;
  for (std::size_t k = 0; k < logs[0].size(); ++k) {
    const TearRecord& r = logs[0][k];
    EXPECT_EQ(r.vertex, logs[1][k].vertex) << k;
    EXPECT_EQ(r.angleDeg, logs[1][k].angleDeg) << k;
    const double offAxis = std::abs(std::remainder(r.angleDeg, 180.0));
    inSeamAlongIt += std::abs(r.restPosition.y() - 0.3) < 0.03 + 1.0 / 23 && offAxis < 10.0;
  }
  std::printf("%zu tears, %d in the seam and along it; first at (%.3f, %.3f), %.1f deg\n", logs[0].size(), inSeamAlongIt,
              logs[0][0].restPosition.x(), logs[0][0].restPosition.y(), logs[0][0].angleDeg);
  EXPECT_GE(inSeamAlongIt, static_cast<int>(0.9 * logs[0].size()));
  // Without the seam, nothing tears by then (the free corners first tear at 0.246 s).
  World plain(test::biaxialSheet(24, own, 0.0, true));
  for (int s = 0; s < 56; ++s) plain.step();
  EXPECT_TRUE(plain.tearLog().empty());
}

// A region added to a running world is a live edit (no reset): the sheet then tears along its seam.
TEST(TearRegion, AddingARegionIsALiveEdit) {
  const TearTable own = test::tearTable({1.0}, 450.0);
  const TearTable seam = test::tearTable({1.0, 1.0, 0.15, 1.0}, 450.0);
  const Scene plain = test::biaxialSheet(24, own, 0.0, true);
  World world(plain);
  for (int s = 0; s < 10; ++s) world.step();
  Scene edited = plain;
  edited.cloths[0].tearRegion = bandRegion(0.3, 0.03, seam);
  ASSERT_FALSE(needsReset(world.scene(), edited));
  applyLiveEdits(world, edited);
  for (int s = 10; s < 56; ++s) world.step();
  ASSERT_FALSE(world.tearLog().empty());
  EXPECT_LT(std::abs(world.tearLog().front().restPosition.y() - 0.3), 0.03 + 1.0 / 23);
}

void writeBandPng(const std::filesystem::path& file) {
  const int w = 8, h = 8;
  std::vector<unsigned char> pixels(w * h, 0);
  for (int i = 0; i < w; ++i) pixels[3 * w + i] = pixels[4 * w + i] = 255;
  ASSERT_NE(stbi_write_png(file.c_str(), w, h, 1, pixels.data(), w), 0);
}

json sheetWithRegion(const json& region, bool ownTable = true) {
  json scene = json::parse(R"({"cloths": [{"mesh": {"grid": {}}, "material": "royal-target"}]})");
  if (ownTable) scene["cloths"][0]["tear_table"] = json::parse(R"({"strength": [1]})");
  scene["cloths"][0]["tear_region"] = region;
  return scene;
}

TEST(TearRegionJson, ARegionIsReadFromAPngBesideTheScene) {
  test::TempDir dir;
  writeBandPng(dir.path() / "seam.png");
  const Scene scene = loadScene(dir.write("s.json", sheetWithRegion(json::parse(
      R"({"image": "seam.png", "tear_table": {"strength": [3, 3, 1, 3], "unit_n_per_m": 100}, "reach_m": 0.02,
          "extent": {"min": [0, 0], "max": [2, 1]}})")).dump()));
  ASSERT_TRUE(scene.cloths[0].tearRegion.has_value());
  const TearRegion& region = *scene.cloths[0].tearRegion;
  EXPECT_EQ(region.outside.image, "seam.png");
  EXPECT_EQ(region.outside.width, 8);
  EXPECT_EQ(region.outside.grey[3 * 8], 1.0f);
  EXPECT_EQ(region.outside.grey[0], 0.0f);
  EXPECT_DOUBLE_EQ(region.outside.reach, 0.02);
  EXPECT_TRUE(region.outside.explicitExtent);
  EXPECT_DOUBLE_EQ(region.table.unitNPerM, 100.0);
  EXPECT_DOUBLE_EQ(requiredStrength(region.table, 90.0), 100.0);
}

TEST(TearRegionJson, BadInputNamesTheFileAndTheField) {
  test::TempDir dir;
  writeBandPng(dir.path() / "ok.png");
  dir.write("not-an-image.png", "this is not a PNG");
  struct Case {
    json region;
    bool ownTable;
    std::string field, mentions;
  };
  const std::vector<Case> cases{
      {json::parse(R"({"image": "missing.png", "tear_table": {"strength": [1]}})"), true, "/cloths/0/tear_region/image",
       "file not found"},
      {json::parse(R"({"image": "not-an-image.png", "tear_table": {"strength": [1]}})"), true,
       "/cloths/0/tear_region/image", "not-an-image.png"},
      {json::parse(R"({"image": "ok.png"})"), true, "/cloths/0/tear_region", "tear_table"},
      {json::parse(R"({"tear_table": {"strength": [1]}})"), true, "/cloths/0/tear_region", "image"},
      {json::parse(R"({"image": "ok.png", "tear_table": "no-such-table"})"), true, "/cloths/0/tear_region/tear_table",
       "no-such-table"},
      {json::parse(R"({"image": "ok.png", "tear_table": {"strength": [0]}})"), true, "/cloths/0/tear_region/tear_table",
       "strength"},
      {json::parse(R"({"image": "ok.png", "tear_table": 3})"), true, "/cloths/0/tear_region/tear_table", "preset name"},
      {json::parse(R"({"image": "ok.png", "tear_table": {"strength": [1]}, "reach_m": -1})"), true,
       "/cloths/0/tear_region/reach_m", "reach_m"},
      {json::parse(R"({"image": "ok.png", "tear_table": {"strength": [1]}, "extent": {"min": [0, 0], "max": [1, 0]}})"),
       true, "/cloths/0/tear_region/extent/max", "min"},
      {json::parse(R"({"image": "ok.png", "tear_table": {"strength": [1]}, "colour": 1})"), true, "/cloths/0/tear_region",
       "colour"},
      {json::parse(R"("ok.png")"), true, "/cloths/0/tear_region", "object"},
      {json::parse(R"({"image": "ok.png", "tear_table": {"strength": [1]}})"), false, "/cloths/0/tear_region",
       "own tear table"},
  };
  for (const Case& c : cases) {
    test::expectLoadRefused(dir.write("bad-scene.json", sheetWithRegion(c.region, c.ownTable).dump()), "bad-scene.json", c.field, c.mentions,
                            c.region.dump());
  }
}

}  // namespace
}  // namespace weft
