// The live viewer's rules for advancing a scene, without a window.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "live_simulation.h"
#include "util/input_error.h"

namespace weft::ui {
namespace {

const std::string kHangingSheet = std::string(WEFT_SOURCE_DIR) + "/presets/scenes/hanging-sheet.json";
const std::vector<std::string> kSmall{"cloths.0.mesh.grid.resolution=[6,6]"};

TEST(LiveSimulation, RunningAdvancesOneOutputFramePerDisplayedFrame) {
  LiveSimulation simulation(kHangingSheet, kSmall);
  const double dt = simulation.scene().solver.dt;
  EXPECT_FALSE(simulation.paused());
  EXPECT_FALSE(simulation.advanceFrame());
  EXPECT_NEAR(simulation.world().time(), stepsPerFrame(simulation.scene()) * dt, 1e-12);
  EXPECT_GT(stepsPerFrame(simulation.scene()), 1) << "the hanging sheet runs 2 steps a frame";
  EXPECT_FALSE(simulation.stepOnce());  // only while paused
  EXPECT_NEAR(simulation.world().time(), stepsPerFrame(simulation.scene()) * dt, 1e-12);
}

TEST(LiveSimulation, PausedItStandsStillAndStepsOnRequest) {
  LiveSimulation simulation(kHangingSheet, kSmall);
  simulation.togglePause();
  ASSERT_TRUE(simulation.paused());
  simulation.advanceFrame();
  EXPECT_EQ(simulation.world().stepCount(), 0);
  simulation.stepOnce();
  EXPECT_EQ(simulation.world().stepCount(), 1);
  EXPECT_NE(simulation.status().find("paused"), std::string::npos) << simulation.status();
}

TEST(LiveSimulation, ReloadStartsOverAndKeepsThePause) {
  LiveSimulation simulation(kHangingSheet, kSmall);
  simulation.advanceFrame();
  simulation.togglePause();
  simulation.reload();
  EXPECT_EQ(simulation.world().stepCount(), 0);
  EXPECT_TRUE(simulation.paused());
  EXPECT_EQ(simulation.world().cloth(0).x.size(), 36u) << "the overrides are applied again";
}

TEST(LiveSimulation, ANonFiniteStateStopsItUntilReload) {
  // Symplectic Euler at 60 Hz on a stiff fabric: far past its stability limit.
  LiveSimulation simulation(kHangingSheet, {"cloths.0.mesh.grid.resolution=[8,8]", "solver.integrator=symplectic_euler",
                                            "cloths.0.material=isotropic-stiff"});
  int frames = 0;
  bool stoppedNow = false;
  while (!stoppedNow && frames < 300) {
    stoppedNow = simulation.advanceFrame();
    ++frames;
  }
  ASSERT_TRUE(stoppedNow) << "still finite after 300 frames";
  EXPECT_TRUE(simulation.stopped());
  const long long steps = simulation.world().stepCount();
  EXPECT_FALSE(simulation.advanceFrame());
  EXPECT_EQ(simulation.world().stepCount(), steps);
  EXPECT_NE(simulation.status().find("non-finite"), std::string::npos) << simulation.status();
  simulation.reload();
  EXPECT_FALSE(simulation.stopped());
}

TEST(LiveSimulation, ABadSceneIsAnInputError) {
  EXPECT_THROW(LiveSimulation(kHangingSheet, {"solver.dt=-1"}), InputError);
}

}  // namespace
}  // namespace weft::ui
