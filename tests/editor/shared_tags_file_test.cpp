// Sharp tags are per obstacle (issue 21): two obstacles of one scene on one mesh read one tags file
// (tools/sword.sharp.json), and saving the tags edited on one must not change the other's unseen.
// Save tags writes the edited obstacle's tags to a file of its own beside the scene and points its
// "sharp_tags" there; the shared file, and so the other obstacle, stay as they were. Once no other
// obstacle reads the file, Save tags writes it as before. Headless, through the Tools panel.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/sharp_tag_edits.h"
#include "support/two_tools_fixture.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::TwoToolsPanelsTest;

json readJson(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

class SharedTagsFileTest : public TwoToolsPanelsTest {
 protected:
  // Two swords, "sword" and "sword-2", on tools/sword.obj, whose tags file tags vertex 5.
  SharedTagsFileTest() : TwoToolsPanelsTest("sword-2", "sword.obj") {}
  void SetUp() override {
    TwoToolsPanelsTest::SetUp();
    if (IsSkipped()) return;
    SharpTags shared;
    shared.vertices = {5};
    std::ofstream(swordTags_) << sharpTagsJson(shared).dump(2);
    session_ = std::make_unique<EditorSession>(twoTools_);  // reads the file now there
    session_->paused = true;
    imgui_->frame(drawUi());
    ASSERT_TRUE(worldVertexSharp(0, 5));
    ASSERT_TRUE(worldVertexSharp(1, 5));
  }
  void clickSaveTags() {
    ASSERT_TRUE(probe_.rects.count("tools/save"));
    clickWidget("tools/save", drawUi());
  }
};

TEST_F(SharedTagsFileTest, SavingOneObstaclesTagsLeavesTheOtherObstaclesFileAlone) {
  const json sharedBefore = readJson(swordTags_);
  pickTool(1);
  currentTool()->toggleVertex(*session_, 0);
  clickSaveTags();
  EXPECT_EQ(readJson(swordTags_), sharedBefore) << "the file sword reads too is unchanged: " << session_->status;
  EXPECT_NE(session_->status.find("sword"), std::string::npos) << "the status says why: " << session_->status;

  // sword-2's own file, beside the scene, named for it; the scene points there (unsaved).
  const fs::path own = twoTools_.parent_path() / "two-tools.sword-2.sharp.json";
  ASSERT_TRUE(fs::is_regular_file(own)) << session_->status;
  EXPECT_EQ(sharpTagsFromJson(readJson(own)).vertices, (std::vector<int>{0, 5}));
  EXPECT_EQ(session_->json()["obstacles"][1]["shape"]["mesh"]["sharp_tags"], "two-tools.sword-2.sharp.json");
  EXPECT_FALSE(session_->json()["obstacles"][0]["shape"]["mesh"].contains("sharp_tags"));
  EXPECT_TRUE(session_->dirty()) << "the scene's pointer is saved with the scene";
  EXPECT_FALSE(currentTool()->document().dirty());

  // Read back as the next session reads it: each sword its own tags.
  session_->save();
  EditorSession reopened(twoTools_);
  EXPECT_FALSE(reopened.world().obstacle(0).sharpVertex[0]) << "sword did not get sword-2's tag";
  EXPECT_TRUE(reopened.world().obstacle(0).sharpVertex[5]);
  EXPECT_TRUE(reopened.world().obstacle(1).sharpVertex[0]);
  EXPECT_TRUE(reopened.world().obstacle(1).sharpVertex[5]);

  // Now sword alone reads tools/sword.sharp.json: its Save tags writes it, as for any tool.
  session_->reset();  // the new "sharp_tags" is read when the world is rebuilt
  imgui_->frame(drawUi());
  pickTool(0);
  currentTool()->toggleVertex(*session_, 1);
  clickSaveTags();
  EXPECT_EQ(sharpTagsFromJson(readJson(swordTags_)).vertices, (std::vector<int>{1, 5})) << session_->status;
  EXPECT_EQ(sharpTagsFromJson(readJson(own)).vertices, (std::vector<int>{0, 5})) << "and sword-2's stays its own";
}

// The quit and open prompts' Save follows the same rule (ToolTagEditors::saveUnsaved).
TEST_F(SharedTagsFileTest, ThePromptsSaveKeepsTagsPerObstacleToo) {
  const json sharedBefore = readJson(swordTags_);
  pickTool(0);
  currentTool()->toggleVertex(*session_, 0);
  ui_.panels.tools.saveUnsaved(*session_);
  EXPECT_EQ(readJson(swordTags_), sharedBefore);
  const fs::path own = twoTools_.parent_path() / "two-tools.sword.sharp.json";
  ASSERT_TRUE(fs::is_regular_file(own)) << session_->status;
  EXPECT_EQ(session_->json()["obstacles"][0]["shape"]["mesh"]["sharp_tags"], "two-tools.sword.sharp.json");
}

}  // namespace
}  // namespace weft::editor
