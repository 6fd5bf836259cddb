// The timeline (issue 21, item 7): every simulated output frame is cached (positions and
// topology) within a memory budget; scrubbing back shows a cached frame, the same state and the
// same pixels as when it was simulated, without simulating; changing the world while looking at
// an earlier frame drops the frames after it and the simulation continues from there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "editor/editor_session.h"
#include "editor/frame_cache.h"
#include "editor/scene_edits.h"
#include "headless_gl_context.h"
#include "offscreen_framebuffer.h"
#include "render_view.h"
#include "scene/scene_json.h"
#include "scene_renderer.h"
#include "support/temp_dir.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path tearingSheet(const test::TempDir& dir) {
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "ball-into-sheet-table4.1-cloth2.json");
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({10, 10});
  return dir.write("scenes/sheet.json", scene.dump(2));
}

// Plays `frames` output frames, the worker keeping up.
void playFrames(EditorSession& session, int frames) {
  session.paused = false;
  const double frame = session.stepsPerFrame() * session.scene().solver.dt;
  for (int i = 0; i < frames; ++i) {
    session.advanceFrame(frame);
    (void)session.world();
  }
  session.advanceFrame(0.0);  // collects the last frames into the cache
  session.paused = true;
}

std::uint64_t positionsHash(const WorldSnapshot& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (const ClothMesh& m : s.cloths) {
    for (const Vec3& x : m.x) {
      for (int k = 0; k < 3; ++k) {
        const double d = x[k];
        const auto* bytes = reinterpret_cast<const unsigned char*>(&d);
        for (std::size_t b = 0; b < sizeof d; ++b) h = (h ^ bytes[b]) * 1099511628211ull;
      }
    }
    h ^= m.tris.size() * 31 + m.x.size();
  }
  return h;
}

TEST(FrameCache, StaysWithinItsBudgetDroppingTheOldestButFrameZero) {
  test::TempDir dir;
  EditorSession session(tearingSheet(dir));
  const std::shared_ptr<const WorldSnapshot> one = session.view();
  const std::size_t size = snapshotBytes(*one);
  FrameCache cache(3 * size + size / 2);  // room for three frames
  for (long long f = 0; f < 6; ++f) cache.add(f, one);
  EXPECT_EQ(cache.frameCount(), 3u);
  EXPECT_LE(cache.bytes(), cache.budgetBytes());
  EXPECT_TRUE(cache.find(0)) << "frame 0 is kept";
  EXPECT_TRUE(cache.find(5)) << "the newest is kept";
  EXPECT_FALSE(cache.find(1));
  cache.invalidateAfter(0);
  EXPECT_EQ(cache.lastFrame(), 0);
  EXPECT_EQ(cache.nearest(4), 0);
}

// Past the budget the world copies go first, thinned evenly: every frame stays shown, the kept
// copies spread over the timeline (frame 0's and the newest kept), and each frame resumes from
// the nearest kept copy at or before it.
TEST(FrameCache, WorldCopiesAreThinnedEvenlyBeforeAnyFrameGoes) {
  test::TempDir dir;
  EditorSession session(tearingSheet(dir));
  const std::shared_ptr<const WorldSnapshot> one = session.view();
  const std::shared_ptr<const World> world = session.frames().worldAt(0);
  ASSERT_TRUE(world);
  const std::size_t s = snapshotBytes(*one), w = world->approximateBytes();
  EXPECT_GT(w, s) << "a world copy weighs more than what is drawn";
  FrameCache cache(33 * s + 6 * w + w / 2);  // every frame, and room for six copies
  for (long long f = 0; f <= 32; ++f) cache.add(f, one, world);
  EXPECT_EQ(cache.frameCount(), 33u) << "no frame dropped while copies can go";
  EXPECT_EQ(cache.worldCount(), 6u);
  EXPECT_LE(cache.bytes(), cache.budgetBytes());
  EXPECT_TRUE(cache.worldAt(0));
  EXPECT_TRUE(cache.worldAt(32));
  long long previous = 0, widest = 0;
  for (long long f = 1; f <= 32; ++f) {
    if (!cache.worldAt(f)) continue;
    widest = std::max(widest, f - previous);
    previous = f;
  }
  EXPECT_LE(widest, 2 * 32 / 5) << "spread evenly, not only the newest kept";
  for (long long f = 0; f <= 32; ++f) {
    const std::optional<long long> from = cache.worldFrameAtOrBefore(f);
    ASSERT_TRUE(from);
    EXPECT_LE(*from, f);
    EXPECT_GT(*from, f - widest);
  }
  cache.setBudget(33 * s);  // no room for copies but frame 0's and the newest
  EXPECT_EQ(cache.worldCount(), 2u);
  cache.setBudget(10 * s);  // then frames go, the oldest first, frame 0 last
  EXPECT_LE(cache.bytes(), cache.budgetBytes());
  EXPECT_TRUE(cache.find(0));
  EXPECT_TRUE(cache.find(32));
  EXPECT_FALSE(cache.find(1));
}

