// A tool's unsaved sharp tags survive a crash as the scene's edits do (issue 21): the autosave
// keeps every tool's unsaved tags, those kept in files of their own and those kept in the scene;
// after a kill, the next start offers them with the scene (at start, and again when that scene is
// opened), recovering brings them back as unsaved edits of their tools, and the autosave goes only
// once they are saved (or discarded on purpose). Headless, through the panels and the workspace as
// the app's loop drives them.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "editor/autosave.h"
#include "editor/editor_workspace.h"
#include "support/two_tools_fixture.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::HeadlessImGui;
using test::TwoToolsPanelsTest;

class ToolTagsCrashRecoveryTest : public TwoToolsPanelsTest {
 protected:
  fs::path autosaveDir() const { return dir_.path() / "autosave"; }
  bool autosaveExists() const { return fs::exists(Autosave(autosaveDir()).fileFor(twoTools_)); }
  EditorSession& session() override { return workspace_ ? workspace_->session() : *session_; }

  // The editor started on `scene`, as the app starts it.
  void start(const fs::path& scene) {
    workspace_ = std::make_unique<EditorWorkspace>(std::make_unique<EditorSession>(scene), Autosave(autosaveDir()), ui_);
    workspace_->session().paused = true;
  }
  // kill -9: nothing of the running editor is kept but what it wrote (no quit, no prompt).
  void kill() {
    ui_.panels.tools.clear();
    ui_.recoveries.clear();
    ui_.recoveryChoice = RecoveryChoice::Undecided;
    ui_.quit = QuitPrompt::None;
    ui_.open = OpenPrompt::None;
    ui_.openRecovered.reset();
    workspace_.reset();
  }
  // One frame of the app's loop: the UI, the user's choices, the autosave's upkeep.
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
  const ToolTagEditor* keptTool(const std::string& name) const {
    for (const ToolTagEditor* tool : ui_.panels.tools.editors()) {
      if (tool->name() == name) return tool;
    }
    return nullptr;
  }

  std::unique_ptr<EditorWorkspace> workspace_;
};

// The sword's tags live in their own file (tools/sword.sharp.json): a tag, the timed autosave, a
// kill; the restart on that scene offers them, and Recover brings them back, unsaved.
TEST_F(ToolTagsCrashRecoveryTest, TagsInTheirOwnFileAreAutosavedAndRecovered) {
  start(twoTools_);
  frames(1);
  pickTool(0, appFrame());
  const bool swordWasSharp = worldVertexSharp(0, 0);
  currentTool()->toggleVertex(session(), 0);
  frames(1);
  ASSERT_FALSE(session().dirty()) << "only the tags are unsaved";
  workspace_->writeAutosave(ui_.panels.tools);  // the app's timed write
  frames(1);
  ASSERT_TRUE(autosaveExists()) << "unsaved tags alone are worth an autosave";
  kill();
  ASSERT_FALSE(fs::exists(swordTags_));

  start(twoTools_);
  ASSERT_EQ(ui_.recoveries.size(), 1u) << "offered at start";
  ASSERT_EQ(ui_.recoveries.front().toolTags.size(), 1u);
  EXPECT_EQ(ui_.recoveries.front().toolTags.front().tool, "sword");
  frames(2);
  ASSERT_TRUE(aPromptIsOpen());
  EXPECT_EQ(worldVertexSharp(0, 0), swordWasSharp) << "as saved on disk until the user chooses";
  imgui_->click(probe_.centre("recovery/recover"), appFrame());
  frames(1);
  const ToolTagEditor* sword = keptTool("sword");
  ASSERT_NE(sword, nullptr) << session().status;
  EXPECT_TRUE(sword->document().dirty()) << "recovered, not yet saved";
  EXPECT_EQ(sword->tags().vertices.empty(), swordWasSharp);
  EXPECT_NE(worldVertexSharp(0, 0), swordWasSharp) << "the world shows the recovered tags";
  EXPECT_TRUE(autosaveExists()) << "kept until the tags are saved";
  EXPECT_FALSE(fs::exists(swordTags_));

  ui_.panels.tools.saveUnsaved(session());  // the quit prompt's Save
  frames(1);
  ASSERT_TRUE(fs::is_regular_file(swordTags_));
  EXPECT_FALSE(autosaveExists()) << "saved: the autosave has done its job";
}

