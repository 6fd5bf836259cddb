// Unsaved edits survive a crash, through the editor's own prompts (headless): an autosave of any
// scene is offered at start and again when its scene is opened, and it is deleted only after the
// user saved or explicitly discarded it. The issue's steps (edit, crash, start on another scene,
// open the edited one, Esc, quit) keep it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>

#include <imgui_internal.h>

#include "editor/autosave.h"
#include "editor/editor_workspace.h"
#include "editor/scene_edits.h"
#include "support/editor_panels_fixture.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::EditorPanelsTest;
using test::HeadlessImGui;

class CrashRecoveryTest : public EditorPanelsTest {
 protected:
  void SetUp() override {
    EditorPanelsTest::SetUp();
    if (IsSkipped()) return;
    edited_ = test::copyScene(dir_, "hanging-sheet", 6);
    // The editor that crashed: one edit, autosaved, then killed (nothing else ran).
    Autosave store(autosaveDir());
    EditorSession crashed(edited_);
    ASSERT_TRUE(crashed.edit(withWeftAngle(crashed.json(), 0, 30.0), "weft angle").accepted);
    crashed.autosave(store);
    ASSERT_TRUE(fs::exists(store.fileFor(edited_)));
  }
  fs::path autosaveDir() const { return dir_.path() / "autosave"; }
  bool autosaveExists() const { return fs::exists(Autosave(autosaveDir()).fileFor(edited_)); }

  // The editor started on `scene`, as the app's loop runs it: UI, then the user's choices.
  void start(const fs::path& scene) {
    workspace_ = std::make_unique<EditorWorkspace>(std::make_unique<EditorSession>(scene), Autosave(autosaveDir()), ui_);
    workspace_->session().paused = true;
    ui_.panels.probe = &probe_;
  }
  std::function<void()> appFrame() {
    return [this] {
      drawEditorUi(workspace_->session(), ui_);
      workspace_->applyChoices(ui_);
      workspace_->forgetAutosaveWhenClean(ui_.panels.tools);
    };
  }
  void frames(int n) {
    for (int i = 0; i < n; ++i) imgui_->frame(appFrame());
  }
  static bool aPromptIsOpen() { return ImGui::GetCurrentContext()->OpenPopupStack.Size > 0; }
  double weftAngle() { return workspace_->session().scene().cloths[0].weftAngleDeg; }

  fs::path edited_;
  std::unique_ptr<EditorWorkspace> workspace_;
};

TEST_F(CrashRecoveryTest, TheIssuesStepsOfferTheEditsTwiceAndKeepThem) {
  start(scene_);  // plain `weft`: another scene than the edited one
  ASSERT_EQ(ui_.recoveries.size(), 1u);
  frames(2);
  ASSERT_TRUE(aPromptIsOpen()) << "offered at start";
  ASSERT_TRUE(probe_.rects.count("recovery/later"));
  imgui_->tap(HeadlessImGui::kEscapeKey, appFrame());  // Esc: decide later
  frames(1);
  EXPECT_FALSE(aPromptIsOpen());
  EXPECT_TRUE(autosaveExists());

  ui_.panels.openRequest = edited_;  // Open X.json
  frames(3);
  ASSERT_EQ(workspace_->session().document().file(), edited_);
  EXPECT_DOUBLE_EQ(weftAngle(), 0.0) << "opened as saved on disk, until the user chooses";
  ASSERT_TRUE(aPromptIsOpen()) << "offered again when its scene is opened";
  imgui_->tap(HeadlessImGui::kEscapeKey, appFrame());  // Esc does not make the choice here
  frames(1);
  EXPECT_TRUE(aPromptIsOpen());

  ui_.quit = QuitPrompt::Asking;  // the window's close button
  frames(2);
  ASSERT_EQ(ui_.quit, QuitPrompt::Confirmed);
  workspace_->quitConfirmed();
  EXPECT_TRUE(autosaveExists()) << "quitting without choosing keeps the edits";
  EXPECT_DOUBLE_EQ(Autosave(autosaveDir()).find(edited_)->document["cloths"][0]["weft_angle_deg"], 30.0);
}

TEST_F(CrashRecoveryTest, AnotherScenesEditsOpenThatSceneWithThemUntilSaved) {
  start(scene_);
  frames(2);
  imgui_->click(probe_.centre("recovery/recover"), appFrame());  // "Open it with them"
  frames(2);
  ASSERT_EQ(workspace_->session().document().file(), edited_);
  EXPECT_DOUBLE_EQ(weftAngle(), 30.0);
  EXPECT_TRUE(workspace_->session().dirty()) << "recovered, not yet saved";
  EXPECT_FALSE(aPromptIsOpen());
  EXPECT_TRUE(autosaveExists());
  workspace_->session().save();
  frames(1);
  EXPECT_FALSE(autosaveExists()) << "saved: the autosave has done its job";
}

TEST_F(CrashRecoveryTest, TheOpenScenesEditsAreRecoveredOrDiscardedOnPurpose) {
  start(edited_);
  frames(2);
  ASSERT_TRUE(aPromptIsOpen());
  EXPECT_FALSE(probe_.rects.count("recovery/later")) << "the open scene's autosave must be settled";
  imgui_->click(probe_.centre("recovery/recover"), appFrame());
  EXPECT_DOUBLE_EQ(weftAngle(), 30.0);
  EXPECT_TRUE(workspace_->session().dirty());
  // Quitting and discarding the recovered edits at the prompt is the explicit discard.
  ui_.quit = QuitPrompt::Asking;
  frames(2);
  EXPECT_TRUE(autosaveExists()) << "the prompt waits";
  ui_.quit = QuitPrompt::Confirmed;  // "Discard and quit"
  workspace_->quitConfirmed();
  EXPECT_FALSE(autosaveExists());
}

TEST_F(CrashRecoveryTest, DiscardingAtThePromptRemovesIt) {
  start(scene_);
  frames(2);
  imgui_->click(probe_.centre("recovery/discard"), appFrame());
  EXPECT_FALSE(autosaveExists());
  EXPECT_TRUE(ui_.recoveries.empty());
  EXPECT_EQ(workspace_->session().document().file(), scene_) << "nothing else opened";
}

}  // namespace
}  // namespace weft::editor