TEST(Timeline, ScrubbingBackShowsACachedFrameWithoutSimulating) {
  test::TempDir dir;
  EditorSession session(tearingSheet(dir));
  playFrames(session, 3);
  const std::shared_ptr<const WorldSnapshot> atThree = session.view();
  ASSERT_EQ(atThree->stepCount, 3 * session.stepsPerFrame());
  const std::uint64_t threeHash = positionsHash(*atThree);
  playFrames(session, 5);
  ASSERT_EQ(session.liveFrame(), 8);
  EXPECT_EQ(session.frames().firstFrame(), 0);
  EXPECT_EQ(session.frames().lastFrame(), 8);
  EXPECT_EQ(session.frames().frameCount(), 9u) << "every output frame";

  session.showFrame(3);
  EXPECT_EQ(session.shownFrame(), 3);
  EXPECT_EQ(session.view()->stepCount, 3 * session.stepsPerFrame());
  EXPECT_EQ(positionsHash(*session.view()), threeHash) << "the state as simulated";
  EXPECT_EQ(session.world().stepCount(), 8 * session.stepsPerFrame()) << "nothing re-simulated";

  // Play runs through the cached frames and then goes on live.
  session.stepOnce();
  EXPECT_EQ(session.shownFrame(), 4);
  session.showFrame(8);
  EXPECT_FALSE(session.shownFrame()) << "the newest frame is the live world";
}

TEST(Timeline, AnEditOnAnEarlierFrameDropsTheFramesAfterItAndContinuesFromIt) {
  test::TempDir dir;
  EditorSession session(tearingSheet(dir));
  playFrames(session, 4);
  const std::uint64_t twoHash = positionsHash(*session.frames().find(2));
  const std::uint64_t fourHash = positionsHash(*session.view());
  session.showFrame(2);
  ASSERT_TRUE(session.edit(withWeftAngle(session.json(), 0, 30.0), "weft angle").accepted);
  EXPECT_EQ(session.frames().lastFrame(), 2) << "frames after the edited one are dropped";
  EXPECT_EQ(session.world().stepCount(), 2 * session.stepsPerFrame()) << "back at frame 2";
  session.advanceFrame(0.0);
  EXPECT_FALSE(session.shownFrame()) << "live again, at frame 2";
  EXPECT_EQ(positionsHash(*session.view()), twoHash) << "frame 2's state, copied";
  EXPECT_DOUBLE_EQ(session.world().scene().cloths[0].weftAngleDeg, 30.0);
  playFrames(session, 2);
  EXPECT_EQ(session.liveFrame(), 4);
  EXPECT_NE(positionsHash(*session.view()), fourHash) << "frame 4 again, simulated with the edit";
}

// The sheet with a linear solver whose answer depends only on the state (block Jacobi CG), so a
// world resumed from a frame and one that never stopped agree bit for bit (World::clone).
fs::path blockJacobiSheet(const test::TempDir& dir, const std::string& name) {
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "ball-into-sheet-table4.1-cloth2.json");
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({10, 10});
  scene["solver"]["linear_solver"]["preconditioner"] = "block_jacobi";
  return dir.write("scenes/" + name, scene.dump(2));
}

