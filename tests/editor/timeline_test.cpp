// The timeline (issue 21, item 7): every simulated output frame is cached (positions and
// topology) within a memory budget; scrubbing back shows a cached frame, the same state and the
// same pixels as when it was simulated, without simulating; changing the world while looking at
// an earlier frame drops the frames after it and the simulation continues from there.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
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
