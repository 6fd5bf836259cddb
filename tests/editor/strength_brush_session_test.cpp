// The tear strength brush wired into the editor (issue 23 point 3), without a window: a left drag
// in the viewport's paint mode paints the cloth under it, the running world takes the painted map
// when the stroke ends (and keeps it through other edits and a reset), the shared Undo takes the
// stroke back, Save writes the PNG beside the scene and points the scene at it, the autosave
// keeps unsaved paint, and a map handed to a running world makes it tear where it is painted.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "editor/autosave.h"
#include "editor/editor_session.h"
#include "editor/scene_edits.h"
#include "editor/shared_undo.h"
#include "editor/strength_painting.h"
#include "editor/tool_tag_editors.h"
#include "editor/viewport_interaction.h"
#include "mesh/material_bounds.h"
#include "sim/pick.h"
#include "sim/world.h"
#include "support/facing_sheet.h"
#include "support/painted_band.h"
#include "support/tear_scenes.h"
#include "support/temp_dir.h"
#include "tearing/strength_map.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The facing sheet (support/facing_sheet.h) and what the brush's tests ask of it.
struct FacingSheet : test::FacingSheet {
  // The material point under the pixel (x, y).
  Vec2 materialPointAt(double x, double y) {
    Vec3 origin, dir;
    ui::cameraRay(camera, x, y, kWidth, kHeight, origin, dir);
    const World& world = session->world();
    const auto hit = pickCloth(world, origin, dir);
    EXPECT_TRUE(hit.has_value());
    return hit ? materialPointOfHit(world, *hit) : Vec2::Zero();
  }

  // The multiplier the running world's cloth 0 (or `cloth`) has at material point `p` (1 without
  // a map).
  double worldMultiplierAt(const Vec2& p) { return multiplierAt(session->world(), p); }
  double clothMultiplierAt(int cloth, const Vec2& p) { return multiplierAt(session->world(), p, cloth); }

  static double multiplierAt(const World& world, const Vec2& p, int cloth = 0) {
    const std::optional<TearStrengthMap>& map = world.scene().cloths[static_cast<std::size_t>(cloth)].tearStrengthMap;
    if (!map) return 1.0;
    TearStrengthMap prepared = *map;
    const MaterialBounds bounds = materialBounds(world.cloth(cloth));
    prepareStrengthMap(prepared, bounds.lo, bounds.hi);
    return strengthMultiplierAt(prepared, p);
  }

  // A left drag in paint mode from (x0, y) to (x1, y).
  void stroke(ViewportInteraction& interaction, double x0, double x1, double y) {
    ui::MouseState mouse;
    mouse.x = x0;
    mouse.y = y;
    interaction.update(*session, camera, mouse, {}, kWidth, kHeight);
    mouse.left = true;
    EXPECT_TRUE(interaction.update(*session, camera, mouse, {}, kWidth, kHeight)) << "the press is the brush's";
    EXPECT_TRUE(interaction.painting());
    mouse.x = x1;
    interaction.update(*session, camera, mouse, {}, kWidth, kHeight);
    mouse.left = false;
    interaction.update(*session, camera, mouse, {}, kWidth, kHeight);
  }
};

// The brush's outline: over the cloth with a brush set, a circle round the cursor whose radius is
// the brush's on the sheet (the facing sheet's 1 m spans its width in pixels, so a 0.1 m brush
// spans a tenth of that); off the cloth, or without a brush, none; a bigger brush, a bigger circle.
TEST(StrengthPaintingInTheEditor, TheBrushOutlineIsDrawnAtTheBrushsSizeOnTheCloth) {
  FacingSheet s;
  ViewportInteraction interaction;
  ui::MouseState mouse;
  mouse.x = 0.5 * FacingSheet::kWidth;
  mouse.y = 0.5 * FacingSheet::kHeight;
  interaction.update(*s.session, s.camera, mouse, {}, FacingSheet::kWidth, FacingSheet::kHeight);
  EXPECT_FALSE(interaction.brushOutline()) << "no brush, no outline";

  StrengthBrush brush;
  brush.radius = 0.1;
  interaction.setPaintBrush(&brush);
  interaction.update(*s.session, s.camera, mouse, {}, FacingSheet::kWidth, FacingSheet::kHeight);
  ASSERT_TRUE(interaction.brushOutline());
  EXPECT_DOUBLE_EQ(interaction.brushOutline()->x, mouse.x);
  EXPECT_DOUBLE_EQ(interaction.brushOutline()->y, mouse.y);
  // The sheet's width on screen, from the material points under two pixels a known distance apart.
  const double pixels = 100.0;
  const double metres = (s.materialPointAt(mouse.x + pixels, mouse.y) - s.materialPointAt(mouse.x, mouse.y)).norm();
  ASSERT_GT(metres, 0.0);
  EXPECT_NEAR(interaction.brushOutline()->radiusPixels, 0.1 * pixels / metres, 0.05 * 0.1 * pixels / metres);

  brush.radius = 0.2;
  interaction.update(*s.session, s.camera, mouse, {}, FacingSheet::kWidth, FacingSheet::kHeight);
  ASSERT_TRUE(interaction.brushOutline());
  EXPECT_NEAR(interaction.brushOutline()->radiusPixels, 0.2 * pixels / metres, 0.05 * 0.2 * pixels / metres);

  mouse.x = 5.0;  // the corner of the view: no cloth there
  mouse.y = 5.0;
  interaction.update(*s.session, s.camera, mouse, {}, FacingSheet::kWidth, FacingSheet::kHeight);
  EXPECT_FALSE(interaction.brushOutline()) << "off the cloth";
}