// Item 7 as Houdini's playbar does it: an edit at frame k keeps frames 0..k as they were and the
// simulation continues from frame k's own state, not from t = 0. The resumed world is a copy of
// the one cached at frame k: its stage times (wall clock, never reproduced by simulating again)
// are frame k's to the bit, and it steps on exactly as a world edited live at frame k does.
TEST(Timeline, AnEditOnAnEarlierFrameResumesFromThatFramesStateWithoutResimulating) {
  test::TempDir dir;
  const fs::path file = blockJacobiSheet(dir, "scrubbed.json");
  EditorSession scrubbed(file);
  playFrames(scrubbed, 6);
  const std::shared_ptr<const WorldSnapshot> frameOne = scrubbed.frames().find(1);
  const std::shared_ptr<const WorldSnapshot> frameThree = scrubbed.frames().find(3);
  ASSERT_TRUE(frameThree && scrubbed.frames().worldAt(3)) << "each cached frame keeps its world";
  scrubbed.showFrame(3);
  ASSERT_TRUE(scrubbed.edit(withWeftAngle(scrubbed.json(), 0, 30.0), "weft angle").accepted);
  const World& resumed = scrubbed.world();
  EXPECT_EQ(resumed.stepCount(), 3 * scrubbed.stepsPerFrame());
  EXPECT_EQ(resumed.profile().totalMs, frameThree->profile.totalMs) << "frame 3's world, copied, not simulated again";
  EXPECT_EQ(resumed.solverStats().linearIterations, frameThree->solver.linearIterations);
  EXPECT_EQ(scrubbed.frames().lastFrame(), 3);
  EXPECT_EQ(scrubbed.frames().find(1), frameOne) << "frames 0..3 are kept as they were";
  EXPECT_EQ(scrubbed.frames().find(3), frameThree);
  playFrames(scrubbed, 3);

  // The same edit made live at frame 3, never going back.
  EditorSession live(blockJacobiSheet(dir, "live.json"));
  playFrames(live, 3);
  ASSERT_TRUE(live.edit(withWeftAngle(live.json(), 0, 30.0), "weft angle").accepted);
  playFrames(live, 3);
  ASSERT_EQ(scrubbed.liveFrame(), 6);
  ASSERT_EQ(live.liveFrame(), 6);
  EXPECT_EQ(scrubbed.world().stateHash(), live.world().stateHash());
  EXPECT_EQ(scrubbed.world().tearLog().size(), live.world().tearLog().size());
  EXPECT_EQ(positionsHash(*scrubbed.frames().find(5)), positionsHash(*live.frames().find(5)));
}