// Started on another scene, "Open it with them" opens the tagged scene with the sword's tags.
TEST_F(ToolTagsCrashRecoveryTest, OpeningAnotherScenesAutosaveBringsItsToolsTags) {
  start(twoTools_);
  frames(1);
  pickTool(0, appFrame());
  const bool swordWasSharp = worldVertexSharp(0, 0);
  currentTool()->toggleVertex(session(), 0);
  workspace_->writeAutosave(ui_.panels.tools);
  kill();

  start(scene_);
  frames(2);
  ASSERT_TRUE(aPromptIsOpen());
  imgui_->click(probe_.centre("recovery/recover"), appFrame());  // "Open it with them"
  frames(2);
  ASSERT_EQ(session().document().file(), twoTools_);
  const ToolTagEditor* sword = keptTool("sword");
  ASSERT_NE(sword, nullptr) << session().status;
  EXPECT_TRUE(sword->document().dirty());
  EXPECT_NE(worldVertexSharp(0, 0), swordWasSharp);
  EXPECT_NE(session().status.find("sharp tags"), std::string::npos) << session().status;
  EXPECT_TRUE(autosaveExists());
}

// An autosave's tags that the mesh cannot have (a vertex it lacks) are not recovered, and said so;
// the scene and its other work still are.
TEST_F(ToolTagsCrashRecoveryTest, TagsTheMeshCannotHaveAreSkippedAndNamed) {
  const JsonDocument clean = JsonDocument::open(twoTools_);
  Autosave(autosaveDir()).write(clean, {UnsavedToolTags{0, "sword", swordTags_, false, json{{"sharp_vertices", {999999}}}}});
  start(twoTools_);
  frames(2);
  ASSERT_TRUE(aPromptIsOpen());
  imgui_->click(probe_.centre("recovery/recover"), appFrame());
  frames(1);
  EXPECT_TRUE(ui_.panels.tools.unsavedToolNames().empty());
  EXPECT_NE(session().status.find("autosaved tags of sword were not recovered"), std::string::npos) << session().status;
}

// The hammer's tags kept in the scene itself: tagged after the scene was saved, then a kill. The
// restart on another scene offers them; "Later" keeps them, opening the scene offers them again,
// and Recover opens it with the hammer's tags as they were.
TEST_F(ToolTagsCrashRecoveryTest, TagsKeptInTheSceneAreOfferedAtStartAndWhenTheSceneIsOpened) {
  start(twoTools_);
  frames(1);
  pickTool(1, appFrame());
  clickWidget("tools/inscene", appFrame());  // "In the scene"
  ASSERT_TRUE(currentTool()->inScene()) << session().status;
  session().save();
  frames(1);
  const bool hammerWasSharp = worldVertexSharp(1, 2);
  currentTool()->toggleVertex(session(), 2);
  frames(1);
  ASSERT_FALSE(session().dirty());
  workspace_->writeAutosave(ui_.panels.tools);
  ASSERT_TRUE(autosaveExists());
  kill();

  start(scene_);  // plain `weft`: another scene
  ASSERT_EQ(ui_.recoveries.size(), 1u);
  frames(2);
  ASSERT_TRUE(aPromptIsOpen()) << "offered at start";
  imgui_->tap(HeadlessImGui::kEscapeKey, appFrame());  // Later
  frames(1);
  EXPECT_TRUE(autosaveExists());

  ui_.panels.openRequest = twoTools_;
  frames(3);
  ASSERT_EQ(session().document().file(), twoTools_);
  ASSERT_TRUE(aPromptIsOpen()) << "offered again when its scene is opened";
  imgui_->click(probe_.centre("recovery/recover"), appFrame());
  frames(1);
  const ToolTagEditor* hammer = keptTool("hammer");
  ASSERT_NE(hammer, nullptr) << session().status;
  EXPECT_TRUE(hammer->inScene());
  EXPECT_TRUE(hammer->document().dirty());
  EXPECT_NE(worldVertexSharp(1, 2), hammerWasSharp) << session().status;
  EXPECT_TRUE(autosaveExists());

  // Quitting and discarding them at the prompt is the explicit discard.
  ui_.quit = QuitPrompt::Asking;
  frames(2);
  ASSERT_TRUE(aPromptIsOpen()) << "the unsaved tags are asked about";
  imgui_->click(probe_.centre("unsaved/discard"), appFrame());
  ASSERT_EQ(ui_.quit, QuitPrompt::Confirmed);
  workspace_->quitConfirmed();
  EXPECT_FALSE(autosaveExists());
}

}  // namespace
}  // namespace weft::editor
