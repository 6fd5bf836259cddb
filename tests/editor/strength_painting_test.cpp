// The tear strength brush (editor/strength_painting.h): a stroke lowers the multiplier where it
// is painted and nowhere else, one stroke is one undo step, the saved PNG reads back as the same
// multipliers, the material point of a hit, and a band painted on a running pulled sheet makes it
// tear inside the band.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "editor/strength_painting.h"
#include "mesh/material_bounds.h"
#include "scene/scene_json.h"
#include "sim/world.h"
#include "support/painted_band.h"
#include "support/tear_scenes.h"
#include "support/temp_dir.h"
#include "tearing/strength_map.h"

namespace weft::editor {
namespace {

TearStrengthMap unitMap() { return newStrengthMap(Vec2(0.0, 0.0), Vec2(1.0, 1.0), "painted.png"); }

TEST(StrengthPainting, AStrokeLowersTheMultiplierWhereItIsPaintedAndNotTenCentimetresAway) {
  StrengthPainting painting(unitMap(), nullptr);
  const Vec2 at(0.4, 0.6), away(0.5, 0.6);
  ASSERT_DOUBLE_EQ(strengthMultiplierAt(painting.map(), at), 1.0);
  StrengthBrush brush;
  brush.radius = 0.03;
  brush.multiplier = 0.2;
  painting.beginStroke();
  EXPECT_TRUE(painting.dab(at, brush));
  EXPECT_TRUE(painting.dab(at, brush) == false);  // the same dab again builds nothing up
  painting.endStroke();
  EXPECT_NEAR(strengthMultiplierAt(painting.map(), at), 0.2, 0.02);
  EXPECT_DOUBLE_EQ(strengthMultiplierAt(painting.map(), away), 1.0);
  // The bounds the search skips by know of the weak spot (prepareStrengthMap ran).
  EXPECT_LT(painting.map().smallest, 0.25);
  EXPECT_TRUE(painting.dirty());
}

TEST(StrengthPainting, UndoRestoresTheExactGreyLevelsOfBeforeTheStrokeAndRedoTheStroke) {
  auto clock = std::make_shared<EditClock>();
  StrengthPainting painting(unitMap(), clock);
  StrengthBrush brush;
  brush.multiplier = 0.5;
  painting.beginStroke();
  painting.dab(Vec2(0.3, 0.3), brush);
  painting.endStroke();
  const std::vector<std::uint8_t> afterFirst = painting.grey();
  brush.multiplier = 0.1;
  painting.beginStroke();  // one stroke, several dabs: one undo step
  for (double x = 0.2; x <= 0.4; x += 0.01) painting.dab(Vec2(x, 0.32), brush);
  painting.endStroke();
  ASSERT_NE(painting.grey(), afterFirst);
  painting.undo();
  EXPECT_EQ(painting.grey(), afterFirst);
  painting.undo();
  EXPECT_FALSE(painting.dirty());
  EXPECT_DOUBLE_EQ(strengthMultiplierAt(painting.map(), Vec2(0.3, 0.3)), 1.0);
  painting.redo();
  EXPECT_EQ(painting.grey(), afterFirst);
  EXPECT_GT(clock->now, 0u);  // the steps are on the editor's shared clock
}

TEST(StrengthPainting, EraseGoesBackToTheMapAsPaintingBegan) {
  TearStrengthMap start = unitMap();
  for (int i = 0; i < start.width; ++i) start.grey[static_cast<std::size_t>(start.height / 2) * start.width + i] = 0.0f;
  prepareStrengthMap(start, start.lo, start.hi);
  StrengthPainting painting(start, nullptr);
  const Vec2 onLine(0.5, 0.5 - 0.5 / start.height), off(0.5, 0.3);
  const double lineBefore = strengthMultiplierAt(painting.map(), onLine);
  StrengthBrush brush;
  brush.multiplier = 0.3;
  painting.beginStroke();
  painting.dab(off, brush);
  painting.endStroke();
  ASSERT_LT(strengthMultiplierAt(painting.map(), off), 0.5);
  brush.erase = true;
  brush.radius = 0.3;  // over the painted spot and the loaded line alike
  painting.beginStroke();
  painting.dab(off, brush);
  painting.endStroke();
  EXPECT_DOUBLE_EQ(strengthMultiplierAt(painting.map(), off), 1.0);
  EXPECT_DOUBLE_EQ(strengthMultiplierAt(painting.map(), onLine), lineBefore);
}

TEST(StrengthPainting, TheSavedPngReadsBackAsTheSameMultipliers) {
  test::TempDir dir;
  StrengthPainting painting(unitMap(), nullptr);
  StrengthBrush brush;
  brush.multiplier = 0.37;
  brush.radius = 0.1;
  painting.beginStroke();
  painting.dab(Vec2(0.25, 0.75), brush);
  painting.endStroke();
  const std::filesystem::path file = dir.path() / "scene.sheet.strength.png";
  painting.savePng(file);
  EXPECT_FALSE(painting.dirty());
  ASSERT_TRUE(std::filesystem::exists(file));
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
  TearStrengthMap loaded;
  loaded.black = painting.map().black;
  loaded.white = painting.map().white;
  readStrengthImage(file.string(), "scene.json", "/cloths/0/tear_strength_map/image", loaded);
  prepareStrengthMap(loaded, Vec2(0.0, 0.0), Vec2(1.0, 1.0));
  ASSERT_EQ(loaded.width, painting.map().width);
  ASSERT_EQ(loaded.height, painting.map().height);
  double worst = 0.0;
  for (double x = 0.0; x <= 1.0; x += 0.013) {
    for (double y = 0.0; y <= 1.0; y += 0.017) {
      worst = std::max(worst, std::abs(strengthMultiplierAt(loaded, Vec2(x, y)) - strengthMultiplierAt(painting.map(), Vec2(x, y))));
    }
  }
  EXPECT_LE(worst, (loaded.white - loaded.black) / 255.0);
  EXPECT_LT(strengthMultiplierAt(loaded, Vec2(0.25, 0.75)), 0.45);
}

// Saving beside the scene: the PNG under the scene's name and the cloth's, the scene pointing at
// it, and the scene loaded again gives the painted multipliers (within one grey level).
TEST(StrengthPainting, ASceneSavedWithItsPaintedMapLoadsTheSameMultipliers) {
  test::TempDir dir;
  const nlohmann::json scene = nlohmann::json::parse(
      R"({"cloths": [{"name": "sheet", "mesh": {"grid": {}}, "material": "royal-target", "tear_table": {"strength": [1]}}]})");
  const std::filesystem::path sceneFile = dir.write("shirt.json", scene.dump());
  const Scene before = loadScene(sceneFile);
  World world(before);
  const MaterialBounds bounds = materialBounds(world.cloth(0));
  const Vec2 lo = bounds.lo, hi = bounds.hi;
  const std::filesystem::path png = paintedMapFile(sceneFile, "sheet", "");
  EXPECT_EQ(png, dir.path() / "shirt.sheet.strength.png");
  StrengthPainting painting(newStrengthMap(lo, hi, png.filename().string()), nullptr);
  StrengthBrush brush;
  brush.multiplier = 0.3;
  brush.radius = 0.08;
  const Vec2 centre = 0.5 * (lo + hi);
  painting.beginStroke();
  painting.dab(centre, brush);
  painting.endStroke();
  painting.savePng(png);
  dir.write("shirt.json", withStrengthMapImage(scene, 0, png.filename().string(), painting.map().black,
                                               painting.map().white).dump());
  const Scene after = loadScene(sceneFile);
  ASSERT_TRUE(after.cloths[0].tearStrengthMap.has_value());
  TearStrengthMap loaded = *after.cloths[0].tearStrengthMap;
  prepareStrengthMap(loaded, lo, hi);  // as buildCloth does
  double worst = 0.0;
  for (double x = lo.x(); x <= hi.x(); x += 0.011) {
    for (double y = lo.y(); y <= hi.y(); y += 0.013) {
      worst = std::max(worst, std::abs(strengthMultiplierAt(loaded, Vec2(x, y)) - strengthMultiplierAt(painting.map(), Vec2(x, y))));
    }
  }
  EXPECT_LE(worst, (loaded.white - loaded.black) / 255.0);
  EXPECT_NEAR(strengthMultiplierAt(loaded, centre), 0.3, 0.02);
  // Saved again, the cloth's own image beside the scene is the file written over.
  EXPECT_EQ(paintedMapFile(sceneFile, "sheet", "shirt.sheet.strength.png"), png);
  EXPECT_EQ(paintedMapFile(sceneFile, "sheet", "strength_maps/perforation.png"), png);
  EXPECT_EQ(paintedMapFile(sceneFile, "sheet", "perforation.png"), png);  // not beside the scene: assets/'s
}

TEST(StrengthPainting, AHitMapsToMaterialSpaceThroughItsTrianglesRestCorners) {
  const Scene scene = test::biaxialSheet(8, test::tearTable({1.0}, 450.0), 0.0, true);
  World world(scene);
  for (int s = 0; s < 5; ++s) world.step();  // deformed: world and material coordinates differ
  const ClothMesh& mesh = world.cloth(0);
  const int t = static_cast<int>(mesh.tris.size() / 3);
  const Triangle& tri = mesh.tris[static_cast<std::size_t>(t)];
  ClothHit hit;
  hit.cloth = 0;
  hit.triangle = t;
  hit.point = 0.2 * mesh.x[tri.v[0]] + 0.3 * mesh.x[tri.v[1]] + 0.5 * mesh.x[tri.v[2]];
  const Vec2 expected = 0.2 * tri.rest[0] + 0.3 * tri.rest[1] + 0.5 * tri.rest[2];
  EXPECT_LT((materialPointOfHit(world, hit) - expected).norm(), 1e-9);
}

// tests/tearing/strength_map_test.cpp's sheet: pulled equally in all directions, an isotropic
// table; a band painted with the brush at y = 0.3 makes it tear inside the band (without a map
// nothing tears by then: the free corners first tear at 0.246 s).
TEST(StrengthPainting, APaintedBandMakesAPulledSheetTearInsideIt) {
  const int resolution = 24;
  const double edge = 1.0 / (resolution - 1);
  Scene scene = test::biaxialSheet(resolution, test::tearTable({1.0}, 450.0), 0.0, true);
  scene.cloths[0].tearStrengthMap = test::paintedBand(materialBounds(World(scene).cloth(0)));
  World world(scene);
  for (int s = 0; s < 56; ++s) world.step();
  test::expectTearsInsideBand(world.tearLog(), edge);
}

}  // namespace
}  // namespace weft::editor
