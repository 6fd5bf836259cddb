// The small things an artist notices (issue 21, item 10), headless: Esc answers an open prompt
// instead of quitting, the Open field selects its text when clicked, the polar plot's axis labels
// are drawn inside the plot, scenes open with a hint of what to press.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include <imgui_internal.h>

#include "editor/editor_viewport.h"
#include "editor/scene_edits.h"
#include "editor/panels/preset_names.h"
#include "support/editor_panels_fixture.h"
#include "support/temp_dir.h"

namespace weft::editor {
namespace {

using test::EditorPanelsTest;
using test::HeadlessImGui;

TEST_F(EditorPanelsTest, EscClosesTheUnsavedChangesPromptInsteadOfQuitting) {
  ASSERT_TRUE(session_->edit(withWeftAngle(session_->json(), 0, 15.0), "weft angle").accepted);
  ui_.quit = QuitPrompt::Asking;
  imgui_->frame(drawUi());
  ASSERT_EQ(ImGui::GetCurrentContext()->OpenPopupStack.Size, 1);
  imgui_->tap(HeadlessImGui::kEscapeKey, drawUi());
  imgui_->frame(drawUi());
  EXPECT_EQ(ui_.quit, QuitPrompt::None) << "Esc is the prompt's Cancel";
  EXPECT_EQ(ImGui::GetCurrentContext()->OpenPopupStack.Size, 0);
  EXPECT_TRUE(session_->dirty());
}

TEST_F(EditorPanelsTest, TheOpenFieldSelectsItsTextWhenClicked) {
  imgui_->click(probe_.centre("scene/openpath"), drawUi());
  imgui_->typeAndEnter("first/path.json", drawUi());
  imgui_->click(probe_.centre("tear/plot"), drawUi());  // elsewhere
  imgui_->click(probe_.centre("scene/openpath"), drawUi());
  imgui_->typeAndEnter("other.json", drawUi());
  EXPECT_EQ(std::string(ui_.panels.openPath), "other.json") << "typing replaced the old path";
}

// Pixels of the weft axis' blue (40, 90, 200) in a rectangle.
long long bluePixels(const test::RgbaImage& image, int x0, int y0, int x1, int y1) {
  long long count = 0;
  for (int y = std::max(y0, 0); y < std::min(y1, image.height); ++y) {
    for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x) {
      const std::uint8_t* p = &image.pixels[4 * (static_cast<std::size_t>(y) * image.width + x)];
      if (p[2] > p[0] + 60 && p[2] > p[1] + 30) ++count;
    }
  }
  return count;
}

TEST_F(EditorPanelsTest, ThePolarPlotsLabelsAreInsideThePlot) {
  imgui_->frame(drawUi());
  const ImVec4 plot = probe_.rects.at("tear/plot");
  const int cy = static_cast<int>(0.5f * (plot.y + plot.w));
  const test::RgbaImage image = imgui_->image();
  // "weft" is written above the weft axis' right end, which points along screen x here.
  EXPECT_GT(bluePixels(image, static_cast<int>(plot.z) - 40, static_cast<int>(plot.y), static_cast<int>(plot.z), cy - 3), 15)
      << "no weft label inside the plot";
  EXPECT_EQ(bluePixels(image, static_cast<int>(plot.z) + 1, static_cast<int>(plot.y), static_cast<int>(plot.z) + 8, cy - 3), 0)
      << "the label runs out of the plot";
}

// The timeline's memory line (frames, copies, MB of the budget, the change log) is wrapped to
// the Playback panel's width: in the narrow left column it ran past the edge, the budget cut off.
TEST_F(EditorPanelsTest, TheTimelinesMemoryLineFitsThePlaybackPanel) {
  imgui_->frame(drawUi());
  ASSERT_TRUE(probe_.rects.count("play/cache") && probe_.rects.count("play/timeline"));
  const ImVec4 line = probe_.rects.at("play/cache");
  const ImVec4 bar = probe_.rects.at("play/timeline");  // as wide as the panel's content
  EXPECT_LE(line.z, bar.z + 1.0f) << "the line runs out of the panel";
  EXPECT_GT(line.w - line.y, 1.5f * ImGui::GetTextLineHeight()) << "wrapped onto more lines";
}

TEST_F(EditorPanelsTest, AScenePausedAtTheStartShowsWhatToPress) {
  auto darkPixelsOverTheViewport = [&] {
    const test::RgbaImage image = imgui_->image();
    long long count = 0;
    for (int y = 20; y < 50; ++y) {
      for (int x = kLeftColumnWidth + 10; x < test::kWidth - kRightColumnWidth - 10; ++x) {
        const std::uint8_t* p = &image.pixels[4 * (static_cast<std::size_t>(y) * image.width + x)];
        if (p[0] < 80 && p[1] < 80 && p[2] < 80) ++count;
      }
    }
    return count;
  };
  imgui_->frame(drawUi());
  EXPECT_GT(darkPixelsOverTheViewport(), 100) << "no hint";
  session_->paused = false;
  session_->advanceFrame(1.0 / 30.0);
  imgui_->frame(drawUi());
  EXPECT_EQ(darkPixelsOverTheViewport(), 0) << "the hint goes once the scene plays";
}

}  // namespace
}  // namespace weft::editor

