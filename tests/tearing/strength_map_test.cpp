// A painted tear strength (tearing/strength_map.h): the map's sampling, its bounds, where a pulled
// sheet tears with a weak painted band, that the map lives in material space (same torn path with
// the weft turned and the mesh refined), and the loader's errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include "mesh/grid.h"
#include "scene/scene_json.h"
#include "sim/world.h"
#include "support/tear_measures.h"
#include "support/tear_scenes.h"
#include "support/input_error_checks.h"
#include "support/painted_search.h"
#include "support/temp_dir.h"
#include "tearing/strength_map.h"
#include "tearing/tear_candidates.h"
#include "util/input_error.h"

namespace weft {
namespace {

using nlohmann::json;

// A map of `pixels` a side over the unit square: grey 0 (black) where |y - bandY| < halfWidth,
// else 1 (white).
TearStrengthMap bandMap(double bandY, double halfWidth, double black, int pixels = 200) {
  TearStrengthMap map;
  map.image = "band";
  map.width = map.height = pixels;
  map.black = black;
  map.white = 1.0;
  map.grey.assign(static_cast<std::size_t>(pixels) * pixels, 1.0f);
  for (int j = 0; j < pixels; ++j) {
    const double y = 1.0 - (j + 0.5) / pixels;  // row 0 at the top
    if (std::abs(y - bandY) < halfWidth) {
      for (int i = 0; i < pixels; ++i) map.grey[static_cast<std::size_t>(j) * pixels + i] = 0.0f;
    }
  }
  return map;
}

TEST(StrengthMap, RowZeroIsTheTopAndBetweenPixelCentresTheMultiplierIsBilinear) {
  TearStrengthMap map;
  map.width = 2;
  map.height = 2;
  map.grey = {0.0f, 1.0f,   // top row: black, white
              1.0f, 1.0f};  // bottom row
  map.black = 0.5;
  map.white = 2.0;
  prepareStrengthMap(map, Vec2(0, 0), Vec2(2, 2));  // pixel centres at x, y = 0.5 and 1.5
  EXPECT_DOUBLE_EQ(strengthMultiplierAt(map, Vec2(0.5, 1.5)), 0.5);  // top left: black
  EXPECT_DOUBLE_EQ(strengthMultiplierAt(map, Vec2(1.5, 1.5)), 2.0);
  EXPECT_DOUBLE_EQ(strengthMultiplierAt(map, Vec2(0.5, 0.5)), 2.0);
  EXPECT_DOUBLE_EQ(strengthMultiplierAt(map, Vec2(0.0, 2.0)), 0.5);  // clamped beyond the centres
  EXPECT_NEAR(strengthMultiplierAt(map, Vec2(1.0, 1.5)), 1.25, 1e-12);
  EXPECT_NEAR(strengthMultiplierAt(map, Vec2(1.0, 1.0)), 0.25 * 0.5 + 0.75 * 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(map.smallest, 0.5);
}

// The search's bounds use lowestStrengthMultiplierNear: it must be at most every line's mean.
TEST(StrengthMap, TheLowestMultiplierNearAPointBoundsEveryLineThroughIt) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  TearStrengthMap map;
  map.width = 37;
  map.height = 23;
  map.reach = 0.07;
  for (int k = 0; k < map.width * map.height; ++k) map.grey.push_back(static_cast<float>(unit(random)));
  prepareStrengthMap(map, Vec2(0, 0), Vec2(1.3, 0.8));
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec2 p(-0.2 + 1.7 * unit(random), -0.2 + 1.2 * unit(random));
    const double angle = 2.0 * std::numbers::pi * unit(random);
    const bool ray = trial % 2 == 0;
    const StrengthScale scale(0.7, &map, p, ray);
    ASSERT_LE(scale.lowest(), scale.of(angle)) << p.transpose() << " " << angle;
  }
}

// A line along a painted band reads it all; one across reads it only where it crosses.
TEST(StrengthMap, ALineAlongAWeakBandIsWeakerThanOneAcrossIt) {
  TearStrengthMap map = bandMap(0.5, 0.01, 0.2);
  prepareStrengthMap(map, Vec2(0, 0), Vec2(1, 1));
  const Vec2 onBand(0.5, 0.5);
  EXPECT_NEAR(strengthMultiplierAlong(map, onBand, 0.0, false), 0.2, 1e-6);
  EXPECT_GT(strengthMultiplierAlong(map, onBand, 0.5 * std::numbers::pi, false), 0.8);
  EXPECT_NEAR(strengthMultiplierAlong(map, Vec2(0.5, 0.8), 0.0, false), 1.0, 1e-6);
}

// Where a sheet tears, in material space: every torn segment's midpoint inside [margin, 1 - margin]^2.
std::vector<Vec2> tornMidpoints(const ClothMesh& mesh, double margin) {
  std::vector<Vec2> points;
  for (const auto& s : test::segmentsInside(test::tornSegments(mesh), Vec2(margin, margin), Vec2(1 - margin, 1 - margin))) {
    points.push_back(0.5 * (s.a + s.b));
  }
  return points;
}

struct BandRun {
  std::vector<Vec2> torn;     // midpoints of torn segments in the sheet's middle
  std::vector<Vec2> started;  // where each tear was (material space)
};

BandRun runBandSheet(int resolution, const TearTable& table, double weftDeg, const TearStrengthMap* map, int steps,
                     double margin = 0.1) {
  Scene scene = test::biaxialSheet(resolution, table, weftDeg, true);
  if (map != nullptr) scene.cloths[0].tearStrengthMap = *map;
  World world(scene);
  for (int s = 0; s < steps; ++s) world.step();
  EXPECT_TRUE(world.metrics().finite);
  BandRun run;
  run.torn = tornMidpoints(world.cloth(0), margin);
  for (const TearRecord& r : world.tearLog()) {
    run.started.push_back(r.restPosition);
    if (std::getenv("WEFT_STRENGTH_MAP_LOG") != nullptr) {
      std::printf("  t %.4f at (%.3f, %.3f) angle %.1f zeta %.1f required %.1f omega %.3f\n", r.time, r.restPosition.x(),
                  r.restPosition.y(), r.angleDeg, r.separation, r.required, r.ratio);
    }
  }
  return run;
}

// Every point of `a` within `tolerance` of some point of `b` (material space); the largest gap.
double farthestFrom(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double worst = 0.0;
  for (const Vec2& p : a) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec2& q : b) nearest = std::min(nearest, (p - q).norm());
    worst = std::max(worst, nearest);
  }
  return worst;
}

