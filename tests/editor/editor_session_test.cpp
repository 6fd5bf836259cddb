// The editor's model without a window: the pure scene edits the panels make, and the session that
// validates them, applies them live or asks for a reset, undoes them, plays and saves.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "editor/editor_session.h"
#include "editor/material_presets.h"
#include "editor/scene_edits.h"
#include "scene/scene_json.h"
#include "support/temp_dir.h"
#include "tearing/tear_table.h"
#include "util/input_error.h"

namespace weft::editor {
namespace {

// A displayed frame as long as the hanging sheet's output frame (1/30 s).
constexpr double kOutputFrame = 1.0 / 30.0;

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kScenes = fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes";

json readJson(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A copy of a preset scene in a temporary scenes/ folder (presets still resolve from the source
// tree), small enough to step quickly.
fs::path smallScene(const test::TempDir& dir, const std::string& preset, int resolution = 8) {
  json scene = readJson(kScenes / (preset + ".json"));
  if (scene["cloths"][0]["mesh"].contains("grid")) {
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({resolution, resolution});
  }
  return dir.write("scenes/" + preset + ".json", scene.dump(2));
}

Scene parsed(const json& j, const fs::path& file) { return parseScene(j, file, defaultSearchPaths(file)); }

TEST(SceneEdits, EditingATearEntryOfAPresetTableInlinesItAndChangesOnlyThatEntry) {
  test::TempDir dir;
  const fs::path file = smallScene(dir, "ball-into-sheet-table4.1-cloth2");
  const json original = readJson(file);
  const Scene before = parsed(original, file);
  ASSERT_TRUE(before.cloths[0].material.tearTable);
  const TearTable old = *before.cloths[0].material.tearTable;

  const json edited = withTearStrength(original, before, 0, 2, 20.0);
  const Scene after = parsed(edited, file);
  const TearTable& table = *after.cloths[0].material.tearTable;
  ASSERT_EQ(table.strength.size(), old.strength.size());
  for (std::size_t k = 0; k < table.strength.size(); ++k) {
    EXPECT_DOUBLE_EQ(table.strength[k], k == 2 ? 20.0 : old.strength[k]) << k;
  }
  EXPECT_DOUBLE_EQ(table.unitNPerM, old.unitNPerM);
  // ℜ(α) at the edited direction (90° from the warp) follows the entry.
  EXPECT_DOUBLE_EQ(requiredStrength(table, 90.0), 20.0 * old.unitNPerM);
  EXPECT_NE(requiredStrength(old, 90.0), requiredStrength(table, 90.0));
  EXPECT_TRUE(edited["cloths"][0]["tear_table"].is_object()) << "the preset is written inline, the preset file untouched";
  EXPECT_FALSE(edited["cloths"][0]["tear_table"].contains("name")) << "an edited table no longer claims the preset's name";
}

TEST(SceneEdits, RemovingTheTearTableStopsTearingAndAPresetBringsItBack) {
  test::TempDir dir;
  const fs::path file = smallScene(dir, "ball-into-sheet-table4.1-cloth2");
  const json original = readJson(file);
  const Scene before = parsed(original, file);
  ASSERT_TRUE(before.cloths[0].material.tearTable);
  const json removed = withoutTearTable(original, before, 0);
  const Scene none = parsed(removed, file);
  EXPECT_FALSE(none.cloths[0].material.tearTable);
  EXPECT_DOUBLE_EQ(none.cloths[0].material.areaDensity, before.cloths[0].material.areaDensity) << "the rest stays";
  const Scene back = parsed(withTearTablePreset(removed, 0, "karaoz2015-table4.1-cloth3"), file);
  ASSERT_TRUE(back.cloths[0].material.tearTable);
  EXPECT_EQ(back.cloths[0].material.tearTable->name, "karaoz2015-table4.1-cloth3");
}

TEST(SceneEdits, ResamplingTheTableKeepsItsCurve) {
  test::TempDir dir;
  const fs::path file = smallScene(dir, "ball-into-sheet-table4.1-cloth2");
  const json original = readJson(file);
  const Scene before = parsed(original, file);
  const TearTable old = *before.cloths[0].material.tearTable;
  const Scene eight = parsed(withTearDirections(original, before, 0, 8), file);
  const TearTable& table = *eight.cloths[0].material.tearTable;
  ASSERT_EQ(table.strength.size(), 8u);
  for (double alpha = 0.0; alpha < 180.0; alpha += 22.5) {
    EXPECT_NEAR(requiredStrength(table, alpha), requiredStrength(old, alpha), 1e-9) << alpha;
  }
  const Scene two = parsed(withTearDirections(original, before, 0, 2), file);
  EXPECT_EQ(two.cloths[0].material.tearTable->strength.size(), 2u);
}

TEST(SceneEdits, MaterialEditsInlineThePresetAndChangeTheNamedValue) {
  test::TempDir dir;
  const fs::path file = smallScene(dir, "hanging-sheet");
  const json original = readJson(file);
  const Scene before = parsed(original, file);
  const Material& m0 = before.cloths[0].material;
  ASSERT_EQ(m0.elasticity.model, ElasticitySettings::Model::Measured);

  const Scene denser = parsed(withAreaDensity(original, before, 0, 0.5), file);
  EXPECT_DOUBLE_EQ(denser.cloths[0].material.areaDensity, 0.5);
  EXPECT_EQ(denser.cloths[0].material.elasticity, m0.elasticity) << "nothing else changes";

  const Scene c33 = parsed(withElasticityCoefficient(original, before, 0, 2, 3, 99.0), file);
  EXPECT_DOUBLE_EQ(c33.cloths[0].material.elasticity.measured.directions[2][3], 99.0);
  EXPECT_DOUBLE_EQ(c33.cloths[0].material.elasticity.measured.directions[2][0], m0.elasticity.measured.directions[2][0]);

  const Scene bent = parsed(withBendingStiffness(original, before, 0, 1, 2, 3e-4), file);
  EXPECT_DOUBLE_EQ(bent.cloths[0].material.bending.measured[1][2], 3e-4);
  EXPECT_DOUBLE_EQ(bent.cloths[0].material.bending.measured[0][0], m0.bending.measured[0][0]);

  const Scene iso = parsed(withIsotropicElasticity(original, before, 0, 3000.0, 0.25), file);
  EXPECT_EQ(iso.cloths[0].material.elasticity.model, ElasticitySettings::Model::Isotropic);
  EXPECT_DOUBLE_EQ(iso.cloths[0].material.elasticity.youngModulus, 3000.0);
  EXPECT_DOUBLE_EQ(iso.cloths[0].material.elasticity.poissonRatio, 0.25);
}

TEST(EditorSession, AnInvalidEditIsRefusedWithTheReadersMessageAndChangesNothing) {
  test::TempDir dir;
  EditorSession session(smallScene(dir, "hanging-sheet"));
  const json before = session.json();
  json bad = before;
  bad["solver"]["dt"] = -1.0;
  const EditResult result = session.edit(bad, "time step");
  EXPECT_FALSE(result.accepted);
  EXPECT_NE(result.message.find("/solver/dt"), std::string::npos) << result.message;
  EXPECT_EQ(session.json(), before);
  EXPECT_FALSE(session.dirty());
  EXPECT_FALSE(session.document().history().canUndo());
}

TEST(EditorSession, AWeftEditAppliesLiveAndUndoRestoresIt) {
  test::TempDir dir;
  EditorSession session(smallScene(dir, "hanging-sheet"));
  session.advanceFrame(kOutputFrame);
  const long long steps = session.world().stepCount();
  ASSERT_GT(steps, 0);
  ASSERT_TRUE(session.edit(withWeftAngle(session.json(), 0, 30.0), "weft angle").accepted);
  EXPECT_FALSE(session.resetPending());
  EXPECT_EQ(session.world().stepCount(), steps) << "applied to the running world, no restart";
  EXPECT_DOUBLE_EQ(session.world().scene().cloths[0].weftAngleDeg, 30.0);
  EXPECT_TRUE(session.dirty());
  session.undo();
  EXPECT_DOUBLE_EQ(session.scene().cloths[0].weftAngleDeg, 0.0);
  EXPECT_DOUBLE_EQ(session.world().scene().cloths[0].weftAngleDeg, 0.0);
  EXPECT_FALSE(session.dirty());
  session.redo();
  EXPECT_DOUBLE_EQ(session.world().scene().cloths[0].weftAngleDeg, 30.0);
}

// The CG's preconditioner is picked in the Solver panel like the other solver settings: amg by
// default, the lagged Cholesky (the accuracy and speed reference of docs/solver.md) one edit away,
// applied to the running world and undone.
TEST(EditorSession, APreconditionerEditAppliesLiveAndUndoRestoresTheDefault) {
  test::TempDir dir;
  EditorSession session(smallScene(dir, "hanging-sheet"));
  ASSERT_EQ(session.scene().solver.linearPreconditioner, PreconditionerKind::Amg);
  session.advanceFrame(kOutputFrame);
  ASSERT_TRUE(session.edit(withPreconditioner(session.json(), "lagged_cholesky"), "preconditioner").accepted);
  EXPECT_EQ(session.world().scene().solver.linearPreconditioner, PreconditionerKind::LaggedCholesky);
  const long long steps = session.world().stepCount();
  session.advanceFrame(kOutputFrame);
  EXPECT_GT(session.world().stepCount(), steps);
  EXPECT_TRUE(session.world().metrics().finite);
  EXPECT_FALSE(session.edit(withPreconditioner(session.json(), "multigrid"), "preconditioner").accepted);
  session.undo();
  EXPECT_EQ(session.world().scene().solver.linearPreconditioner, PreconditionerKind::Amg);
}

TEST(EditorSession, TheWorldStepsWithAtMostAllButOneCoreAndTheFileKeepsItsThreads) {
  // editorSolverThreads: the drawing keeps a core; the scene (and what Save writes) keeps the
  // number asked for, and an edit of it is applied with the same cap.
  test::TempDir dir;
  json scene = readJson(kScenes / "hanging-sheet.json");
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
  scene["solver"]["threads"] = 64;
  const fs::path file = dir.write("scenes/hanging-sheet.json", scene.dump(2));
  EditorSession session(file);
  const int machine = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int cap = std::max(1, machine - 1);
  EXPECT_EQ(editorSolverThreads(64), std::min(64, cap));
  EXPECT_EQ(editorSolverThreads(1), 1);
  EXPECT_EQ(session.scene().solver.threads, 64);
  EXPECT_EQ(session.world().scene().solver.threads, std::min(64, cap));
  json edited = session.json();
  edited["solver"]["threads"] = 1;
  ASSERT_TRUE(session.edit(edited, "threads").accepted);
  EXPECT_EQ(session.world().scene().solver.threads, 1);
  session.undo();
  EXPECT_EQ(session.world().scene().solver.threads, std::min(64, cap));
  session.advanceFrame(kOutputFrame);
  EXPECT_TRUE(session.world().metrics().finite);
}

TEST(EditorSession, AResolutionEditWaitsForAReset) {
  test::TempDir dir;
  EditorSession session(smallScene(dir, "hanging-sheet", 8));
  session.advanceFrame(kOutputFrame);
  json next = session.json();
  next["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({6, 6});
  ASSERT_TRUE(session.edit(next, "resolution").accepted);
  EXPECT_TRUE(session.resetPending());
  EXPECT_EQ(session.world().cloth(0).x.size(), 64u) << "the running world keeps its mesh until reset";
  session.reset();
  EXPECT_FALSE(session.resetPending());
  EXPECT_EQ(session.world().cloth(0).x.size(), 36u);
  EXPECT_EQ(session.world().stepCount(), 0);
}

TEST(EditorSession, PlaybackRunsInRealTimePausesStepsAndScalesBySpeed) {
  test::TempDir dir;
  EditorSession session(smallScene(dir, "hanging-sheet"));
  const int perFrame = stepsPerFrame(session.scene());
  session.advanceFrame(kOutputFrame);
  EXPECT_EQ(session.world().stepCount(), perFrame);
  session.paused = true;
  session.advanceFrame(kOutputFrame);
  EXPECT_EQ(session.world().stepCount(), perFrame);
  session.stepOnce();
  EXPECT_EQ(session.world().stepCount(), perFrame + 1);
  session.paused = false;
  session.speed = 0.5;
  for (int i = 0; i < 4; ++i) {
    session.advanceFrame(kOutputFrame);
    (void)session.world();  // a worker that keeps up (a slow one drops steps: the next test)
  }
  EXPECT_EQ(session.world().stepCount(), perFrame + 1 + 2 * perFrame) << "half speed: half the steps";
}

// A heavy scene cannot keep up: a frame owes at most kMaxFrameSeconds, and the meter shows the
// speed achieved, not the one asked for. The meter counts the simulated time a frame showed on
// arriving (what the worker finished since the frame before).
TEST(EditorSession, TheMeterShowsTheSpeedAchievedWhenFramesAreSlow) {
  test::TempDir dir;
  EditorSession session(smallScene(dir, "hanging-sheet"));
  const double dt = session.scene().solver.dt;
  for (int i = 0; i < 3; ++i) {
    session.advanceFrame(0.5);  // frames of half a second each
    (void)session.world();      // the worker took what was asked before the next frame
  }
  EXPECT_EQ(session.world().stepCount(), 3 * std::lround(EditorSession::kMaxFrameSeconds / dt));
  EXPECT_NEAR(session.meter().achievedSpeed(), EditorSession::kMaxFrameSeconds / 0.5, 1e-9)
      << "1.00x asked, 0.20x achieved";
  EXPECT_NEAR(session.meter().framesPerSecond(), 2.0, 1e-9);
  EXPECT_GT(session.meter().msPerStep(), 0.0);
  const std::string readout = playbackReadout(session.meter(), session.speed, session.paused);
  EXPECT_NE(readout.find("target 1.00x"), std::string::npos) << readout;
  EXPECT_NE(readout.find("achieved 0.20x real time"), std::string::npos) << readout;
  EXPECT_NE(readout.find(" fps"), std::string::npos) << readout;
}

TEST(EditorSession, ANonFiniteStateStopsPlaybackUntilReset) {
  test::TempDir dir;
  const fs::path file = smallScene(dir, "hanging-sheet");
  json scene = readJson(file);
  scene["solver"]["integrator"] = "symplectic_euler";
  scene["cloths"][0]["material"] = "isotropic-stiff";
  std::ofstream(file) << scene.dump(2);
  EditorSession session(file);
  for (int frame = 0; frame < 300 && !session.stopped(); ++frame) {
    session.advanceFrame(kOutputFrame);
    (void)session.world();  // a worker that keeps up with the frames
  }
  ASSERT_TRUE(session.stopped()) << "still finite after 300 frames";
  EXPECT_NE(session.status.find("non-finite"), std::string::npos) << session.status;
  const long long steps = session.world().stepCount();
  session.advanceFrame(kOutputFrame);
  EXPECT_EQ(session.world().stepCount(), steps);
  session.reset();
  EXPECT_FALSE(session.stopped());
}

TEST(EditorSession, SaveWritesTheEditedSceneAndKeepsTheOldOneAsBackup) {
  test::TempDir dir;
  const fs::path file = smallScene(dir, "hanging-sheet");
  const std::string original = readText(file);
  EditorSession session(file);
  ASSERT_TRUE(session.edit(withWeftAngle(session.json(), 0, 45.0), "weft angle").accepted);
  session.save();
  EXPECT_FALSE(session.dirty());
  EXPECT_DOUBLE_EQ(loadScene(file).cloths[0].weftAngleDeg, 45.0);
  EXPECT_EQ(readText(fs::path(file.string() + ".bak")), original);
}

TEST(EditorSession, RecoveredEditsAreOneUnsavedUndoableStepOnTopOfTheFile) {
  test::TempDir dir;
  const fs::path file = smallScene(dir, "hanging-sheet");
  const std::string original = readText(file);
  json recovered = readJson(file);
  recovered["cloths"][0]["weft_angle_deg"] = 15.0;
  EditorSession session(file, recovered);
  EXPECT_DOUBLE_EQ(session.world().scene().cloths[0].weftAngleDeg, 15.0);
  EXPECT_TRUE(session.dirty());
  EXPECT_EQ(readText(file), original) << "the file is untouched until saved";
  session.undo();
  EXPECT_DOUBLE_EQ(session.scene().cloths[0].weftAngleDeg, 0.0);
  EXPECT_FALSE(session.dirty());
}

TEST(EditorSession, ABadSceneFileIsAnInputError) {
  test::TempDir dir;
  const fs::path file = dir.write("scenes/bad.json", R"({"cloths": [{"mesh": {"grid": {}}, "material": "no-such"}]})");
  EXPECT_THROW(EditorSession session(file), InputError);
}

}  // namespace
}  // namespace weft::editor

namespace weft::editor {
namespace {

TEST(MaterialPresetSaving, AnEditedMaterialSavedAsAPresetLoadsBackAndNothingIsOverwritten) {
  test::TempDir dir;
  const fs::path file = smallScene(dir, "hanging-sheet");
  const json original = readJson(file);
  const Scene edited = parsed(withAreaDensity(original, parsed(original, file), 0, 0.4), file);
  const fs::path folder = dir.path() / "materials";
  fs::create_directories(folder);
  const fs::path saved = saveMaterialPreset(edited.cloths[0].material, "my-denser-target", folder);
  EXPECT_EQ(saved, folder / "my-denser-target.json");
  const Material back = loadMaterialFile(saved);
  EXPECT_EQ(back.name, "my-denser-target");
  EXPECT_DOUBLE_EQ(back.areaDensity, 0.4);
  EXPECT_EQ(back.elasticity, edited.cloths[0].material.elasticity);
  // The scene beside it finds the new preset by name.
  const Scene usesIt = parsed(withMaterialPreset(original, 0, "my-denser-target"), file);
  EXPECT_DOUBLE_EQ(usesIt.cloths[0].material.areaDensity, 0.4);

  EXPECT_THROW(saveMaterialPreset(back, "my-denser-target", folder), std::invalid_argument) << "never overwritten";
  EXPECT_THROW(saveMaterialPreset(back, "../escape", folder), std::invalid_argument);
  EXPECT_THROW(saveMaterialPreset(back, "Capital", folder), std::invalid_argument);
}

}  // namespace
}  // namespace weft::editor
