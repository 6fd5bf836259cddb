// Issue 19 in the editor: the health check `weft run` runs after every step runs in the editor
// too (on its step worker), and the editor shows the warning `weft run` prints for the same
// steps: in red in the playback panel and in the status bar, until a reset.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_json.h"
#include "sim/health_check.h"
#include "sim/world.h"
#include "support/editor_panels_fixture.h"

namespace weft::test {
namespace {

class EditorHealth : public EditorPanelsTest {};

long long redPixels(const test::RgbaImage& image, const ImVec4& r) {
  long long count = 0;
  for (int y = std::max(0, static_cast<int>(r.y)); y < std::min(image.height, static_cast<int>(r.w)); ++y) {
    for (int x = std::max(0, static_cast<int>(r.x)); x < std::min(image.width, static_cast<int>(r.z)); ++x) {
      const std::uint8_t* p = &image.pixels[4 * (static_cast<std::size_t>(y) * image.width + x)];
      if (p[0] > 140 && p[1] < 90 && p[2] < 90) ++count;
    }
  }
  return count;
}

TEST_F(EditorHealth, TheWarningOfWeftRunShowsInThePlaybackPanel) {
  // One CG iteration against a tolerance no solve reaches: every solve fails while the sheet
  // looks finite and calm (sim/health_check.h: three failed solves in a row).
  json scene = session_->json();
  scene["solver"]["linear_solver"] = {{"type", "cg"}, {"tolerance", 1e-14}, {"max_iterations", 1}};
  const fs::path file = dir_.write("scenes/failing-solves.json", scene.dump(2));
  session_ = std::make_unique<EditorSession>(file);
  imgui_->frame(drawUi());
  EXPECT_FALSE(probe_.rects.count("play/health")) << "no warning before a step";

  session_->paused = false;
  for (int frame = 0; frame < 20 && !session_->unhealthy(); ++frame) {
    session_->advanceFrame(1.0 / 60.0);
    (void)session_->world();
  }
  session_->advanceFrame(0.0);  // the frame that collects the worker's report
  ASSERT_TRUE(session_->unhealthy().has_value()) << "the editor ran no health check";
  EXPECT_EQ(session_->unhealthy()->check, "linear-solve");

  // What `weft run` reports for the same scene: the same check on the same steps.
  const Scene parsed = loadScene(file);
  World headless(parsed);
  HealthCheck health(headless, stepsPerFrame(parsed));
  for (int s = 0; s < 20; ++s) {
    headless.step();
    if (!health.afterStep(headless)) break;
  }
  ASSERT_FALSE(health.healthy());
  EXPECT_EQ(healthWarning(*session_->unhealthy()), healthWarning(*health.failure()));
  EXPECT_NE(session_->status.find(healthWarning(*health.failure())), std::string::npos) << session_->status;

  imgui_->frame(drawUi());
  probe_.rects.clear();
  imgui_->frame(drawUi());
  ASSERT_TRUE(probe_.rects.count("play/health")) << "the playback panel shows no warning";
  EXPECT_GT(redPixels(imgui_->image(), probe_.rects.at("play/health")), 20) << "drawn in red";

  session_->reset();
  EXPECT_FALSE(session_->unhealthy().has_value()) << "a reset starts a fresh run";
}

// Found driving the window as an artist (the sword scene warns a few steps in): the warning,
// wrapped over six lines above the scrub bar, pushed the bar and the "cached frame N: an edit
// continues from here" note out of the Playback panel's view, so scrubbing back after a warning
// meant scrolling the panel first. Both stay in view with the warning shown, and so does it.
TEST_F(EditorHealth, WithAWarningTheScrubBarAndTheCachedFrameNoteStayInView) {
  json scene = session_->json();
  scene["solver"]["linear_solver"] = {{"type", "cg"}, {"tolerance", 1e-14}, {"max_iterations", 1}};
  session_ = std::make_unique<EditorSession>(dir_.write("scenes/failing-solves.json", scene.dump(2)));
  session_->paused = false;
  for (int frame = 0; frame < 40 && (!session_->unhealthy() || session_->liveFrame() < 4); ++frame) {
    session_->advanceFrame(1.0 / 30.0);
    (void)session_->world();
  }
  session_->advanceFrame(0.0);
  ASSERT_TRUE(session_->unhealthy().has_value());
  ASSERT_GE(session_->liveFrame(), 2);
  session_->showFrame(1);  // scrubbed back: paused on a cached frame
  ASSERT_TRUE(session_->shownFrame().has_value());
  imgui_->frame(drawUi());
  probe_.rects.clear();
  imgui_->frame(drawUi());
  ASSERT_TRUE(probe_.rects.count("play/panel"));
  const ImVec4 panel = probe_.rects.at("play/panel");
  for (const char* id : {"play/timeline", "play/live", "play/health"}) {
    ASSERT_TRUE(probe_.rects.count(id)) << id;
    const ImVec4 r = probe_.rects.at(id);
    EXPECT_GE(r.y, panel.y) << id;
    EXPECT_LE(r.w, panel.w) << id << " is below the panel's visible part (ends at " << r.w << ", the panel at " << panel.w << ")";
  }
}

}  // namespace
}  // namespace weft::test