// With a budget too small for a copy per frame, an edit on a frame whose copy was thinned away
// steps the nearest earlier copy forward to it (with the changes made meanwhile, here a live edit
// at frame 2), not the world from t = 0, and continues exactly as an edit made live there.
TEST(Timeline, AFrameWithoutItsOwnCopyResumesFromTheNearestEarlierOne) {
  test::TempDir dir;
  EditorSession scrubbed(blockJacobiSheet(dir, "thinned.json"));
  playFrames(scrubbed, 2);
  ASSERT_TRUE(scrubbed.edit(withGravity(scrubbed.json(), Vec3(0.0, -5.0, 0.0)), "gravity").accepted);
  playFrames(scrubbed, 7);
  // Frame 9's sizes: at frame 0 the contact stage has built nothing yet.
  const std::size_t s = snapshotBytes(*scrubbed.frames().find(9));
  const std::size_t w = scrubbed.frames().worldAt(9)->approximateBytes();
  scrubbed.setTimelineBudget(10 * s + 4 * w);  // frames 0..9, about four copies: 0, 9 and two between
  ASSERT_EQ(scrubbed.frames().frameCount(), 10u);
  ASSERT_LT(scrubbed.frames().worldCount(), 7u);
  long long target = -1;
  for (long long f = 8; f > 1 && target < 0; --f) {
    if (!scrubbed.frames().worldAt(f) && scrubbed.frames().worldFrameAtOrBefore(f) > 0) target = f;
  }
  ASSERT_GT(target, 0) << "a frame without its own copy, a kept copy after frame 0 before it";
  scrubbed.showFrame(target);
  ASSERT_TRUE(scrubbed.edit(withWeftAngle(scrubbed.json(), 0, 30.0), "weft angle").accepted);
  ASSERT_TRUE(scrubbed.lastResume());
  EXPECT_EQ(scrubbed.lastResume()->frame, target);
  EXPECT_EQ(scrubbed.lastResume()->from, *scrubbed.frames().worldFrameAtOrBefore(target));
  EXPECT_GT(scrubbed.lastResume()->from, 0) << "from the nearest kept copy, not from t = 0";
  EXPECT_LT(scrubbed.lastResume()->from, target);
  EXPECT_EQ(scrubbed.world().stepCount(), target * scrubbed.stepsPerFrame());
  playFrames(scrubbed, 2);

  EditorSession live(blockJacobiSheet(dir, "live-thinned.json"));
  playFrames(live, 2);
  ASSERT_TRUE(live.edit(withGravity(live.json(), Vec3(0.0, -5.0, 0.0)), "gravity").accepted);
  playFrames(live, static_cast<int>(target) - 2);
  ASSERT_TRUE(live.edit(withWeftAngle(live.json(), 0, 30.0), "weft angle").accepted);
  playFrames(live, 2);
  ASSERT_EQ(scrubbed.liveFrame(), live.liveFrame());
  EXPECT_EQ(scrubbed.world().stateHash(), live.world().stateHash());
  EXPECT_EQ(scrubbed.world().tearLog().size(), live.world().tearLog().size());
}

// A long tearing session with a change every frame (step_worker.h: the user's changes a resume
// replays are logged from the oldest copy held, frame 0's) keeps the timeline, the change log
// counted in, within its budget. Each change here says it holds `changeBytes` (a heavy edit), so
// the log matters within a few dozen frames. Returns what each frame showed when it was simulated.
struct LongSession {
  std::map<long long, std::uint64_t> positions;  // each frame's positions when simulated
  std::map<long long, std::size_t> vertices;     // a tear splits vertices
  std::size_t mostLogged = 0;                    // the worker's log at its longest
};
LongSession playWithAChangeEveryFrame(EditorSession& session, int frames, std::size_t changeBytes) {
  LongSession run;
  run.positions[0] = positionsHash(*session.view());
  run.vertices[0] = session.view()->cloths[0].x.size();
  for (int frame = 1; frame <= frames; ++frame) {
    session.applyToWorld(WorldChange{[frame](World& world) {
                                       ForcesSpec forces = world.scene().forces;
                                       forces.gravity = Vec3(0.3 * std::sin(frame), -9.81 + 0.5 * std::cos(frame), 0.0);
                                       world.setForces(forces);
                                     },
                                     {}, changeBytes});
    playFrames(session, 1);
    EXPECT_LE(session.frames().bytes(), session.frames().budgetBytes()) << "frame " << frame;
    const std::shared_ptr<const WorldSnapshot> newest = session.frames().find(frame);
    EXPECT_TRUE(newest) << "frame " << frame << ": the newest frame is always kept";
    if (!newest) continue;
    run.positions[frame] = positionsHash(*newest);
    run.vertices[frame] = newest->cloths[0].x.size();
    run.mostLogged = std::max(run.mostLogged, session.loggedChanges());
  }
  return run;
}

