// The sharp tags a user is editing on a tool are never dropped unseen (issue 21, found driving the
// editor): picking another tool in the Tools panel keeps the first one's unsaved tags and undo
// steps; a reset puts every tool's unsaved tags back into the world; the quit and open prompts ask
// about unsaved tags as about the scene's edits ("Save" writes the tags file, "Discard" does not,
// "Cancel" keeps everything); Ctrl+Z reaches every tool's tags. Headless, through the panels.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <imgui_internal.h>
#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/autosave.h"
#include "editor/editor_workspace.h"
#include "editor/menu_bar.h"
#include "editor/shared_undo.h"
#include "editor/sharp_tag_edits.h"
#include "support/two_tools_fixture.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::TwoToolsPanelsTest;

class KeptToolTagsTest : public TwoToolsPanelsTest {
 protected:
  // The sword with vertex 0 tagged and not saved; the scene itself has no unsaved edit.
  void tagTheSwordUnsaved() {
    pickTool(0);
    currentTool()->toggleVertex(*session_, 0);
    imgui_->frame(drawUi());
    ASSERT_TRUE(currentTool()->document().dirty());
    ASSERT_FALSE(session_->dirty());
  }
  // The UI with the app's key handling (editor_app.cpp calls applyEditShortcuts the same way).
  std::function<void()> drawUiAndKeys() {
    return [this] {
      drawEditorUi(*session_, ui_);
      if (!ImGui::GetIO().WantCaptureKeyboard) applyEditShortcuts(*session_, ui_.panels);
    };
  }
  void ctrlTap(int key) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = true;
    imgui_->tap(key, drawUiAndKeys());
    io.KeyCtrl = false;
    imgui_->frame(drawUiAndKeys());
  }
  static constexpr int kZKey = 300;  // free indices of io.KeysDown for the key map
  static constexpr int kYKey = 301;
};

TEST_F(KeptToolTagsTest, SwitchingToolsKeepsEachToolsUnsavedTagsAndUndo) {
  pickTool(0);
  const bool swordWasSharp = worldVertexSharp(0, 0);
  currentTool()->toggleVertex(*session_, 0);
  pickTool(1);
  currentTool()->toggleVertex(*session_, 1);
  pickTool(0);
  EXPECT_TRUE(currentTool()->document().dirty()) << "the sword's tags are still unsaved, not forgotten";
  EXPECT_NE(worldVertexSharp(0, 0), swordWasSharp);
  pickTool(1);
  EXPECT_TRUE(currentTool()->document().dirty()) << "and the hammer's tags are still there";
  // Both tools' undo steps are kept, in the one history: the hammer's (the latest), then the
  // sword's, whichever tool is picked.
  pickTool(0);
  ASSERT_TRUE(probe_.rects.count("tools/undo"));
  clickWidget("tools/undo", drawUi());
  EXPECT_EQ(currentTool()->name(), "hammer") << "the undo picked the tool it changed";
  EXPECT_FALSE(currentTool()->document().dirty());
  clickWidget("tools/undo", drawUi());
  EXPECT_EQ(worldVertexSharp(0, 0), swordWasSharp) << "the sword's own undo step came back with it";
  EXPECT_EQ(currentTool()->name(), "sword");
  EXPECT_FALSE(currentTool()->document().dirty());
}

