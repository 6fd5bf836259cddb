// A tool's kept tag editor belongs to its obstacle, not to an index (issue 21, follow-up): removing
// an obstacle before a tagged tool in the Scene panel, or an obstacle coming in before it, leaves
// the tool's unsaved tags, undo steps, autosave entry and save with that tool. A removed tool's
// editor goes with it, and comes back with its unsaved tags when the removal is undone. Headless,
// through the panels.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/scene_edits.h"
#include "editor/shared_undo.h"
#include "editor/sharp_tag_edits.h"
#include "support/two_tools_fixture.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::TwoToolsPanelsTest;

class ObstacleTagEditorsTest : public TwoToolsPanelsTest {
 protected:
  // Scene panel: select obstacle `obstacle` in the list and press Remove, as the user does.
  void removeInScenePanel(int obstacle) {
    // The Scene panel grown and in front, so its obstacle list and Remove are on screen.
    imgui_->frame([&] {
      ImGui::SetWindowPos("Scene", ImVec2(10, 30));
      ImGui::SetWindowSize("Scene", ImVec2(420, 800));
      ImGui::SetWindowFocus("Scene");
      drawUi()();
    });
    imgui_->frame(drawUi());
    const std::string item = "scene/obstacle" + std::to_string(obstacle);
    ASSERT_TRUE(probe_.rects.count(item)) << "the Scene panel lists the obstacle";
    imgui_->click(probe_.centre(item), drawUi());
    ASSERT_EQ(ui_.panels.obstacle, obstacle);
    ASSERT_TRUE(probe_.rects.count("scene/remove"));
    imgui_->click(probe_.centre("scene/remove"), drawUi());
    imgui_->frame(drawUi());
  }
  std::vector<std::string> sceneObstacleNames() {
    std::vector<std::string> names;
    for (const ObstacleSpec& spec : session_->scene().obstacles) names.push_back(spec.name);
    return names;
  }
  const ToolTagEditor* editorNamed(const std::string& name) {
    for (const ToolTagEditor* tool : ui_.panels.tools.editors()) {
      if (tool->name() == name) return tool;
    }
    return nullptr;
  }
  fs::path hammerTags() const { return twoTools_.parent_path() / "tools" / "hammer.sharp.json"; }
};

// The hammer (obstacle 1) tagged and not saved; the sword (obstacle 0) removed. The hammer's editor
// is obstacle 0's now: the Tools panel, the autosave, a reset and Save tags all reach the hammer.
TEST_F(ObstacleTagEditorsTest, RemovingAnObstacleBeforeATaggedToolKeepsTheTagsWithTheTool) {
  pickTool(1);
  const bool hammerWasSharp = worldVertexSharp(1, 1);
  currentTool()->toggleVertex(*session_, 1);
  removeInScenePanel(0);
  ASSERT_EQ(sceneObstacleNames(), (std::vector<std::string>{"hammer"})) << session_->status;

  ASSERT_NE(currentTool(), nullptr) << "the hammer is still the tool picked";
  EXPECT_EQ(currentTool()->name(), "hammer");
  EXPECT_EQ(currentTool()->obstacle(), 0) << "its editor follows it to its new index";
  EXPECT_TRUE(currentTool()->document().dirty());
  const std::vector<UnsavedToolTags> autosaved = ui_.panels.tools.unsavedTags();
  ASSERT_EQ(autosaved.size(), 1u);
  EXPECT_EQ(autosaved[0].obstacle, 0) << "the autosave names the hammer's index now";
  EXPECT_EQ(autosaved[0].tool, "hammer");

  session_->reset();
  imgui_->frame(drawUi());
  EXPECT_EQ(session_->status.find("dropped"), std::string::npos) << session_->status;
  EXPECT_NE(worldVertexSharp(0, 1), hammerWasSharp) << "the reset put the hammer's unsaved tag back, on the hammer";
  ASSERT_NE(currentTool(), nullptr);
  EXPECT_TRUE(currentTool()->document().dirty());

  ui_.panels.tools.saveUnsaved(*session_);
  ASSERT_TRUE(fs::is_regular_file(hammerTags())) << session_->status;
  std::ifstream in(hammerTags());
  const SharpTags saved = sharpTagsFromJson(json::parse(in));
  EXPECT_EQ(std::binary_search(saved.vertices.begin(), saved.vertices.end(), 1), !hammerWasSharp);
  EXPECT_FALSE(session_->json()["obstacles"][0]["shape"]["mesh"].contains("sharp_tags")) << "no scene edit was needed";
}

