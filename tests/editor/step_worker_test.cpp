// The simulation off the UI thread (issue 21, item 6): the session hands steps to a worker and
// returns at once, the snapshot shows the latest finished step, changes the user makes while a
// step runs are applied between steps, and the steps taken are the ones `weft run` takes.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <memory>
#include <optional>
#include <filesystem>
#include <functional>
#include <future>
#include <thread>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "editor/editor_session.h"
#include "editor/scene_edits.h"
#include "editor/step_worker.h"
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

// Table 4.1 Cloth 2 at 10^2 with block Jacobi CG, so World::step depends on the state only and a
// replayed log gives the same world to the bit.
Scene smallTearingSheet(const test::TempDir& dir) {
  json sheetJson = preset("ball-into-sheet-table4.1-cloth2");
  sheetJson["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({10, 10});
  sheetJson["solver"]["linear_solver"]["preconditioner"] = "block_jacobi";
  return loadScene(dir.write("scenes/sheet.json", sheetJson.dump(2)));
}

// The change log a resume replays (timeline, item 7) goes back only as far as the oldest world
// copy still held: a long session with an edit every frame, and a timeline that keeps the last
// few copies (as thinning and a full budget leave it), logs a few frames' edits, not the
// session's. A resume from the oldest copy kept still replays every edit since, where it landed:
// the world is the one that never stopped, to the bit (block Jacobi CG: World::step depends on
// the state only).
TEST(StepWorker, TheChangeLogGoesBackOnlyAsFarAsTheOldestWorldCopyHeld) {
  test::TempDir dir;
  const Scene scene = smallTearingSheet(dir);
  const long long frameSteps = std::max<long long>(stepsPerFrame(scene), 1);
  StepWorker worker(std::make_unique<World>(scene));
  std::deque<std::shared_ptr<const World>> kept{worker.copyWhenIdle()};  // the timeline's copies
  constexpr std::size_t kKept = 3;
  constexpr int kFrames = 30;
  for (int frame = 1; frame <= kFrames; ++frame) {
    worker.apply([frame](World& world) {  // an edit at the start of every frame
      ForcesSpec forces = world.scene().forces;
      forces.gravity = Vec3(0.3 * std::sin(frame), -9.81 + 0.5 * std::cos(frame), 0.0);
      world.setForces(forces);
    });
    worker.ask(frameSteps, frameSteps);
    worker.wait();
    const std::optional<StepResult> result = worker.takeResult();
    ASSERT_TRUE(result);
    ASSERT_EQ(result->frames.size(), 1u);
    kept.push_back(result->frames.front().world);
    while (kept.size() > kKept) kept.pop_front();  // thinned away: nothing holds it any more
    EXPECT_LE(worker.loggedChanges(), kKept) << "frame " << frame << ": the edits since the oldest copy held";
  }
  EXPECT_GE(worker.loggedChanges(), kKept - 1) << "the edits a resume from a kept copy replays are kept";

  const World& live = worker.idleWorld();
  const long long end = live.stepCount();
  ASSERT_EQ(end, kFrames * frameSteps);
  const std::uint64_t liveHash = live.stateHash();
  const Vec3 liveGravity = live.scene().forces.gravity;
  const std::shared_ptr<const World> oldest = kept.front();
  ASSERT_LT(oldest->stepCount(), end - frameSteps) << "the resume steps over more than one logged edit";
  worker.resumeFrom(oldest, end);
  const World& resumed = worker.idleWorld();
  EXPECT_EQ(resumed.stepCount(), end);
  EXPECT_EQ(resumed.scene().forces.gravity, liveGravity) << "the last edit replayed";
  EXPECT_EQ(resumed.stateHash(), liveHash) << "every edit since the oldest copy replayed where it landed";
  const std::optional<StepResult> rewound = worker.takeResult();
  ASSERT_TRUE(rewound && rewound->rewoundTo);
  EXPECT_EQ(*rewound->rewoundTo, end);
}

// R while a heavy scene plays: the reset (attach) lands while a step runs, and drops the owed
// steps, the running one included. The step that ends afterwards does not count itself off again
// (owed -1: the worker slept and the reset's copy of the new world waited for it forever, the
// editor hung). The same for going back to a frame (resumeFrom) while a step runs.
TEST(StepWorker, AResetOrAResumeWhileAStepRunsDoesNotHangTheNextWait) {
  test::TempDir dir;
  const Scene scene = loadScene(sheet(dir, 20, 150));  // a step of about 0.1 s and more
  StepWorker worker(std::make_unique<World>(scene));
  const std::shared_ptr<const World> start = worker.copyWhenIdle();
  const auto waitsAtMost = [&](const std::function<void()>& wait) {
    auto done = std::make_shared<std::promise<void>>();
    std::future<void> finished = done->get_future();
    std::thread waiter([wait, done] {
      wait();
      done->set_value();
    });
    const bool ended = finished.wait_for(std::chrono::seconds(30)) == std::future_status::ready;
    if (!ended) worker.ask(2, 2);  // wakes the worker so the waiter (and the test) can end
    waiter.join();
    return ended;
  };
  worker.ask(5, 5);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  ASSERT_TRUE(worker.busy());
  worker.attach(std::make_unique<World>(scene));  // R while playing
  EXPECT_TRUE(waitsAtMost([&] { (void)worker.copyWhenIdle(); })) << "the reset's copy waited forever";
  EXPECT_EQ(worker.owed(), 0);

  worker.ask(5, 5);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  worker.resumeFrom(start, 0);  // back to frame 0 while a step runs
  EXPECT_TRUE(waitsAtMost([&] { (void)worker.idleWorld(); })) << "the wait after going back never ended";
  EXPECT_EQ(worker.idleWorld().stepCount(), 0);
}

// A drag while paused (the grab's target, a tool's position, set every frame at the same step)
// logs one change, not one a frame: a setter's change replaces the same setter's change logged
// right before it between the same two steps. Other changes in between keep both; replaying the
// log still gives the world as it is.
TEST(StepWorker, ADragWhilePausedLogsOneChangeNotOneAFrame) {
  test::TempDir dir;
  const Scene scene = smallTearingSheet(dir);
  StepWorker worker(std::make_unique<World>(scene));
  const std::shared_ptr<const World> start = worker.copyWhenIdle();
  worker.ask(3, 3);
  worker.wait();
  const Vec3 at = worker.idleWorld().cloth(0).x[5];
  worker.apply([at](World& world) { world.grab(0, 5, at, 60.0); });
  const auto move = [&](double dy) {
    const Vec3 target = at + Vec3(0.0, dy, 0.0);  // a Vec3, not an Eigen expression of a temporary
    worker.apply(WorldChange{[target](World& world) { world.moveGrab(target); }, "grab target", 0});
  };
  for (int frame = 0; frame < 200; ++frame) move(0.001 * frame);
  EXPECT_EQ(worker.loggedChanges(), 2u) << "the grab and its latest target";
  worker.apply([](World& world) { world.setForces(world.scene().forces); });
  move(0.3);
  EXPECT_EQ(worker.loggedChanges(), 4u) << "a change in between: the target set after it is another change";
  worker.ask(2, 2);
  worker.wait();
  move(0.4);
  EXPECT_EQ(worker.loggedChanges(), 5u) << "after a step: another change";
  worker.ask(2, 2);
  worker.wait();
  const std::uint64_t liveHash = worker.idleWorld().stateHash();
  const long long end = worker.idleWorld().stepCount();
  worker.resumeFrom(start, end);
  EXPECT_EQ(worker.idleWorld().stateHash(), liveHash) << "the log replayed gives the world that never stopped";
  ASSERT_TRUE(worker.idleWorld().grabState());
  const Vec3 last = at + Vec3(0.0, 0.4, 0.0);
  EXPECT_EQ(worker.idleWorld().grabState()->spring.target, last) << "the last target set";
}

}  // namespace
}  // namespace weft::editor
