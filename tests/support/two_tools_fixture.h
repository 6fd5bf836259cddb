#pragma once
// The editor's panels, headless, on a scene with two mesh tools to tag: sword-into-sheet (6 x 6
// cloth) with a second tool beside the sword (the hammer, unless a test asks for another mesh).
// The meshes are copied beside the scene, so their tags files are the test's own
// (scenes/tools/NAME.sharp.json, not there yet). Shared by the tests of tools' sharp tags: kept
// across picks, undone from any tool, autosaved and recovered, saved per obstacle.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <memory>
#include <string>

#include <imgui_internal.h>
#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/sharp_tag_edits.h"
#include "support/editor_panels_fixture.h"

namespace weft::test {

class TwoToolsPanelsTest : public EditorPanelsTest {
 protected:
  // The second tool: its name and the mesh it uses (from assets/tools).
  explicit TwoToolsPanelsTest(std::string secondTool = "hammer", std::string secondMesh = "hammer.obj")
      : secondTool_(std::move(secondTool)), secondMesh_(std::move(secondMesh)) {}

  void SetUp() override {
    EditorPanelsTest::SetUp();
    if (IsSkipped()) return;
    const fs::path tools = dir_.path() / "scenes" / "tools";
    fs::create_directories(tools);
    for (const std::string& mesh : {std::string("sword.obj"), secondMesh_}) {
      if (!fs::exists(tools / mesh)) fs::copy_file(fs::path(WEFT_SOURCE_DIR) / "assets" / "tools" / mesh, tools / mesh);
    }
    std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sword-into-sheet.json");
    json scene = json::parse(in);
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({6, 6});
    json second = scene["obstacles"][0];
    second["name"] = secondTool_;
    second["shape"]["mesh"]["path"] = "tools/" + secondMesh_;
    scene["obstacles"].push_back(second);
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

  // Picks a tool in the Tools panel's combo, as the user does, drawing with `draw` (the UI alone
  // unless given).
  void pickTool(int obstacle, std::function<void()> draw = {}) {
    if (!draw) draw = drawUi();
    const std::string item = "tools/tool" + std::to_string(obstacle);
    probe_.rects.erase(item);
    imgui_->click(probe_.centre("tools/tool"), draw);
    imgui_->frame(draw);
    ASSERT_TRUE(probe_.rects.count(item)) << "the tool combo did not open";
    imgui_->click(probe_.centre(item), draw);
    imgui_->frame(draw);
    ASSERT_NE(currentTool(), nullptr) << session().status;
    ASSERT_EQ(currentTool()->obstacle(), obstacle);
  }
  editor::ToolTagEditor* currentTool() { return ui_.panels.tools.current(); }
  // The session the UI edits: the fixture's own, unless a test moved it into a workspace.
  virtual EditorSession& session() { return *session_; }
  bool worldVertexSharp(int obstacle, int vertex) {
    return session().world().obstacle(obstacle).sharpVertex[static_cast<std::size_t>(vertex)];
  }
  static bool aPromptIsOpen() { return ImGui::GetCurrentContext()->OpenPopupStack.Size > 0; }

  std::string secondTool_;
  std::string secondMesh_;
  fs::path twoTools_;
  fs::path swordTags_;
};

}  // namespace weft::test