// A sheet pulled equally in all directions, isotropic table, a band a third as strong painted
// off the middle (y = 0.3 +- 2.5 cm): the sheet tears inside the band, along it.
TEST(StrengthMap, ASheetWithAWeakPaintedBandUnderUniformPullTearsInsideTheBand) {
  const int resolution = 24;
  const double edge = 1.0 / (resolution - 1);
  const TearTable table = test::tearTable({1.0}, 450.0);
  const TearStrengthMap map = bandMap(0.3, 0.025, 0.15);
  // 0.23 s: without the map nothing tears yet (the free corners first tear at 0.246 s).
  const BandRun run = runBandSheet(resolution, table, 0.0, &map, 56);
  ASSERT_FALSE(run.started.empty());
  ASSERT_FALSE(run.torn.empty());
  const Vec2 first = run.started.front();
  std::printf("first tear at (%.3f, %.3f); %zu tears, %zu torn segments in the middle\n", first.x(), first.y(),
              run.started.size(), run.torn.size());
  EXPECT_LT(std::abs(first.y() - 0.3), 0.025 + edge);
  int inside = 0;
  for (const Vec2& p : run.torn) inside += std::abs(p.y() - 0.3) < 0.025 + edge;
  const double share = static_cast<double>(inside) / run.torn.size();
  std::printf("share of torn segments within the band (+- one edge): %.2f\n", share);
  EXPECT_GE(share, 0.9);
}