// Going back to `frame` (an edit that changes nothing) puts the world where it was when the frame
// was simulated, to the bit (block Jacobi), however far back its nearest kept copy is.
void expectResumesExactly(EditorSession& session, long long frame, const LongSession& run) {
  session.showFrame(frame);
  session.applyToWorld([](World&) {});
  const World& resumed = session.world();
  EXPECT_EQ(resumed.stepCount(), frame * session.stepsPerFrame());
  const std::shared_ptr<const WorldSnapshot> now = snapshotOf(resumed);
  EXPECT_EQ(positionsHash(*now), run.positions.at(frame)) << "frame " << frame << ", resumed from "
                                                          << session.lastResume()->from;
  EXPECT_EQ(now->cloths[0].x.size(), run.vertices.at(frame)) << "frame " << frame << ": its torn topology";
}

TEST(Timeline, TheChangeLogCountsInTheBudgetAndFrameZeroStillShowsTheUntornSheet) {
  test::TempDir dir;
  EditorSession session(blockJacobiSheet(dir, "long.json"));
  playFrames(session, 12);
  const std::size_t s = snapshotBytes(*session.frames().find(12));
  const std::size_t w = session.frames().worldAt(12)->approximateBytes();
  session.reset();
  const std::size_t budget = 40 * s + 6 * w;
  session.setTimelineBudget(budget);
  const LongSession run = playWithAChangeEveryFrame(session, 90, budget / 180);  // 90 changes: half the budget
  ASSERT_GT(session.world().tearLog().size(), 0u) << "the ball tore the sheet";
  EXPECT_GT(run.vertices.at(90), run.vertices.at(0));
  EXPECT_GE(session.frames().changeLogBytes(), budget / 2) << "the log takes the place of frames";
  EXPECT_LT(session.frames().frameCount(), 91u) << "frames went to make room for it";
  ASSERT_EQ(session.frames().firstFrame(), 0) << "while the log fits, frame 0 stays";
  EXPECT_EQ(session.loggedChanges(), 90u) << "every change since frame 0's copy";
  session.showFrame(0);
  EXPECT_EQ(session.view()->cloths[0].x.size(), run.vertices.at(0)) << "frame 0 shows the sheet untorn";
  EXPECT_LT(session.view()->cloths[0].x.size(), session.world().cloth(0).x.size());
  EXPECT_EQ(positionsHash(*session.view()), run.positions.at(0));
  // A frame near the end, its copy thinned: stepped forward from frame 0's with every change replayed.
  const long long target = session.frames().lastFrame() - 1;
  ASSERT_FALSE(session.frames().worldAt(target));
  expectResumesExactly(session, target, run);
  EXPECT_EQ(session.lastResume()->from, 0);
}

TEST(Timeline, ALogOutgrowingTheBudgetTakesFrameZeroWithItAndStaysBounded) {
  test::TempDir dir;
  EditorSession session(blockJacobiSheet(dir, "longer.json"));
  // The sizes once the sheet has torn (a torn world's caches are larger than an intact one's):
  // three copies of the largest world fit beside the log.
  playFrames(session, 60);
  const std::size_t s = snapshotBytes(*session.frames().find(60));
  const std::size_t w = session.frames().worldAt(60)->approximateBytes();
  session.reset();
  const std::size_t budget = 10 * s + 3 * w;
  session.setTimelineBudget(budget);
  const std::size_t change = w / 4;
  const LongSession run = playWithAChangeEveryFrame(session, 60, change);
  ASSERT_GT(session.world().tearLog().size(), 0u) << "the ball tore the sheet";
  EXPECT_GT(session.frames().firstFrame(), 0) << "frame 0 went, and the log before the frames left";
  // The worker trims its log when it next logs or copies, a frame after the timeline let go.
  EXPECT_LE(run.mostLogged, budget / change + 2) << "the log never outgrew the budget";
  EXPECT_LT(session.loggedChanges(), 60u);
  // The oldest frame left, and one after it without its own copy, still resume exactly.
  const long long first = session.frames().firstFrame();
  ASSERT_TRUE(session.frames().worldAt(first)) << "the first frame keeps its copy";
  long long target = -1;
  for (long long f = session.frames().lastFrame() - 1; f > first && target < 0; --f) {
    if (session.frames().find(f) && !session.frames().worldAt(f)) target = f;
  }
  ASSERT_GT(target, first) << "a frame after it without its own copy";
  expectResumesExactly(session, target, run);
  EXPECT_EQ(session.lastResume()->from, first);
  session.showFrame(first);
  EXPECT_EQ(session.view()->cloths[0].x.size(), run.vertices.at(first));
  expectResumesExactly(session, first, run);
}