TEST(StrengthPaintingInTheEditor, AStrokeInTheViewportReachesTheRunningWorldAndUndoTakesItBack) {
  FacingSheet s;
  const Vec2 painted = s.materialPointAt(400, 300), unpainted = s.materialPointAt(400, 360);
  ASSERT_GT((painted - unpainted).norm(), 0.15);
  ASSERT_DOUBLE_EQ(s.worldMultiplierAt(painted), 1.0);
  StrengthBrush brush;
  brush.radius = 0.05;
  brush.multiplier = 0.2;
  ViewportInteraction interaction;
  interaction.setPaintBrush(&brush);
  s.stroke(interaction, 380, 420, 300);
  EXPECT_FALSE(s.session->world().grabState()) << "painting does not grab the cloth";
  EXPECT_NEAR(s.worldMultiplierAt(painted), 0.2, 0.02);
  EXPECT_DOUBLE_EQ(s.worldMultiplierAt(unpainted), 1.0);
  EXPECT_TRUE(s.session->dirty());
  EXPECT_EQ(s.session->unsavedStrengthMaps(), std::vector<std::string>{s.session->scene().cloths[0].name});

  // Another edit, and a reset, keep the paint in the world.
  ASSERT_TRUE(s.session->edit(withMassDamping(s.session->json(), 0.3), "mass damping").accepted);
  EXPECT_NEAR(s.worldMultiplierAt(painted), 0.2, 0.02);
  s.session->reset();
  EXPECT_NEAR(s.worldMultiplierAt(painted), 0.2, 0.02);

  // Ctrl+Z: the damping first (the latest), then the stroke.
  ToolTagEditors tools;
  EXPECT_EQ(latestUndoLabel(*s.session, tools), "mass damping");
  undoLatest(*s.session, tools);
  EXPECT_NE(latestUndoLabel(*s.session, tools).find("paint tear strength"), std::string::npos);
  undoLatest(*s.session, tools);
  EXPECT_DOUBLE_EQ(s.worldMultiplierAt(painted), 1.0);
  EXPECT_FALSE(s.session->dirty());
  redoLatest(*s.session, tools);
  EXPECT_NEAR(s.worldMultiplierAt(painted), 0.2, 0.02);
}

TEST(StrengthPaintingInTheEditor, WithoutTheBrushTheSameDragGrabsTheCloth) {
  FacingSheet s;
  ViewportInteraction interaction;
  ui::MouseState mouse;
  mouse.x = 400;
  mouse.y = 300;
  mouse.left = true;
  interaction.update(*s.session, s.camera, mouse, {}, FacingSheet::kWidth, FacingSheet::kHeight);
  EXPECT_TRUE(s.session->world().grabState());
  EXPECT_FALSE(s.session->findStrengthPainting(0));
}

TEST(StrengthPaintingInTheEditor, SaveWritesThePngBesideTheSceneAndTheSceneLoadsThePaintedValues) {
  FacingSheet s;
  const Vec2 painted = s.materialPointAt(400, 300), unpainted = s.materialPointAt(400, 360);
  StrengthBrush brush;
  brush.radius = 0.05;
  brush.multiplier = 0.3;
  ViewportInteraction interaction;
  interaction.setPaintBrush(&brush);
  s.stroke(interaction, 390, 410, 300);
  s.session->save();
  EXPECT_FALSE(s.session->dirty());
  const fs::path png = s.file.parent_path() / "sheet.sheet.strength.png";
  ASSERT_EQ(s.session->scene().cloths[0].name, "sheet") << "the preset's cloth name, which names the file";
  EXPECT_TRUE(fs::exists(png));
  EXPECT_FALSE(fs::exists(png.string() + ".tmp"));
  std::ifstream in(s.file);
  const json saved = json::parse(in);
  EXPECT_EQ(saved["cloths"][0]["tear_strength_map"]["image"], "sheet.sheet.strength.png");

  EditorSession again(s.file);
  const double grey = 0.95 / 255.0;  // one grey level of a new map (black 0.05, white 1)
  EXPECT_NEAR(FacingSheet::multiplierAt(again.world(), painted), s.worldMultiplierAt(painted), grey);
  EXPECT_NEAR(FacingSheet::multiplierAt(again.world(), painted), 0.3, 0.02);
  EXPECT_DOUBLE_EQ(FacingSheet::multiplierAt(again.world(), unpainted), 1.0);
  EXPECT_FALSE(again.dirty());
}

