// Saving lands where the user chose: "save as new preset" asks for the folder (remembered, created
// when missing) and warns before writing into Weft's installed presets; the sharp tags of a
// shipped tool go beside the scene unless the user explicitly changes the shipped file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <imgui_internal.h>
#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/editor_settings.h"
#include "editor/scene_edits.h"
#include "editor/sharp_tag_edits.h"
#include "support/editor_panels_fixture.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::EditorPanelsTest;
using test::HeadlessImGui;

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
  // With `secondSword`, the scene has a second obstacle of that name on the same shipped mesh, so
  // reading the same shipped tags file.
  bool toggleATagOfTheShippedSwordAndSave(const std::string& secondSword = "") {
    std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sword-into-sheet.json");
    json scene = json::parse(in);
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
    if (!secondSword.empty()) {
      json second = scene["obstacles"][0];
      second["name"] = secondSword;
      scene["obstacles"].push_back(second);
    }
    session_ = std::make_unique<EditorSession>(dir_.write("copied/sword-copy.json", scene.dump(2)));
    ui_.panels.tools.select(*session_, 0);
    const bool wasSharp = session_->world().obstacle(0).sharpVertex[kToggledVertex];
    ui_.panels.tools.current()->toggleVertex(*session_, kToggledVertex);
    // The tools panel, grown and in front, so all its buttons are on screen.
    imgui_->frame([&] {
      ImGui::SetWindowPos("Tools", ImVec2(300, 300));
      ImGui::SetWindowSize("Tools", ImVec2(400, 400));
      ImGui::SetWindowFocus("Tools");
      drawUi()();
    });
    imgui_->frame(drawUi());
    clickWidget("tools/save", drawUi());
    imgui_->frame(drawUi());
    return wasSharp;
  }
  static constexpr int kToggledVertex = 0;
  const fs::path shippedSwordTags_ = fs::path(WEFT_SOURCE_DIR) / "assets" / "tools" / "sword.sharp.json";
};

// Save (the button, File > Save, Ctrl+S) on a scene shipped with Weft does not write over it, as
// Ctrl+S on the default scene did: the "Save scene as" dialog opens, saying why, with a copy in
// ~/weft/scenes suggested; saving there creates the folder, and Save then writes the copy.
// The shipped folder here is $WEFT_DATA_DIR's, a copy in the test's folder.
TEST_F(SaveLocationsTest, SavingAShippedSceneAsksWhereTheUsersVersionGoes) {
  const fs::path data = dir_.path() / "data";
  fs::create_directories(data / "presets" / "scenes");
  const fs::path shipped = data / "presets" / "scenes" / "shipped.json";
  fs::copy_file(scene_, shipped);
  const std::string shippedBytes = readText(shipped);
  setenv("WEFT_DATA_DIR", data.c_str(), 1);
  const char* home = std::getenv("HOME");
  const std::string oldHome = home != nullptr ? home : "";
  setenv("HOME", (dir_.path() / "home").c_str(), 1);
  session_ = std::make_unique<EditorSession>(shipped);
  ASSERT_TRUE(session_->savesIntoInstalledData());
  ASSERT_TRUE(session_->edit(withWeftAngle(session_->json(), 0, 20.0), "weft angle").accepted);
  EXPECT_THROW(session_->save(), std::runtime_error) << "the session itself refuses";

  imgui_->frame(drawUi());
  imgui_->click(probe_.centre("scene/save"), drawUi());
  imgui_->frame(drawUi());
  EXPECT_EQ(readText(shipped), shippedBytes) << "the shipped scene is untouched";
  EXPECT_FALSE(fs::exists(fs::path(shipped) += ".bak"));
  EXPECT_EQ(ImGui::GetCurrentContext()->OpenPopupStack.Size, 1) << "the dialog asks where the user's version goes";
  const fs::path suggested = dir_.path() / "home" / "weft" / "scenes" / "shipped.json";
  EXPECT_EQ(fs::path(ui_.panels.saveAsPath), suggested);
  EXPECT_NE(session_->status.find("ships with Weft"), std::string::npos) << session_->status;

  imgui_->frame(drawUi());  // the dialog's field takes the keyboard
  imgui_->tap(HeadlessImGui::kEnterKey, drawUi());  // the suggested file
  imgui_->frame(drawUi());
  unsetenv("WEFT_DATA_DIR");
  setenv("HOME", oldHome.c_str(), 1);
  EXPECT_EQ(session_->document().file(), suggested);
  EXPECT_FALSE(session_->dirty());
  EXPECT_EQ(json::parse(readText(suggested))["cloths"][0]["weft_angle_deg"], 20.0);
  EXPECT_EQ(readText(shipped), shippedBytes);
  ASSERT_TRUE(session_->edit(withWeftAngle(session_->json(), 0, 25.0), "weft angle").accepted);
  EXPECT_FALSE(session_->resetPending()) << "saved elsewhere, a weft edit still applies live";
  saveScene(*session_, ui_.panels);  // the user's own file now: saved in place
  EXPECT_FALSE(ui_.panels.saveAsRequested);
  EXPECT_EQ(json::parse(readText(suggested))["cloths"][0]["weft_angle_deg"], 25.0);
}

