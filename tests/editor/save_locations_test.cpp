// Saving lands where the user chose: "save as new preset" asks for the folder (remembered, created
// when missing) and warns before writing into Weft's installed presets; the sharp tags of a
// shipped tool go beside the scene unless the user explicitly changes the shipped file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/editor_settings.h"
#include "support/editor_panels_fixture.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::EditorPanelsTest;

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class SaveLocationsTest : public EditorPanelsTest {
 protected:
  // Opens the "save as new preset" dialog and types `name` into it.
  void openPresetDialog(const std::string& name) {
    imgui_->click(probe_.centre("material/saveas"), drawUi());
    imgui_->frame(drawUi());
    ASSERT_TRUE(probe_.rects.count("material/presetname")) << "no dialog";
    imgui_->click(probe_.centre("material/presetname"), drawUi());
    imgui_->typeAndEnter(name, drawUi());
  }

  // A copy of sword-into-sheet (8 x 8 cloth) beside the test's folder, its sword's first vertex's
  // tag toggled in the Tools panel and Save pressed: the dialog that asks where the tags of a
  // shipped tool go is open. Returns the vertex's tag before the toggle.
  bool toggleATagOfTheShippedSwordAndSave() {
    std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sword-into-sheet.json");
    json scene = json::parse(in);
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
    session_ = std::make_unique<EditorSession>(dir_.write("copied/sword-copy.json", scene.dump(2)));
    ui_.panels.tool.emplace(*session_, 0);
    ui_.panels.toolGeneration = session_->worldGeneration();
    const bool wasSharp = session_->world().obstacle(0).sharpVertex[kToggledVertex];
    ui_.panels.tool->toggleVertex(*session_, kToggledVertex);
    // The tools panel, grown and in front, so all its buttons are on screen.
    imgui_->frame([&] {
      ImGui::SetWindowPos("Tools", ImVec2(300, 300));
      ImGui::SetWindowSize("Tools", ImVec2(400, 400));
      ImGui::SetWindowFocus("Tools");
      drawUi()();
    });
    imgui_->frame(drawUi());
    imgui_->click(probe_.centre("tools/save"), drawUi());
    imgui_->frame(drawUi());
    return wasSharp;
  }
  static constexpr int kToggledVertex = 0;
  const fs::path shippedSwordTags_ = fs::path(WEFT_SOURCE_DIR) / "assets" / "tools" / "sword.sharp.json";
};

TEST_F(SaveLocationsTest, APresetGoesToTheChosenFolderWhichIsCreatedAndRemembered) {
  const fs::path materials = dir_.path() / "materials";  // the scene's ../materials, not there yet
  ASSERT_FALSE(fs::exists(materials));
  openPresetDialog("my-denim");
  EXPECT_EQ(fs::path(ui_.panels.presetFolder), materials) << "suggested: where the scene finds presets";
  imgui_->click(probe_.centre("material/savepreset"), drawUi());
  ASSERT_TRUE(fs::is_regular_file(materials / "my-denim.json")) << session_->status;
  EXPECT_EQ(session_->json()["cloths"][0]["material"], "my-denim") << "the scene uses it by name";
  EXPECT_EQ(session_->scene().cloths[0].material.name, "my-denim");
  EXPECT_EQ(ui_.panels.settings.materialPresetFolder, materials);
  EXPECT_FALSE(ui_.panels.presetDialog);

  // The settings survive a restart.
  const fs::path settingsFile = dir_.path() / "config" / "editor.json";
  saveEditorSettings(ui_.panels.settings, settingsFile);
  EXPECT_EQ(loadEditorSettings(settingsFile).materialPresetFolder, materials);
}

TEST_F(SaveLocationsTest, AFolderTheSceneDoesNotSearchKeepsTheMaterialInline) {
  const fs::path elsewhere = dir_.path() / "my presets" / "cloth";
  ui_.panels.settings.materialPresetFolder = elsewhere;  // chosen last time
  openPresetDialog("kept-inline");
  EXPECT_EQ(fs::path(ui_.panels.presetFolder), elsewhere) << "the remembered folder comes first";
  imgui_->click(probe_.centre("material/savepreset"), drawUi());
  ASSERT_TRUE(fs::is_regular_file(elsewhere / "kept-inline.json")) << session_->status;
  EXPECT_TRUE(session_->json()["cloths"][0]["material"].is_object() ||
              session_->json()["cloths"][0]["material"] != "kept-inline")
      << "a name the scene cannot find would make it unreadable";
}