TEST(StrengthPaintingInTheEditor, TheAutosaveKeepsUnsavedPaintAndRecoveringItSavesItBesideTheScene) {
  FacingSheet s;
  const Vec2 painted = s.materialPointAt(400, 300);
  StrengthBrush brush;
  brush.radius = 0.05;
  brush.multiplier = 0.25;
  ViewportInteraction interaction;
  interaction.setPaintBrush(&brush);
  s.stroke(interaction, 390, 410, 300);
  Autosave store(s.dir.path() / "autosave");
  s.session->autosave(store);
  const std::optional<Recovery> found = store.find(s.file);
  ASSERT_TRUE(found) << "unsaved paint alone is work to recover";
  const std::string image = found->document["cloths"][0]["tear_strength_map"]["image"];
  EXPECT_TRUE(fs::path(image).is_absolute());
  EXPECT_TRUE(fs::exists(image));

  EditorSession recovered(s.file, found->document);  // as after a crash
  EXPECT_NEAR(FacingSheet::multiplierAt(recovered.world(), painted), 0.25, 0.02);
  EXPECT_TRUE(recovered.dirty());
  recovered.save();
  std::ifstream in(s.file);
  const json saved = json::parse(in);
  EXPECT_EQ(saved["cloths"][0]["tear_strength_map"]["image"], "sheet.sheet.strength.png");
  EXPECT_TRUE(fs::exists(s.file.parent_path() / "sheet.sheet.strength.png"));
  store.discard(s.file);
  EXPECT_FALSE(fs::exists(image)) << "the autosave's PNG goes with it";
  EditorSession reopened(s.file);
  EXPECT_NEAR(FacingSheet::multiplierAt(reopened.world(), painted), 0.25, 0.02);
}

// Paintings follow their cloths, not their indices: removing the cloth before a painted one leaves
// the paint on its own cloth, now first, and undoing the removal puts it back where it was.
TEST(StrengthPaintingInTheEditor, APaintingStaysWithItsClothWhenAnEarlierClothIsRemoved) {
  FacingSheet s;
  ASSERT_TRUE(s.session->edit(withClothDuplicated(s.session->json(), 0, Vec3(0.0, 0.0, 0.3)), "duplicate cloth").accepted);
  s.session->reset();  // a new cloth needs a new world
  ASSERT_EQ(s.session->scene().cloths.size(), 2u);
  const std::string paintedName = s.session->scene().cloths[1].name;
  StrengthPainting& painting = s.session->strengthPainting(1);
  StrengthBrush brush;
  brush.radius = 0.1;
  brush.multiplier = 0.2;
  const Vec2 spot(0.5, 0.5);
  painting.beginStroke();
  painting.dab(spot, brush);
  painting.endStroke();
  s.session->strengthPaintingChanged(1);
  ASSERT_LT(s.clothMultiplierAt(1, spot), 0.3);

  ASSERT_TRUE(s.session->edit(withoutCloth(s.session->json(), 0), "remove cloth").accepted);
  s.session->reset();  // whatever the removal needs, the world is built from the scene now
  ASSERT_EQ(s.session->scene().cloths.size(), 1u);
  EXPECT_EQ(s.session->scene().cloths[0].name, paintedName);
  EXPECT_EQ(s.session->findStrengthPainting(0), &painting) << "the painting went with its cloth";
  EXPECT_EQ(s.session->findStrengthPainting(1), nullptr);
  EXPECT_LT(s.clothMultiplierAt(0, spot), 0.3) << "the painted cloth keeps its paint in the world";

  s.session->undo();
  s.session->reset();
  ASSERT_EQ(s.session->scene().cloths.size(), 2u);
  EXPECT_EQ(s.session->findStrengthPainting(1), &painting) << "back with its cloth";
  EXPECT_EQ(s.session->findStrengthPainting(0), nullptr);
  EXPECT_DOUBLE_EQ(s.clothMultiplierAt(0, spot), 1.0) << "the unpainted cloth is not painted";
  EXPECT_LT(s.clothMultiplierAt(1, spot), 0.3);
}

// The hand-over itself: a band painted into a world already running (World's setter, as the
// session's stroke does it) makes the pulled sheet tear inside the band (strength_painting_test's
// sheet; without a map its free corners first tear at 0.246 s, away from the band).
TEST(StrengthPaintingInTheEditor, ABandHandedToARunningWorldMakesItTearInsideTheBand) {
  const int resolution = 24;
  const double edge = 1.0 / (resolution - 1);
  const Scene scene = test::biaxialSheet(resolution, test::tearTable({1.0}, 450.0), 0.0, true);
  World world(scene);
  world.step();
  ASSERT_TRUE(world.tearLog().empty());
  world.setClothTearStrengthMap(0, test::paintedBand(materialBounds(world.cloth(0))));
  for (int s = 1; s < 56; ++s) world.step();
  test::expectTearsInsideBand(world.tearLog(), edge);
}

}  // namespace
}  // namespace weft::editor