// The sharp tags of a shipped tool in a shipped scene: "beside the scene" would be Weft's own
// presets folder, so it is refused (the dialog offers it disabled); kept in the scene, they go
// with the user's version of it (Save as).
// Found driving the window: File > Save as... opened on an empty field, so an artist typed a
// whole path from nothing. It starts on the scene's own file (edit the name, press Enter).
TEST_F(SaveLocationsTest, SaveAsStartsOnTheScenesOwnFile) {
  ASSERT_EQ(ui_.panels.saveAsPath[0], '\0');
  imgui_->frame(drawUi());
  imgui_->click(probe_.centre("menu/file"), drawUi());
  ASSERT_TRUE(probe_.rects.count("menu/saveas")) << "the File menu did not open";
  imgui_->click(probe_.centre("menu/saveas"), drawUi());
  imgui_->frame(drawUi());
  EXPECT_TRUE(ui_.saveAsDialog);
  EXPECT_EQ(fs::path(ui_.panels.saveAsPath), session_->document().file());
  imgui_->frame(drawUi());  // the dialog's field takes the keyboard
  ASSERT_TRUE(session_->edit(withWeftAngle(session_->json(), 0, 20.0), "weft angle").accepted);
  imgui_->tap(HeadlessImGui::kEnterKey, drawUi());  // as suggested: the scene saved in place
  imgui_->frame(drawUi());
  EXPECT_FALSE(session_->dirty());
  EXPECT_EQ(json::parse(readText(scene_))["cloths"][0]["weft_angle_deg"], 20.0);
}

TEST_F(SaveLocationsTest, AShippedScenesToolTagsAreNotSavedBesideIt) {
  const fs::path data = dir_.path() / "data";
  fs::create_directories(data / "presets" / "scenes");
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sword-into-sheet.json");
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
  const fs::path shipped = data / "presets" / "scenes" / "sword.json";
  std::ofstream(shipped) << scene.dump(2);
  const std::string shippedBytes = readText(shipped);
  setenv("WEFT_DATA_DIR", data.c_str(), 1);
  session_ = std::make_unique<EditorSession>(shipped);
  ToolTagEditor tool(*session_, 0);
  tool.toggleVertex(*session_, 0);
  EXPECT_THROW(tool.saveBesideScene(*session_), std::runtime_error);
  EXPECT_FALSE(fs::exists(data / "presets" / "scenes" / "sword.sharp.json"));
  EXPECT_EQ(readText(shipped), shippedBytes);
  tool.saveInScene(*session_);
  EXPECT_TRUE(session_->dirty()) << "the tags are in the scene, to be saved with it";
  saveScene(*session_, ui_.panels);
  EXPECT_TRUE(ui_.panels.saveAsRequested) << "the scene is shipped: Save as";
  EXPECT_EQ(readText(shipped), shippedBytes);
  unsetenv("WEFT_DATA_DIR");
}

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
  clickWidget("tools/savebesidescene", drawUi());

  const fs::path besideScene = dir_.path() / "copied" / "sword.sharp.json";
  ASSERT_TRUE(fs::is_regular_file(besideScene)) << session_->status;
  EXPECT_EQ(readText(shipped), shippedBefore) << "the shipped tags are untouched";
  EXPECT_EQ(session_->json()["obstacles"][0]["shape"]["mesh"]["sharp_tags"], "sword.sharp.json");
  session_->reset();  // the rebuilt world reads the tags from the scene's own file
  EXPECT_NE(session_->world().obstacle(0).sharpVertex[vertex], wasSharp);
}

// The dialog says what each choice writes, naming the file. "Change the shipped file" follows the
// per-obstacle rule: with another obstacle of the scene on the same shipped tags file, it writes
// this obstacle's own file beside the scene instead, and the dialog says that, not that the
// shipped file changes.
TEST_F(SaveLocationsTest, TheShippedToolDialogNamesTheFileEachChoiceWrites) {
  const std::string shippedBefore = readText(shippedSwordTags_);
  toggleATagOfTheShippedSwordAndSave("sword-2");
  ASSERT_TRUE(probe_.rects.count("tools/saveshipped")) << "the dialog is open";
  const std::string changeShipped = probe_.texts["tools/saveshippedtext"];
  const fs::path own = dir_.path() / "copied" / "sword-copy.sword.sharp.json";
  EXPECT_NE(changeShipped.find("sword-2"), std::string::npos) << "names the other reader: " << changeShipped;
  EXPECT_NE(changeShipped.find(own.string()), std::string::npos) << "names the file written: " << changeShipped;
  EXPECT_NE(changeShipped.find("instead"), std::string::npos) << changeShipped;
  // sword.sharp.json beside the scene is free (sword-2 reads the shipped one): Save beside names it.
  const std::string beside = probe_.texts["tools/besidescenetext"];
  EXPECT_NE(beside.find((dir_.path() / "copied" / "sword.sharp.json").string()), std::string::npos) << beside;

  clickWidget("tools/saveshipped", drawUi());
  EXPECT_TRUE(fs::is_regular_file(own)) << "what the dialog said was written: " << session_->status;
  EXPECT_EQ(readText(shippedSwordTags_), shippedBefore) << "the shipped file is left as it is";
}