TEST_F(SaveLocationsTest, WritingIntoTheInstalledPresetsNeedsTheUsersSayWithAWarning) {
  const fs::path installed = fs::path(WEFT_SOURCE_DIR) / "presets" / "materials";
  ui_.panels.settings.materialPresetFolder = installed;
  openPresetDialog("never-written-by-tests");
  ASSERT_TRUE(probe_.rects.count("material/writeinstalled")) << "no warning, no checkbox";
  imgui_->click(probe_.centre("material/savepreset"), drawUi());  // disabled until agreed
  EXPECT_FALSE(fs::exists(installed / "never-written-by-tests.json"));
  EXPECT_TRUE(ui_.panels.presetDialog) << "the dialog stays until the user decides";
}

TEST_F(SaveLocationsTest, AShippedToolsTagsAreSavedBesideTheSceneUnlessTheUserSaysOtherwise) {
  const fs::path& shipped = shippedSwordTags_;
  const std::string shippedBefore = readText(shipped);
  const int vertex = kToggledVertex;
  const bool wasSharp = toggleATagOfTheShippedSwordAndSave();
  ASSERT_TRUE(probe_.rects.count("tools/savebesidescene")) << "saving a shipped tool's tags asks where";
  EXPECT_EQ(readText(shipped), shippedBefore) << "nothing written before the user chose";
  imgui_->click(probe_.centre("tools/savebesidescene"), drawUi());

  const fs::path besideScene = dir_.path() / "copied" / "sword.sharp.json";
  ASSERT_TRUE(fs::is_regular_file(besideScene)) << session_->status;
  EXPECT_EQ(readText(shipped), shippedBefore) << "the shipped tags are untouched";
  EXPECT_EQ(session_->json()["obstacles"][0]["shape"]["mesh"]["sharp_tags"], "sword.sharp.json");
  session_->reset();  // the rebuilt world reads the tags from the scene's own file
  EXPECT_NE(session_->world().obstacle(0).sharpVertex[vertex], wasSharp);
}

// The user prefers the tags in the scene itself: no file is written, neither beside the scene nor
// into assets/; the scene's obstacle holds "sharp_tags": {...} and, saved and opened again, the
// world reads the tags from it.
TEST_F(SaveLocationsTest, AToolsTagsCanLiveInTheSceneItself) {
  const fs::path& shipped = shippedSwordTags_;
  const std::string shippedBefore = readText(shipped);
  const int vertex = kToggledVertex;
  const bool wasSharp = toggleATagOfTheShippedSwordAndSave();
  ASSERT_TRUE(probe_.rects.count("tools/saveinscene")) << "the dialog offers the scene itself";
  imgui_->click(probe_.centre("tools/saveinscene"), drawUi());

  const json& tags = session_->json()["obstacles"][0]["shape"]["mesh"]["sharp_tags"];
  ASSERT_TRUE(tags.is_object()) << session_->status;
  EXPECT_EQ(sharpTagsFromJson(tags).vertices, ui_.panels.tool->tags().vertices);
  EXPECT_FALSE(fs::exists(dir_.path() / "copied" / "sword.sharp.json")) << "no file beside the scene";
  EXPECT_EQ(readText(shipped), shippedBefore) << "the shipped tags are untouched";
  EXPECT_TRUE(ui_.panels.tool->inScene());
  EXPECT_FALSE(ui_.panels.tool->document().dirty());
  EXPECT_TRUE(session_->dirty()) << "the tags are a scene edit, saved with the scene";

  session_->save();
  EditorSession reopened(dir_.path() / "copied" / "sword-copy.json");
  EXPECT_NE(reopened.world().obstacle(0).sharpVertex[vertex], wasSharp) << "read from the scene";
  const ToolTagEditor again(reopened, 0);
  EXPECT_TRUE(again.inScene()) << "its next save goes to the scene again";
}

}  // namespace
}  // namespace weft::editor