namespace weft::editor {
namespace {

TEST_F(EditorPanelsTest, TheMenuBarHoldsUndoAndFramingWithTheirShortcuts) {
  ASSERT_TRUE(session_->edit(withWeftAngle(session_->json(), 0, 15.0), "weft angle").accepted);
  imgui_->frame(drawUi());
  imgui_->click(probe_.centre("menu/edit"), drawUi());
  ASSERT_TRUE(probe_.rects.count("menu/undo")) << "the Edit menu did not open";
  imgui_->click(probe_.centre("menu/undo"), drawUi());
  EXPECT_DOUBLE_EQ(session_->scene().cloths[0].weftAngleDeg, 0.0) << "Edit > Undo undid the edit";
  imgui_->click(probe_.centre("menu/view"), drawUi());
  ASSERT_TRUE(probe_.rects.count("menu/frame"));
  imgui_->click(probe_.centre("menu/frame"), drawUi());
  EXPECT_TRUE(ui_.frameScene) << "View > Frame the scene asks the app to frame it";
}

}  // namespace
}  // namespace weft::editor

namespace weft::editor {
namespace {

TEST_F(EditorPanelsTest, FFramesTheSelectedObstacleOrTheSceneKeepingTheViewDirection) {
  ui::OrbitCamera current;
  current.yawDeg = 75.0;
  current.pitchDeg = 10.0;
  const ui::RenderView view = ui::renderViewOf(session_->world());
  ASSERT_FALSE(view.obstacles.empty());
  const ui::OrbitCamera ball = frameSelection(view, 0, current, 1.5);
  Vec3 lo = Vec3::Constant(1e30), hi = Vec3::Constant(-1e30);
  for (const Vec3& v : view.obstacles[0].vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  EXPECT_LT((ball.target - 0.5 * (lo + hi)).norm(), 1e-9) << "looks at the selected ball";
  EXPECT_DOUBLE_EQ(ball.yawDeg, 75.0);
  EXPECT_DOUBLE_EQ(ball.pitchDeg, 10.0);
  const ui::OrbitCamera scene = frameSelection(view, -1, current, 1.5);
  EXPECT_GT(scene.distance, 2.0 * ball.distance) << "the whole scene is farther than the ball alone";
}

}  // namespace
}  // namespace weft::editor

namespace weft::editor {
namespace {

// The scene list's tooltip (issue 21, item 8): each scene's own description, nothing for a file
// that is not a readable scene.
TEST(SceneList, EachSceneShowsItsDescription) {
  const std::filesystem::path scenes = std::filesystem::path(WEFT_SOURCE_DIR) / "presets" / "scenes";
  const std::string hanging = sceneDescription(scenes / "hanging-sheet.json");
  EXPECT_EQ(hanging.rfind("A 1 m square of royal-target", 0), 0u) << hanging;
  EXPECT_NE(sceneDescription(scenes / "ball-into-sheet-table4.1-cloth2.json").find("ball"), std::string::npos);
  test::TempDir dir;
  EXPECT_EQ(sceneDescription(dir.write("twice.json", R"({"description": "a", "description": "b"})")), "");
  EXPECT_EQ(sceneDescription(dir.path() / "missing.json"), "");
}

}  // namespace
}  // namespace weft::editor