// With no other obstacle on the shipped file, "Change the shipped file" says it writes that file.
TEST_F(SaveLocationsTest, TheShippedToolDialogSaysChangingTheShippedFileWritesIt) {
  toggleATagOfTheShippedSwordAndSave();
  ASSERT_TRUE(probe_.rects.count("tools/saveshipped"));
  const std::string changeShipped = probe_.texts["tools/saveshippedtext"];
  EXPECT_NE(changeShipped.find(shippedSwordTags_.string()), std::string::npos) << changeShipped;
  EXPECT_EQ(changeShipped.find("instead"), std::string::npos) << changeShipped;
}

// Saving beside the scene points the obstacle's "sharp_tags" at the new file, which holds exactly
// the tags the world's sword has: the switch changes nothing in the world, so tagging goes on
// without a reset, and the next save writes the new file.
TEST_F(SaveLocationsTest, TaggingGoesOnWithoutAResetAfterTheTagsAreSavedBesideTheScene) {
  const bool wasSharp = toggleATagOfTheShippedSwordAndSave();
  clickWidget("tools/savebesidescene", drawUi());
  const fs::path besideScene = dir_.path() / "copied" / "sword.sharp.json";
  ASSERT_TRUE(fs::is_regular_file(besideScene)) << session_->status;
  EXPECT_FALSE(session_->resetPending()) << session_->status;
  probe_.rects.erase("tools/tagmode");
  imgui_->frame(drawUi());
  EXPECT_TRUE(probe_.rects.count("tools/tagmode")) << "the Tools panel does not ask for a reset";
  EXPECT_EQ(session_->world().scene().obstacles[0].shape.sharpTagsPath.filename(), "sword.sharp.json")
      << "the running world records where its tags come from now";
  EXPECT_NE(session_->world().obstacle(0).sharpVertex[kToggledVertex], wasSharp) << "the tags did not change";

  ToolTagEditor& tool = *ui_.panels.tools.current();
  tool.toggleVertex(*session_, 1);
  const bool vertex1 = session_->world().obstacle(0).sharpVertex[1];
  const SharpTags tagged = tool.tags();  // a copy: begin and end of one vector
  EXPECT_EQ(vertex1, std::binary_search(tagged.vertices.begin(), tagged.vertices.end(), 1))
      << "the next tag reaches the world";
  clickWidget("tools/save", drawUi());
  EXPECT_EQ(sharpTagsFromJson(json::parse(readText(besideScene))).vertices, tool.tags().vertices)
      << "saved into the scene's own file now, no dialog: " << session_->status;
  // A later live edit still applies live (the world's scene and the editor's agree).
  session_->edit(withGravity(session_->json(), Vec3(0.0, -5.0, 0.0)), "gravity");
  EXPECT_FALSE(session_->resetPending()) << session_->status;
}

// A "sharp_tags" file whose tags are not the world's still needs a reset: the switch would change
// what the tool cuts with.
TEST_F(SaveLocationsTest, PointingAToolAtOtherTagsStillNeedsAReset) {
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sword-into-sheet.json");
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
  session_ = std::make_unique<EditorSession>(dir_.write("copied/sword-copy.json", scene.dump(2)));
  SharpTags other;
  other.vertices = {2};
  std::ofstream(dir_.path() / "copied" / "other.sharp.json") << sharpTagsJson(other).dump(2);
  session_->edit(withSharpTagsFile(session_->json(), 0, "other.sharp.json"), "other tags");
  EXPECT_TRUE(session_->resetPending()) << session_->status;
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
  clickWidget("tools/saveinscene", drawUi());

  const json& tags = session_->json()["obstacles"][0]["shape"]["mesh"]["sharp_tags"];
  ASSERT_TRUE(tags.is_object()) << session_->status;
  EXPECT_EQ(sharpTagsFromJson(tags).vertices, ui_.panels.tools.current()->tags().vertices);
  EXPECT_FALSE(fs::exists(dir_.path() / "copied" / "sword.sharp.json")) << "no file beside the scene";
  EXPECT_EQ(readText(shipped), shippedBefore) << "the shipped tags are untouched";
  EXPECT_TRUE(ui_.panels.tools.current()->inScene());
  EXPECT_FALSE(ui_.panels.tools.current()->document().dirty());
  EXPECT_TRUE(session_->dirty()) << "the tags are a scene edit, saved with the scene";

  session_->save();
  EditorSession reopened(dir_.path() / "copied" / "sword-copy.json");
  EXPECT_NE(reopened.world().obstacle(0).sharpVertex[vertex], wasSharp) << "read from the scene";
  const ToolTagEditor again(reopened, 0);
  EXPECT_TRUE(again.inScene()) << "its next save goes to the scene again";
}

}  // namespace
}  // namespace weft::editor