// Going back twice to the same frame starts from the same state both times: the cached frame's
// world is copied, never stepped itself.
TEST(Timeline, ACachedFramesWorldIsNotChangedByResumingFromIt) {
  test::TempDir dir;
  EditorSession session(blockJacobiSheet(dir, "twice.json"));
  playFrames(session, 4);
  const std::shared_ptr<const World> frameTwo = session.frames().worldAt(2);
  ASSERT_TRUE(frameTwo);
  const std::uint64_t hash = frameTwo->stateHash();
  session.showFrame(2);
  ASSERT_TRUE(session.edit(withWeftAngle(session.json(), 0, 30.0), "weft angle").accepted);
  playFrames(session, 2);
  EXPECT_EQ(frameTwo->stateHash(), hash);
  EXPECT_EQ(frameTwo->stepCount(), 2 * session.stepsPerFrame());
  session.showFrame(2);
  ASSERT_TRUE(session.edit(withWeftAngle(session.json(), 0, 0.0), "weft angle").accepted);
  EXPECT_EQ(session.world().stateHash(), hash) << "back at frame 2's state (the weft edit moves no vertex)";
}

// A reset while the world is going back to an earlier frame: the session is at t = 0 with only
// frame 0 cached, and nothing from the resume arrives later.
TEST(Timeline, AResetWhileGoingBackToAFrameWins) {
  test::TempDir dir;
  EditorSession session(tearingSheet(dir));
  playFrames(session, 6);
  session.showFrame(5);
  ASSERT_TRUE(session.edit(withWeftAngle(session.json(), 0, 30.0), "weft angle").accepted);  // back to 5
  session.reset();
  EXPECT_EQ(session.world().stepCount(), 0);
  session.advanceFrame(0.0);
  EXPECT_FALSE(session.shownFrame());
  EXPECT_EQ(session.frames().frameCount(), 1u);
  EXPECT_EQ(session.view()->stepCount, 0);
  EXPECT_DOUBLE_EQ(session.world().scene().cloths[0].weftAngleDeg, 30.0) << "the reset applies the document";
}

// The same pixels: frame 3 drawn when it was live and drawn again from the cache after
// scrubbing back from frame 7.
TEST(Timeline, ACachedFrameDrawsTheSamePixelsAsWhenItWasSimulated) {
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  std::unique_ptr<ui::HeadlessGlContext> context;
  try {
    context = std::make_unique<ui::HeadlessGlContext>();
  } catch (const ui::GlContextError& e) {
    GTEST_SKIP() << "headless OpenGL (EGL surfaceless) cannot start here: " << e.what();
  }
  test::TempDir dir;
  EditorSession session(tearingSheet(dir));
  const int width = 320, height = 240;
  const ui::OrbitCamera camera = ui::defaultCamera(session.view()->render, session.scene().output.camera,
                                                   static_cast<double>(width) / height);
  ui::SceneRenderer renderer;
  ui::OffscreenFramebuffer framebuffer(width, height, 4);
  const auto draw = [&] {
    const std::shared_ptr<const WorldSnapshot> shown = session.view();
    framebuffer.bind();
    renderer.draw(shown->render, camera, width, height);
    return framebuffer.readPixels();
  };
  playFrames(session, 3);
  const std::vector<std::uint8_t> simulated = draw();
  playFrames(session, 4);
  const std::vector<std::uint8_t> later = draw();
  session.showFrame(3);
  const std::vector<std::uint8_t> scrubbed = draw();
  EXPECT_NE(later, simulated) << "the sheet moved between frames 3 and 7";
  EXPECT_EQ(scrubbed, simulated);
}

}  // namespace
}  // namespace weft::editor