// One history for every tool (shared_undo.h): Ctrl+Z after tagging the sword, picking the hammer
// and tagging it takes back the hammer's tag, then the sword's, making the sword the current tool
// so the user sees what changed; Ctrl+Y brings it back.
TEST_F(KeptToolTagsTest, CtrlZReachesTheTagsOfAToolNoLongerPicked) {
  ImGui::GetIO().KeyMap[ImGuiKey_Z] = kZKey;
  ImGui::GetIO().KeyMap[ImGuiKey_Y] = kYKey;
  pickTool(0);
  const bool swordWasSharp = worldVertexSharp(0, 0);
  currentTool()->toggleVertex(*session_, 0);
  pickTool(1);
  const bool hammerWasSharp = worldVertexSharp(1, 1);
  currentTool()->toggleVertex(*session_, 1);
  imgui_->frame(drawUiAndKeys());

  ctrlTap(kZKey);
  EXPECT_EQ(worldVertexSharp(1, 1), hammerWasSharp) << "the latest edit first: the hammer's";
  EXPECT_NE(worldVertexSharp(0, 0), swordWasSharp);
  EXPECT_EQ(latestUndoLabel(*session_, ui_.panels.tools), "toggle sharp vertex 0 on sword")
      << "the Edit menu names the tool the next undo changes";

  ctrlTap(kZKey);
  EXPECT_EQ(worldVertexSharp(0, 0), swordWasSharp) << "the sword's tag, though the hammer is picked: " << session_->status;
  ASSERT_NE(currentTool(), nullptr);
  EXPECT_EQ(currentTool()->name(), "sword") << "the Tools panel shows the tool the undo changed";
  EXPECT_NE(session_->status.find("sword"), std::string::npos) << session_->status;
  EXPECT_FALSE(currentTool()->document().dirty());

  ctrlTap(kYKey);
  EXPECT_NE(worldVertexSharp(0, 0), swordWasSharp) << "Ctrl+Y redoes it";
  EXPECT_TRUE(currentTool()->document().dirty());
}

// A reset rebuilds the world from the files: each tool's unsaved tags go back in, not only the
// current tool's.
TEST_F(KeptToolTagsTest, AResetPutsBackEveryToolsUnsavedTags) {
  pickTool(0);
  const bool swordWasSharp = worldVertexSharp(0, 0);
  currentTool()->toggleVertex(*session_, 0);
  pickTool(1);
  session_->reset();
  imgui_->frame(drawUi());
  EXPECT_NE(worldVertexSharp(0, 0), swordWasSharp) << "the sword is not the current tool, its tags still apply";
}

TEST_F(KeptToolTagsTest, TheQuitPromptAsksAboutUnsavedTagsAndSaveWritesTheirFile) {
  tagTheSwordUnsaved();
  ui_.quit = QuitPrompt::Asking;
  imgui_->frame(drawUi());
  imgui_->frame(drawUi());
  EXPECT_EQ(ui_.quit, QuitPrompt::Asking) << "unsaved tags: the prompt waits for the user";
  ASSERT_TRUE(aPromptIsOpen());
  EXPECT_EQ(ui_.panels.tools.unsavedToolNames(), std::vector<std::string>{"sword"}) << "the prompt names the tool";
  ASSERT_TRUE(probe_.rects.count("unsaved/save"));
  imgui_->click(probe_.centre("unsaved/save"), drawUi());
  EXPECT_EQ(ui_.quit, QuitPrompt::Confirmed) << session_->status;
  ASSERT_TRUE(fs::is_regular_file(swordTags_)) << session_->status;
  std::ifstream in(swordTags_);
  EXPECT_EQ(sharpTagsFromJson(json::parse(in)).vertices, currentTool()->tags().vertices);
  EXPECT_FALSE(currentTool()->document().dirty());
}

// Esc asks to quit (app/editor_app.cpp sets the prompt going in the frame of the press): with
// unsaved tags the prompt must then stay up, and a second Esc answers it as Cancel.
TEST_F(KeptToolTagsTest, EscWithUnsavedTagsOpensTheQuitPromptAndASecondEscCancelsIt) {
  tagTheSwordUnsaved();
  ui_.quit = QuitPrompt::Asking;  // what the Esc below asked for, in its own frame
  imgui_->tap(test::HeadlessImGui::kEscapeKey, drawUi());
  imgui_->frame(drawUi());
  EXPECT_EQ(ui_.quit, QuitPrompt::Asking) << "the Esc that opened the prompt must not also cancel it";
  EXPECT_TRUE(aPromptIsOpen());
  imgui_->tap(test::HeadlessImGui::kEscapeKey, drawUi());
  EXPECT_EQ(ui_.quit, QuitPrompt::None);
  EXPECT_TRUE(currentTool()->document().dirty());
}