// The map is read in material space: turning the weft (an anisotropic table) and refining the mesh
// leave the torn path where the painted line is, within one edge length of the coarse mesh. The
// paths are compared in [0.15, 0.85]^2, clear of the clamps.
TEST(StrengthMap, TheMapIsReadInMaterialSpaceWhateverTheWeftAndTheMesh) {
  // Weak along the warp only: 450 N/m, and the band a thirtieth of it (15 N/m along the warp, 45
  // across). The fabric outside the band does not tear within the window, so the paths compared
  // are the band's alone. (With 150 N/m and the band at a tenth, the same band strength, the free
  // corners tear along the warp too, and since the surgery no longer refuses lines
  // (restore_quality.h) those cracks reach the window on the 33^2 mesh: a path 0.51 m away.)
  const TearTable table = test::tearTable({1.0, 3.0, 3.0, 3.0}, 450.0);
  const TearStrengthMap map = bandMap(0.3, 0.015, 15.0 / 450.0);
  // 0.17 s: the band has torn through; later the clamps tear too.
  const BandRun coarse = runBandSheet(24, table, 0.0, &map, 40, 0.15);
  const BandRun turned = runBandSheet(24, table, 35.0, &map, 40, 0.15);
  const BandRun fine = runBandSheet(33, table, 35.0, &map, 40, 0.15);
  const double edge = 1.0 / 23.0;
  for (const BandRun* run : {&coarse, &turned, &fine}) ASSERT_FALSE(run->torn.empty());
  const double turnedGap = std::max(farthestFrom(turned.torn, coarse.torn), farthestFrom(coarse.torn, turned.torn));
  const double fineGap = std::max(farthestFrom(fine.torn, coarse.torn), farthestFrom(coarse.torn, fine.torn));
  std::printf("torn path: weft turned %.4f m, weft turned and mesh refined %.4f m from the weft-0 24^2 path "
              "(edge %.4f m); %zu / %zu / %zu segments\n",
              turnedGap, fineGap, edge, coarse.torn.size(), turned.torn.size(), fine.torn.size());
  EXPECT_LE(turnedGap, edge);
  EXPECT_LE(fineGap, edge);
}

// The search's skips use the smallest multiplier a vertex's lines can read: with the bound on or
// off the same tears come, in the same order (the painted band is weaker than the table's weakest
// strength, so a bound from the table alone would skip the band's vertices).
TEST(StrengthMap, TheSearchBoundsSkipNothingAPaintedLineWouldTear) {
  const TearTable table = test::tearTable({1.0, 3.0, 3.0, 3.0}, 150.0);
  const TearStrengthMap map = bandMap(0.3, 0.015, 0.1);
  std::vector<std::vector<TearRecord>> logs;
  for (bool skip : {true, false}) {
    Scene scene = test::biaxialSheet(24, table, 35.0, true);
    scene.cloths[0].tearStrengthMap = map;
    scene.tearing.skipByBound = skip;
    World world(scene);
    for (int s = 0; s < 40; ++s) world.step();
    logs.push_back(world.tearLog());
  }
  ASSERT_FALSE(logs[0].empty());
  ASSERT_EQ(logs[0].size(), logs[1].size());
  for (std::size_t k = 0; k < logs[0].size(); ++k) {
    EXPECT_EQ(logs[0][k].vertex, logs[1][k].vertex) << k;
    EXPECT_EQ(logs[0][k].angleDeg, logs[1][k].angleDeg) << k;
    EXPECT_EQ(logs[0][k].time, logs[1][k].time) << k;
  }
}

// The reference search (findTearCandidates, which tests compare the stage's choices with) reads
// the map as the stage does: under a uniform stress that tears nothing unpainted, every vertex it
// finds lies on the painted band with a line that stays in it, the same with and without the bounds
// that skip vertices; without the map it finds none.
TEST(StrengthMap, TheReferenceSearchReadsTheMapAsTheStageDoes) {
  GridSpec spec;
  spec.resolutionX = spec.resolutionY = 25;  // a row of vertices at y = 0.5, on the band
  const ClothMesh mesh = makeGrid(spec);
  TearStrengthMap map = bandMap(0.5, 0.015, 0.2);
  prepareStrengthMap(map, Vec2(0, 0), Vec2(1, 1));
  const TearTable table = test::tearTable({1.0}, 200.0);  // the unpainted sheet at omega 0.5
  const std::vector<Mat2> stress(mesh.tris.size(), 100.0 * Mat2::Identity());
  const test::PaintedSearch search = test::paintedSearch(mesh, stress, table, &map, nullptr);
  EXPECT_TRUE(search.unpaintedFindsNone);
  test::expectTheBoundSkipsNothing(search);
  ASSERT_FALSE(search.withBound.empty());
  for (const TearCandidate& c : search.withBound) {
    EXPECT_LT(std::abs(c.restPosition.y() - 0.5), 0.05) << "vertex " << c.vertex;
    // Along the band: under this isotropic stress every line that stays inside the band over the
    // map's reach is as weak (x0.2), so the line is one of those, at omega 100 / (200 x 0.2).
    EXPECT_NEAR(strengthMultiplierAlong(map, c.restPosition, c.angle, false), 0.2, 1e-3) << "vertex " << c.vertex;
    EXPECT_LT(std::abs(std::sin(c.angle)), std::sin(degToRad(15.0))) << "vertex " << c.vertex << " angle " << c.angle;
    EXPECT_NEAR(c.ratio, 2.5, 0.025);  // 1%: the sheet's side borders read their open fans
  }
}

