// The editor's panels driven headless: an ImGui context rendered through EGL, with simulated
// clicks and typing, changes the scene as the user meant. Skipped (with the reason) where EGL
// cannot start.
#include <gtest/gtest.h>

#include <GL/gl.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include <imgui_internal.h>

#include "editor/editor_session.h"
#include "editor/editor_ui.h"
#include "editor/editor_viewport.h"
#include "editor/scene_edits.h"
#include "headless_gl_context.h"
#include "render_view.h"
#include "scene_renderer.h"
#include "support/editor_panels_fixture.h"
#include "support/imgui_harness.h"
#include "support/snapshot.h"
#include "support/temp_dir.h"
#include "tearing/tear_table.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;
using test::EditorPanelsTest;
using test::kHeight;
using test::kWidth;

TEST_F(EditorPanelsTest, TypingATearTableEntryChangesTheRequiredStrength) {
  const TearTable before = *session_->scene().cloths[0].material.tearTable;
  ASSERT_EQ(before.strength.size(), 4u);
  ASSERT_NE(before.strength[2], 20.0);
  imgui_->click(probe_.centre("tear/2"), drawUi());
  imgui_->typeAndEnter("20", drawUi());
  const TearTable& after = *session_->scene().cloths[0].material.tearTable;
  EXPECT_DOUBLE_EQ(after.strength[2], 20.0) << session_->status;
  EXPECT_DOUBLE_EQ(after.strength[0], before.strength[0]);
  EXPECT_DOUBLE_EQ(requiredStrength(after, 90.0), 20.0 * after.unitNPerM);
  EXPECT_NE(requiredStrength(after, 90.0), requiredStrength(before, 90.0));
  ASSERT_TRUE(session_->world().scene().cloths[0].material.tearTable);
  EXPECT_DOUBLE_EQ(session_->world().scene().cloths[0].material.tearTable->strength[2], 20.0)
      << "the running simulation tears by the new table";
  EXPECT_TRUE(session_->dirty());
}

TEST_F(EditorPanelsTest, TheUndoButtonRestoresThePreviousValue) {
  const double before = session_->scene().cloths[0].material.tearTable->strength[1];
  imgui_->click(probe_.centre("tear/1"), drawUi());
  imgui_->typeAndEnter("7.5", drawUi());
  ASSERT_DOUBLE_EQ(session_->scene().cloths[0].material.tearTable->strength[1], 7.5) << session_->status;
  imgui_->click(probe_.centre("scene/undo"), drawUi());
  EXPECT_DOUBLE_EQ(session_->scene().cloths[0].material.tearTable->strength[1], before);
  EXPECT_FALSE(session_->dirty());
  imgui_->click(probe_.centre("scene/redo"), drawUi());
  EXPECT_DOUBLE_EQ(session_->scene().cloths[0].material.tearTable->strength[1], 7.5);
}

TEST_F(EditorPanelsTest, DraggingOnTheDialPointsTheWeftAtTheMouse) {
  const ImVec4 r = probe_.rects.at("weft/dial");
  const ImVec2 centre((r.x + r.z) / 2, (r.y + r.w) / 2);
  const float radius = 0.3f * (r.z - r.x);
  const double target = 30.0;
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = centre;
  imgui_->frame(drawUi());
  io.MouseDown[0] = true;
  imgui_->frame(drawUi());
  io.MousePos = ImVec2(centre.x + radius * static_cast<float>(std::cos(target * kPi / 180)),
                       centre.y - radius * static_cast<float>(std::sin(target * kPi / 180)));
  imgui_->frame(drawUi());
  io.MouseDown[0] = false;
  imgui_->frame(drawUi());
  EXPECT_NEAR(session_->scene().cloths[0].weftAngleDeg, target, 0.51);
  EXPECT_NEAR(session_->world().scene().cloths[0].weftAngleDeg, target, 0.51) << "applied live";
  // The whole drag is one undo step.
  session_->undo();
  EXPECT_DOUBLE_EQ(session_->scene().cloths[0].weftAngleDeg, 0.0);
}

TEST_F(EditorPanelsTest, AddingAndRemovingDirectionsResamplesTheTable) {
  const TearTable before = *session_->scene().cloths[0].material.tearTable;
  imgui_->click(probe_.centre("tear/more"), drawUi());
  const TearTable five = *session_->scene().cloths[0].material.tearTable;
  ASSERT_EQ(five.strength.size(), 5u) << session_->status;
  // Each new direction takes the old curve's value there.
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(five.strength[static_cast<std::size_t>(k)] * five.unitNPerM, requiredStrength(before, 36.0 * k), 1e-9) << k;
  }
  imgui_->click(probe_.centre("tear/fewer"), drawUi());
  imgui_->click(probe_.centre("tear/fewer"), drawUi());
  EXPECT_EQ(session_->scene().cloths[0].material.tearTable->strength.size(), 3u);
}

TEST_F(EditorPanelsTest, QuittingAsksFirstOnlyWhenThereAreUnsavedEdits) {
  ui_.quit = QuitPrompt::Asking;
  imgui_->frame(drawUi());
  EXPECT_EQ(ui_.quit, QuitPrompt::Confirmed) << "nothing to lose: no prompt";

  imgui_->click(probe_.centre("tear/0"), drawUi());
  imgui_->typeAndEnter("30", drawUi());
  ASSERT_TRUE(session_->dirty());
  ui_.quit = QuitPrompt::Asking;
  for (int i = 0; i < 3; ++i) imgui_->frame(drawUi());
  EXPECT_EQ(ui_.quit, QuitPrompt::Asking) << "the prompt waits for the user's choice";
  EXPECT_EQ(ImGui::GetCurrentContext()->OpenPopupStack.Size, 1) << "the unsaved-changes prompt is open";
}

TEST_F(EditorPanelsTest, UndoingTheSelectedClothsDuplicationKeepsThePanelsWorking) {
  ASSERT_TRUE(session_->edit(withClothDuplicated(session_->json(), 0, Vec3(0, 0, 0.3)), "duplicate").accepted);
  imgui_->frame(drawUi());
  imgui_->click(probe_.centre("scene/cloth1"), drawUi());
  ASSERT_EQ(ui_.panels.cloth, 1);
  session_->undo();
  imgui_->frame(drawUi());  // the material, tear table and weft panels draw cloth 0 again
  EXPECT_EQ(ui_.panels.cloth, 0);
  EXPECT_TRUE(session_->resetPending() || session_->world().clothCount() == 1);
}

// The editor at a fixed frame, panels and viewport, against a golden (tests/ui/snapshots/editor).
TEST_F(EditorPanelsTest, EditorSnapshotAtTheStart) {
  ui::SceneRenderer renderer;
  const ViewportRect rect = sceneViewport(kWidth, kHeight);
  const ui::OrbitCamera camera =
      ui::defaultCamera(ui::renderViewOf(session_->world()), session_->scene().output.camera, rect.aspect());
  ui_.panels.probe = nullptr;
  auto drawScene = [&] {
    drawSceneViewport(renderer, ui::renderViewOf(session_->world()), camera, rect, kWidth, kHeight);
  };
  for (int i = 0; i < 3; ++i) imgui_->frame(drawUi(), drawScene);  // windows settle their sizes
  const fs::path golden = fs::path(WEFT_SOURCE_DIR) / "tests" / "ui" / "snapshots" / "editor" / "start.png";
  EXPECT_EQ(test::checkSnapshot(imgui_->image(), golden), "");
}

}  // namespace
}  // namespace weft::editor