// The sword and the hammer both tagged, then the sword removed: its editor goes with it (out of
// the Undo, the autosave and the prompts). Undoing the removal brings it back at its index with its
// unsaved tags, and the next undos take back the hammer's tag, then the sword's, each on its tool.
TEST_F(ObstacleTagEditorsTest, UndoingARemovalBringsBackTheRemovedToolsUnsavedTags) {
  pickTool(0);
  const bool swordWasSharp = worldVertexSharp(0, 0);
  currentTool()->toggleVertex(*session_, 0);
  pickTool(1);
  const bool hammerWasSharp = worldVertexSharp(1, 1);
  currentTool()->toggleVertex(*session_, 1);
  removeInScenePanel(0);
  EXPECT_EQ(ui_.panels.tools.unsavedToolNames(), (std::vector<std::string>{"hammer"}))
      << "the sword's tags went with the sword";
  ASSERT_NE(editorNamed("hammer"), nullptr);
  EXPECT_EQ(editorNamed("hammer")->obstacle(), 0);
  EXPECT_EQ(latestUndoLabel(*session_, ui_.panels.tools), "remove obstacle");

  undoLatest(*session_, ui_.panels.tools);
  imgui_->frame(drawUi());
  ASSERT_EQ(sceneObstacleNames(), (std::vector<std::string>{"sword", "hammer"})) << session_->status;
  ASSERT_NE(editorNamed("sword"), nullptr) << "the sword's editor came back with the sword";
  EXPECT_EQ(editorNamed("sword")->obstacle(), 0);
  EXPECT_TRUE(editorNamed("sword")->document().dirty());
  ASSERT_NE(editorNamed("hammer"), nullptr);
  EXPECT_EQ(editorNamed("hammer")->obstacle(), 1);
  const std::vector<UnsavedToolTags> autosaved = ui_.panels.tools.unsavedTags();
  ASSERT_EQ(autosaved.size(), 2u);
  EXPECT_EQ(autosaved[0].tool, "sword");
  EXPECT_EQ(autosaved[0].obstacle, 0);
  EXPECT_EQ(autosaved[1].tool, "hammer");
  EXPECT_EQ(autosaved[1].obstacle, 1);
  EXPECT_FALSE(session_->resetPending()) << "the world still has both tools: " << session_->status;

  undoLatest(*session_, ui_.panels.tools);
  EXPECT_EQ(worldVertexSharp(1, 1), hammerWasSharp) << "the hammer's tag, on the hammer: " << session_->status;
  EXPECT_NE(worldVertexSharp(0, 0), swordWasSharp);
  undoLatest(*session_, ui_.panels.tools);
  EXPECT_EQ(worldVertexSharp(0, 0), swordWasSharp) << "then the sword's: " << session_->status;
  EXPECT_TRUE(ui_.panels.tools.unsavedToolNames().empty());
}

// An obstacle coming in before a tagged tool (here a sphere put first by hand, as an undo of its
// removal would) moves the tool's editor down with it; one added at the end moves nothing.
TEST_F(ObstacleTagEditorsTest, AnObstacleAddedBeforeATaggedToolMovesItsEditorWithIt) {
  pickTool(1);
  const bool hammerWasSharp = worldVertexSharp(1, 1);
  currentTool()->toggleVertex(*session_, 1);
  json scene = withObstacleAdded(session_->json(), "sphere", Vec3(0.0, 2.0, 0.0), 0.1);  // at the end
  ASSERT_TRUE(session_->edit(scene, "add sphere").accepted) << session_->status;
  imgui_->frame(drawUi());
  EXPECT_EQ(currentTool()->obstacle(), 1) << "added after it: the hammer stays where it is";

  json first = session_->json();
  json sphere = first["obstacles"].back();
  first["obstacles"].erase(first["obstacles"].size() - 1);
  first["obstacles"].insert(first["obstacles"].begin(), sphere);
  ASSERT_TRUE(session_->edit(first, "sphere first").accepted) << session_->status;
  imgui_->frame(drawUi());
  ASSERT_NE(currentTool(), nullptr);
  EXPECT_EQ(currentTool()->name(), "hammer");
  EXPECT_EQ(currentTool()->obstacle(), 2);
  ASSERT_EQ(ui_.panels.tools.unsavedTags().size(), 1u);
  EXPECT_EQ(ui_.panels.tools.unsavedTags()[0].obstacle, 2);

  session_->reset();
  imgui_->frame(drawUi());
  EXPECT_NE(worldVertexSharp(2, 1), hammerWasSharp) << "the hammer's unsaved tag, on the hammer: " << session_->status;
}

}  // namespace
}  // namespace weft::editor