// Bad input names the scene file and the field.
void writePng(const std::filesystem::path& file, int width, int height, int channels) {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * channels, 200);
  ASSERT_NE(stbi_write_png(file.c_str(), width, height, channels, pixels.data(), width * channels), 0);
}

json sheetWithMap(const json& map) {
  json scene = json::parse(R"({"cloths": [{"mesh": {"grid": {}}, "material": "royal-target",
                              "tear_table": {"strength": [1]}}]})");
  scene["cloths"][0]["tear_strength_map"] = map;
  return scene;
}

TEST(StrengthMapJson, AMapIsReadFromAPngBesideTheScene) {
  test::TempDir dir;
  writePng(dir.path() / "rgb.png", 4, 3, 3);  // colour: read as its luminance
  const Scene scene = loadScene(dir.write("s.json", sheetWithMap(json::parse(
      R"({"image": "rgb.png", "black": 0.2, "white": 3, "reach_m": 0.02,
          "extent": {"min": [0, 0], "max": [2, 1]}})")).dump()));
  ASSERT_TRUE(scene.cloths[0].tearStrengthMap.has_value());
  const TearStrengthMap& map = *scene.cloths[0].tearStrengthMap;
  EXPECT_EQ(map.width, 4);
  EXPECT_EQ(map.height, 3);
  EXPECT_NEAR(map.grey[0], 200.0 / 255.0, 1e-6);
  EXPECT_DOUBLE_EQ(map.black, 0.2);
  EXPECT_DOUBLE_EQ(map.white, 3.0);
  EXPECT_DOUBLE_EQ(map.reach, 0.02);
  EXPECT_TRUE(map.explicitExtent);
  EXPECT_EQ(map.hi, Vec2(2, 1));
}

TEST(StrengthMapJson, BadInputNamesTheFileAndTheField) {
  test::TempDir dir;
  writePng(dir.path() / "ok.png", 2, 2, 1);
  dir.write("not-an-image.png", "this is not a PNG");
  dir.write("empty.png", "");
  struct Case {
    json map;
    std::string field, mentions;
  };
  const std::vector<Case> cases{
      {json::parse(R"({"image": "missing.png"})"), "/cloths/0/tear_strength_map/image", "file not found"},
      {json::parse(R"({"image": "not-an-image.png"})"), "/cloths/0/tear_strength_map/image", "not-an-image.png"},
      {json::parse(R"({"image": "empty.png"})"), "/cloths/0/tear_strength_map/image", "grayscale"},
      {json::parse(R"({"image": "ok.png", "black": 0})"), "/cloths/0/tear_strength_map/black", "black"},
      {json::parse(R"({"image": "ok.png", "white": -1})"), "/cloths/0/tear_strength_map/white", "white"},
      {json::parse(R"({"image": "ok.png", "white": "NaN"})"), "/cloths/0/tear_strength_map/white", "white"},
      {json::parse(R"({"image": "ok.png", "reach_m": 0})"), "/cloths/0/tear_strength_map/reach_m", "reach_m"},
      {json::parse(R"({"image": "ok.png", "extent": {"min": [0, 0], "max": [0, 1]}})"),
       "/cloths/0/tear_strength_map/extent/max", "min"},
      {json::parse(R"({"image": "ok.png", "colour": 1})"), "/cloths/0/tear_strength_map", "colour"},
      {json::parse(R"({"black": 0.5})"), "/cloths/0/tear_strength_map", "image"},
      {json::parse(R"("ok.png")"), "/cloths/0/tear_strength_map", "object"},
  };
  for (const Case& c : cases) {
    test::expectLoadRefused(dir.write("bad-scene.json", sheetWithMap(c.map).dump()), "bad-scene.json", c.field, c.mentions,
                            c.map.dump());
  }
}

}  // namespace
}  // namespace weft
