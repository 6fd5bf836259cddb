// The simulation off the UI thread (issue 21, item 6): the session hands steps to a worker and
// returns at once, the snapshot shows the latest finished step, changes the user makes while a
// step runs are applied between steps, and the steps taken are the ones `weft run` takes.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "editor/editor_session.h"
#include "editor/scene_edits.h"
#include "scene/scene_json.h"
#include "sim/world.h"
#include "support/temp_dir.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

json preset(const std::string& name) {
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / (name + ".json"));
  return json::parse(in);
}

// The hanging sheet at `resolution`, each step cut into `substeps`: a step as slow as needed.
fs::path sheet(const test::TempDir& dir, int resolution, int substeps) {
  json scene = preset("hanging-sheet");
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({resolution, resolution});
  scene["solver"]["substeps"] = substeps;
  return dir.write("scenes/sheet.json", scene.dump(2));
}

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// While a step much longer than a frame runs, the calls a frame makes (ask for steps, read the
// snapshot, edit a field) return without waiting for it; the snapshot still shows the last step.
TEST(StepWorker, AFrameDoesNotWaitForTheStepInFlight) {
  test::TempDir dir;
  EditorSession session(sheet(dir, 20, 150));  // a step of about 0.1 s and more
  session.paused = true;
  const Clock::time_point start = Clock::now();
  session.stepOnce();
  ASSERT_TRUE(session.stepping());
  for (int frame = 0; frame < 5; ++frame) {
    session.advanceFrame(1.0 / 60.0);  // paused: asks for nothing more
    EXPECT_EQ(session.view()->stepCount, 0) << "the snapshot is the last finished step";
  }
  ASSERT_TRUE(session.edit(withWeftAngle(session.json(), 0, 30.0), "weft angle").accepted);
  const double uiSeconds = secondsSince(start);
  const bool stillStepping = session.stepping();
  EXPECT_EQ(session.world().stepCount(), 1);  // waits for the step
  const double stepSeconds = secondsSince(start);
  ASSERT_TRUE(stillStepping) << "the step (" << stepSeconds << " s) ended before the frames did (" << uiSeconds
                             << " s): make it slower";
  EXPECT_LT(uiSeconds, 0.5 * stepSeconds);
  EXPECT_EQ(session.view()->stepCount, 1);
  EXPECT_DOUBLE_EQ(session.world().scene().cloths[0].weftAngleDeg, 30.0) << "applied after the step";
}

// A change made while steps are owed lands between two steps, never inside one: the result is
// bit for bit that of making it, with nothing running, after as many steps as it found done.
// Without changes, the session's worker takes exactly the steps a World stepped directly (as
// `weft run` does) takes.
TEST(StepWorker, ChangesLandBetweenStepsAndStepsAreThoseOfAHeadlessRun) {
  test::TempDir dir;
  const fs::path file = sheet(dir, 12, 20);
  EditorSession during(file);
  during.paused = true;
  during.stepOnce();
  during.stepOnce();
  long long landedAt = -1;
  during.applyToWorld([&landedAt](World& world) {
    landedAt = world.stepCount();
    world.setClothWeftAngle(0, 40.0);
  });
  for (int i = 0; i < 3; ++i) during.stepOnce();
  EXPECT_EQ(during.world().stepCount(), 5);
  ASSERT_GE(landedAt, 0);

  World after(loadScene(file));
  for (long long s = 0; s < landedAt; ++s) after.step();
  after.setClothWeftAngle(0, 40.0);
  while (after.stepCount() < 5) after.step();
  EXPECT_EQ(during.world().stateHash(), after.stateHash()) << "landed after step " << landedAt;

  EditorSession played(file);
  played.paused = false;
  World headless(loadScene(file));
  for (int frame = 0; frame < 6; ++frame) played.advanceFrame(played.scene().solver.dt);
  for (long long s = 0; s < played.world().stepCount(); ++s) headless.step();
  EXPECT_GT(played.world().stepCount(), 0);
  EXPECT_EQ(played.world().stateHash(), headless.stateHash());
  EXPECT_EQ(played.view()->stepCount, played.world().stepCount()) << "the snapshot caught up";
}

// A worker far behind is owed at most kMaxFrameSeconds of simulation: frames arriving faster
// than the steps drop steps instead of queueing them without bound.
TEST(StepWorker, ASlowSceneDropsStepsInsteadOfOwingThem) {
  test::TempDir dir;
  EditorSession session(sheet(dir, 16, 60));
  session.paused = false;
  const double dt = session.scene().solver.dt;
  for (int frame = 0; frame < 40; ++frame) session.advanceFrame(0.05);  // 2 s of wall time asked at once
  const long long maxOwed = static_cast<long long>(EditorSession::kMaxFrameSeconds / dt + 1e-9);
  EXPECT_LE(session.world().stepCount(), maxOwed + 1) << "never more than kMaxFrameSeconds behind";
  EXPECT_GT(session.world().stepCount(), 0);
}

// A click while a step runs: the pick waits for that step only; the grab lands between steps
// and the other owed steps wait for the next frame.
TEST(StepWorker, AClickPicksBetweenStepsAndHoldsTheRestUntilTheNextFrame) {
  test::TempDir dir;
  EditorSession session(sheet(dir, 12, 20));
  session.paused = false;
  session.advanceFrame(EditorSession::kMaxFrameSeconds);  // several steps owed
  const World& world = session.worldBetweenSteps();
  const long long atClick = world.stepCount();
  EXPECT_LT(atClick, static_cast<long long>(EditorSession::kMaxFrameSeconds / session.scene().solver.dt + 1e-9))
      << "the pick did not wait for every owed step";
  const Vec3 at = world.cloth(0).x[5];
  session.applyToWorld([at](World& w) { w.grab(0, 5, at, 60.0); });  // at once: the worker is held
  EXPECT_EQ(session.view()->stepCount, atClick) << "held: nothing steps until the next frame";
  session.paused = true;
  session.advanceFrame(0.0);  // releases the worker: it takes the steps still owed
  EXPECT_GT(session.world().stepCount(), atClick);
  EXPECT_TRUE(session.world().grabState().has_value());
}

}  // namespace
}  // namespace weft::editor
