// The playback meter reports what playback achieves over the last second, from exact numbers.
#include "editor/playback_meter.h"

#include <gtest/gtest.h>

namespace weft::editor {
namespace {

TEST(PlaybackMeter, AchievedSpeedIsSimulatedOverWallTime) {
  PlaybackMeter meter;
  EXPECT_FALSE(meter.measured());
  EXPECT_EQ(meter.msPerStep(), 0.0);
  for (int i = 0; i < 10; ++i) {
    meter.addSteps(4, 40.0);          // 4 steps of 10 ms
    meter.frame(0.05, 4 * 0.0025);    // a 50 ms frame that simulated 10 ms
  }
  EXPECT_NEAR(meter.achievedSpeed(), 0.2, 1e-12);
  EXPECT_NEAR(meter.framesPerSecond(), 20.0, 1e-9);
  EXPECT_NEAR(meter.msPerStep(), 10.0, 1e-12);
  EXPECT_NEAR(meter.stepsPerFrame(), 4.0, 1e-12);
}

TEST(PlaybackMeter, OnlyTheLastSecondCounts) {
  PlaybackMeter meter;
  for (int i = 0; i < 60; ++i) meter.frame(1.0 / 60.0, 1.0 / 60.0);  // a second in real time
  EXPECT_NEAR(meter.achievedSpeed(), 1.0, 1e-9);
  for (int i = 0; i < 30; ++i) meter.frame(0.1, 0.01);  // then three seconds at a tenth
  EXPECT_NEAR(meter.achievedSpeed(), 0.1, 1e-9) << "the real-time frames were forgotten";
  EXPECT_NEAR(meter.framesPerSecond(), 10.0, 1e-6);
}

TEST(PlaybackMeter, KeepsTheLastStepTimeWhilePaused) {
  PlaybackMeter meter;
  meter.addSteps(2, 30.0);
  meter.frame(0.02, 0.01);
  for (int i = 0; i < 100; ++i) meter.frame(0.02, 0.0);  // paused: frames without steps
  EXPECT_NEAR(meter.msPerStep(), 15.0, 1e-12);
  EXPECT_EQ(meter.achievedSpeed(), 0.0);
  EXPECT_NE(playbackReadout(meter, 1.0, true).find("paused"), std::string::npos);
}

}  // namespace
}  // namespace weft::editor