TEST_F(KeptToolTagsTest, CancelAtTheQuitPromptKeepsTheTagsAndDiscardWritesNothing) {
  tagTheSwordUnsaved();
  ui_.quit = QuitPrompt::Asking;
  imgui_->frame(drawUi());
  imgui_->frame(drawUi());
  ASSERT_TRUE(probe_.rects.count("unsaved/cancel"));
  imgui_->click(probe_.centre("unsaved/cancel"), drawUi());
  EXPECT_EQ(ui_.quit, QuitPrompt::None);
  EXPECT_TRUE(currentTool()->document().dirty());
  ui_.quit = QuitPrompt::Asking;
  imgui_->frame(drawUi());
  imgui_->frame(drawUi());
  imgui_->click(probe_.centre("unsaved/discard"), drawUi());
  EXPECT_EQ(ui_.quit, QuitPrompt::Confirmed);
  EXPECT_FALSE(fs::exists(swordTags_));
}

// Opening another scene: the prompt asks; Cancel keeps the scene and the tags, Discard opens the
// other scene without writing the tags, and Save writes them before opening it.
TEST_F(KeptToolTagsTest, TheOpenPromptAsksAboutUnsavedTags) {
  const fs::path other = test::copyScene(dir_, "hanging-sheet", 6);
  EditorWorkspace workspace(std::move(session_), Autosave(dir_.path() / "autosave"), ui_);
  auto appFrame = [&] {
    drawEditorUi(workspace.session(), ui_);
    workspace.applyChoices(ui_);
  };
  auto pickAndTag = [&] {
    probe_.rects.erase("tools/tool0");
    clickWidget("tools/tool", appFrame);
    imgui_->frame(appFrame);
    ASSERT_TRUE(probe_.rects.count("tools/tool0"));
    clickWidget("tools/tool0", appFrame);
    ASSERT_NE(currentTool(), nullptr);
    currentTool()->toggleVertex(workspace.session(), 0);
    imgui_->frame(appFrame);
  };
  pickAndTag();
  ui_.panels.openRequest = other;
  imgui_->frame(appFrame);
  imgui_->frame(appFrame);
  ASSERT_TRUE(aPromptIsOpen()) << "unsaved tags: opening another scene asks first";
  EXPECT_EQ(workspace.session().document().file(), twoTools_);
  imgui_->click(probe_.centre("unsaved/cancel"), appFrame);
  imgui_->frame(appFrame);
  EXPECT_EQ(workspace.session().document().file(), twoTools_);
  ASSERT_NE(currentTool(), nullptr);
  EXPECT_TRUE(currentTool()->document().dirty()) << "Cancel keeps the tags";

  ui_.panels.openRequest = other;
  imgui_->frame(appFrame);
  imgui_->frame(appFrame);
  ASSERT_TRUE(aPromptIsOpen());
  imgui_->click(probe_.centre("unsaved/discard"), appFrame);
  imgui_->frame(appFrame);
  EXPECT_EQ(workspace.session().document().file(), other);
  EXPECT_FALSE(fs::exists(swordTags_)) << "discarded: nothing written";
  EXPECT_EQ(currentTool(), nullptr);
  EXPECT_TRUE(ui_.panels.tools.unsavedToolNames().empty()) << "the old scene's tools are gone with it";

  // Back to the two tools, tag again, and Save, then open.
  ui_.panels.openRequest = twoTools_;
  for (int i = 0; i < 3; ++i) imgui_->frame(appFrame);
  ASSERT_EQ(workspace.session().document().file(), twoTools_);
  pickAndTag();
  ui_.panels.openRequest = other;
  imgui_->frame(appFrame);
  imgui_->frame(appFrame);
  ASSERT_TRUE(aPromptIsOpen());
  imgui_->click(probe_.centre("unsaved/save"), appFrame);
  imgui_->frame(appFrame);
  EXPECT_EQ(workspace.session().document().file(), other) << workspace.session().status;
  EXPECT_TRUE(fs::is_regular_file(swordTags_)) << "saved before the other scene opened";
}

}  // namespace
}  // namespace weft::editor
