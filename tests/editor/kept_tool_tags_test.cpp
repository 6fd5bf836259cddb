// The sharp tags a user is editing on a tool are never dropped unseen (issue 21, found driving the
// editor): picking another tool in the Tools panel keeps the first one's unsaved tags and undo
// steps; a reset puts every tool's unsaved tags back into the world; the quit and open prompts ask
// about unsaved tags as about the scene's edits ("Save" writes the tags file, "Discard" does not,
// "Cancel" keeps everything). Headless, through the panels.
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
#include "editor/sharp_tag_edits.h"
#include "support/editor_panels_fixture.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::EditorPanelsTest;

class KeptToolTagsTest : public EditorPanelsTest {
 protected:
  // sword-into-sheet (6 x 6 cloth) with a hammer beside the sword, both meshes copied beside the
  // scene: their tags files are the test's own (tools/NAME.sharp.json there, not there yet).
  void SetUp() override {
    EditorPanelsTest::SetUp();
    if (IsSkipped()) return;
    const fs::path tools = dir_.path() / "scenes" / "tools";
    fs::create_directories(tools);
    for (const char* mesh : {"sword.obj", "hammer.obj"}) {
      fs::copy_file(fs::path(WEFT_SOURCE_DIR) / "assets" / "tools" / mesh, tools / mesh);
    }
    std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sword-into-sheet.json");
    json scene = json::parse(in);
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({6, 6});
    json hammer = scene["obstacles"][0];
    hammer["name"] = "hammer";
    hammer["shape"]["mesh"]["path"] = "tools/hammer.obj";
    scene["obstacles"].push_back(hammer);
    twoTools_ = dir_.write("scenes/two-tools.json", scene.dump(2));
    swordTags_ = tools / "sword.sharp.json";
    session_ = std::make_unique<EditorSession>(twoTools_);
    session_->paused = true;
    showToolsPanel();
  }

  // The Tools panel in front, with room for its combo's list.
  void showToolsPanel() {
    imgui_->frame([&] {
      ImGui::SetWindowPos("Tools", ImVec2(500, 200));
      ImGui::SetWindowSize("Tools", ImVec2(400, 300));
      ImGui::SetWindowFocus("Tools");
      drawUi()();
    });
    imgui_->frame(drawUi());
  }

  // Picks a tool in the Tools panel's combo, as the user does.
  void pickTool(int obstacle) {
    const std::string item = "tools/tool" + std::to_string(obstacle);
    probe_.rects.erase(item);
    imgui_->click(probe_.centre("tools/tool"), drawUi());
    imgui_->frame(drawUi());
    ASSERT_TRUE(probe_.rects.count(item)) << "the tool combo did not open";
    imgui_->click(probe_.centre(item), drawUi());
    imgui_->frame(drawUi());
    ASSERT_NE(currentTool(), nullptr) << session_->status;
    ASSERT_EQ(currentTool()->obstacle(), obstacle);
  }
  ToolTagEditor* currentTool() { return ui_.panels.tools.current(); }
  bool worldVertexSharp(int obstacle, int vertex) const {
    return session_->world().obstacle(obstacle).sharpVertex[static_cast<std::size_t>(vertex)];
  }
  static bool aPromptIsOpen() { return ImGui::GetCurrentContext()->OpenPopupStack.Size > 0; }
  // The sword with vertex 0 tagged and not saved; the scene itself has no unsaved edit.
  void tagTheSwordUnsaved() {
    pickTool(0);
    currentTool()->toggleVertex(*session_, 0);
    imgui_->frame(drawUi());
    ASSERT_TRUE(currentTool()->document().dirty());
    ASSERT_FALSE(session_->dirty());
  }

  fs::path twoTools_;
  fs::path swordTags_;
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
  ASSERT_TRUE(probe_.rects.count("tools/undo"));
  imgui_->click(probe_.centre("tools/undo"), drawUi());
  EXPECT_EQ(worldVertexSharp(0, 0), swordWasSharp) << "the sword's own undo step came back with it";
  EXPECT_FALSE(currentTool()->document().dirty());
  pickTool(1);
  EXPECT_TRUE(currentTool()->document().dirty()) << "and the hammer's tags are still there";
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
    imgui_->click(probe_.centre("tools/tool"), appFrame);
    imgui_->frame(appFrame);
    ASSERT_TRUE(probe_.rects.count("tools/tool0"));
    imgui_->click(probe_.centre("tools/tool0"), appFrame);
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
