// One undo history for the scene's edits and a tool's sharp tags (shared_undo.h): whichever kind
// of edit came last is undone first, from the Edit menu, Ctrl+Z and the panels' buttons alike,
// and a new edit of either kind forgets what both could have redone.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/edit_history.h"
#include "editor/editor_session.h"
#include "editor/menu_bar.h"
#include "editor/scene_edits.h"
#include "editor/shared_undo.h"
#include "editor/sharp_tag_edits.h"
#include "support/editor_panels_fixture.h"
#include "support/temp_dir.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json littleDoc(int value) { return {{"value", value}}; }

TEST(EditHistory, OnASharedClockACommitInOneHistoryForgetsWhatTheOtherCouldRedo) {
  EditHistory scene(littleDoc(0));
  EditHistory tags(littleDoc(0));
  tags.shareClock(scene.clock());
  tags.commit(littleDoc(1), "tag");
  tags.undo();
  ASSERT_TRUE(tags.canRedo());
  scene.commit(littleDoc(2), "gravity");  // a new line of edits
  EXPECT_FALSE(tags.canRedo()) << "the tag undone before the gravity edit is not redone after it";
  EXPECT_EQ(tags.redoLabel(), "");
  scene.undo();
  EXPECT_FALSE(tags.canRedo()) << "undoing the newer edit does not bring the forgotten one back";
  EXPECT_TRUE(scene.canRedo());
}

TEST(EditHistory, TicksOrderTheStepsOfHistoriesOnOneClock) {
  EditHistory scene(littleDoc(0));
  EditHistory tags(littleDoc(0));
  tags.shareClock(scene.clock());
  EXPECT_EQ(scene.undoTick(), 0u);
  tags.commit(littleDoc(1), "tag");
  scene.commit(littleDoc(1), "gravity");
  EXPECT_GT(scene.undoTick(), tags.undoTick()) << "the gravity edit came last";
  scene.undo();
  tags.undo();
  EXPECT_GT(tags.redoTick(), scene.redoTick()) << "the tag was undone last";
}

// The sword scene (a mesh tool whose sharp tags can be edited), small.
class SharedUndo : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sword-into-sheet.json");
    json scene = json::parse(in);
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({6, 6});
    session_ = std::make_unique<EditorSession>(dir_.write("scenes/sword.json", scene.dump(2)));
    tool_ = std::make_unique<ToolTagEditor>(*session_, 0);
    edge_ = session_->world().obstacle(0).topology.edges.front();
    startTagged_ = hasEdge(tool_->tags());
  }
  bool hasEdge(const SharpTags& tags) const {
    for (const auto& e : tags.edges) {
      if (e == edge_) return true;
    }
    return false;
  }
  bool edgeTagged() const { return hasEdge(tool_->tags()); }
  double gravityY() const { return session_->scene().forces.gravity.y(); }
  void editGravity(double y) {
    ASSERT_TRUE(session_->edit(withGravity(session_->json(), Vec3(0.0, y, 0.0)), "gravity").accepted);
  }

  test::TempDir dir_;
  std::unique_ptr<EditorSession> session_;
  std::unique_ptr<ToolTagEditor> tool_;
  std::array<int, 2> edge_{};
  bool startTagged_ = false;
};

TEST_F(SharedUndo, ATagThenAParameterEditAreUndoneInReverseOrderAndRedoneInOrder) {
  const double g0 = gravityY();
  tool_->toggleEdge(*session_, edge_);
  editGravity(-3.0);
  ASSERT_NE(edgeTagged(), startTagged_);
  EXPECT_EQ(latestUndoLabel(*session_, tool_.get()), "gravity");

  undoLatest(*session_, tool_.get());
  EXPECT_DOUBLE_EQ(gravityY(), g0) << "the parameter edit, the latest, is undone first";
  EXPECT_NE(edgeTagged(), startTagged_) << "the tag stays until the next undo";
  EXPECT_EQ(latestUndoLabel(*session_, tool_.get()).rfind("toggle sharp edge", 0), 0u);

  undoLatest(*session_, tool_.get());
  EXPECT_EQ(edgeTagged(), startTagged_) << "then the tag";
  EXPECT_DOUBLE_EQ(gravityY(), g0);
  EXPECT_FALSE(canUndoLatest(*session_, tool_.get()));
  const Obstacle& sword = session_->world().obstacle(0);
  long long sharpInWorld = 0;
  for (auto s : sword.sharpEdge) sharpInWorld += s ? 1 : 0;
  EXPECT_EQ(sharpInWorld, static_cast<long long>(tool_->tags().edges.size())) << "the world follows the undo";

  redoLatest(*session_, tool_.get());
  EXPECT_NE(edgeTagged(), startTagged_) << "redo replays the tag first";
  EXPECT_DOUBLE_EQ(gravityY(), g0);
  redoLatest(*session_, tool_.get());
  EXPECT_DOUBLE_EQ(gravityY(), -3.0) << "then the parameter edit";
  EXPECT_FALSE(canRedoLatest(*session_, tool_.get()));
}

TEST_F(SharedUndo, AParameterEditThenATagAreUndoneInReverseOrder) {
  const double g0 = gravityY();
  editGravity(-3.0);
  tool_->toggleEdge(*session_, edge_);
  undoLatest(*session_, tool_.get());
  EXPECT_EQ(edgeTagged(), startTagged_) << "the tag, the latest, first";
  EXPECT_DOUBLE_EQ(gravityY(), -3.0);
  undoLatest(*session_, tool_.get());
  EXPECT_DOUBLE_EQ(gravityY(), g0);
}

TEST_F(SharedUndo, ANewEditOfEitherKindForgetsWhatBothCouldRedo) {
  tool_->toggleEdge(*session_, edge_);
  editGravity(-3.0);
  undoLatest(*session_, tool_.get());
  undoLatest(*session_, tool_.get());
  ASSERT_TRUE(canRedoLatest(*session_, tool_.get()));
  editGravity(-5.0);
  EXPECT_FALSE(canRedoLatest(*session_, tool_.get())) << "the undone tag belongs to the abandoned line of edits";
  redoLatest(*session_, tool_.get());
  EXPECT_EQ(edgeTagged(), startTagged_);
  EXPECT_DOUBLE_EQ(gravityY(), -5.0);
}

TEST_F(SharedUndo, WithoutAToolItIsTheScenesUndo) {
  const double g0 = gravityY();
  editGravity(-3.0);
  EXPECT_EQ(latestUndoLabel(*session_, nullptr), "gravity");
  undoLatest(*session_, nullptr);
  EXPECT_DOUBLE_EQ(gravityY(), g0);
  EXPECT_FALSE(canUndoLatest(*session_, nullptr));
  undoLatest(*session_, nullptr);  // nothing left: no-op
  EXPECT_DOUBLE_EQ(gravityY(), g0);
}

}  // namespace
}  // namespace weft::editor

// The same through the editor's UI, headless: the Edit menu, Ctrl+Z and the Tools panel's button.
namespace weft::test {
namespace {

using editor::ToolTagEditor;

class SharedUndoPanels : public EditorPanelsTest {
 protected:
  void SetUp() override {
    EditorPanelsTest::SetUp();
    if (IsSkipped()) return;
    session_ = std::make_unique<EditorSession>(copyScene(dir_, "sword-into-sheet", 6));
    session_->paused = true;
    ui_.panels.tools.select(*session_, 0);
    edge_ = session_->world().obstacle(0).topology.edges.front();
    startTagged_ = edgeTagged();
    g0_ = session_->scene().forces.gravity.y();
    ImGui::GetIO().KeyMap[ImGuiKey_Z] = kZKey;
    ImGui::GetIO().KeyMap[ImGuiKey_Y] = kYKey;
    imgui_->frame(drawUi());
  }
  bool edgeTagged() const {
    for (const auto& e : ui_.panels.tools.current()->tags().edges) {
      if (e == edge_) return true;
    }
    return false;
  }
  // A tag clicked, then a parameter edited: what an artist does before pressing Ctrl+Z twice.
  void tagThenEditGravity() {
    ui_.panels.tools.current()->toggleEdge(*session_, edge_);
    ASSERT_TRUE(session_->edit(editor::withGravity(session_->json(), Vec3(0.0, -3.0, 0.0)), "gravity").accepted);
    ASSERT_NE(edgeTagged(), startTagged_);
    imgui_->frame(drawUi());
  }
  // The UI with the app's key handling (editor_app.cpp calls applyEditShortcuts the same way).
  std::function<void()> drawUiAndKeys() {
    return [this] {
      editor::drawEditorUi(*session_, ui_);
      if (!ImGui::GetIO().WantCaptureKeyboard) editor::applyEditShortcuts(*session_, ui_.panels);
    };
  }
  void ctrlTap(int key, bool shift = false) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = true;
    io.KeyShift = shift;
    imgui_->tap(key, drawUiAndKeys());
    io.KeyCtrl = false;
    io.KeyShift = false;
    imgui_->frame(drawUiAndKeys());
  }

  static constexpr int kZKey = 300;  // free indices of io.KeysDown for the key map
  static constexpr int kYKey = 301;
  std::array<int, 2> edge_{};
  bool startTagged_ = false;
  double g0_ = 0.0;
};

TEST_F(SharedUndoPanels, EditUndoTwiceTakesBackTheParameterThenTheTag) {
  tagThenEditGravity();
  for (int i = 0; i < 2; ++i) {
    probe_.rects.erase("menu/undo");
    imgui_->click(probe_.centre("menu/edit"), drawUi());
    if (!probe_.rects.count("menu/undo")) imgui_->click(probe_.centre("menu/edit"), drawUi());  // it was open: closed
    ASSERT_TRUE(probe_.rects.count("menu/undo")) << "the Edit menu did not open";
    imgui_->click(probe_.centre("menu/undo"), drawUi());
    if (i == 0) {
      EXPECT_DOUBLE_EQ(session_->scene().forces.gravity.y(), g0_) << "Edit > Undo: the parameter first";
      EXPECT_NE(edgeTagged(), startTagged_);
    }
  }
  EXPECT_EQ(edgeTagged(), startTagged_) << "the second Edit > Undo takes back the tag";
}

TEST_F(SharedUndoPanels, CtrlZTwiceUndoesBothAndCtrlYOrCtrlShiftZRedoesThem) {
  tagThenEditGravity();
  ctrlTap(kZKey);
  EXPECT_DOUBLE_EQ(session_->scene().forces.gravity.y(), g0_);
  EXPECT_NE(edgeTagged(), startTagged_);
  ctrlTap(kZKey);
  EXPECT_EQ(edgeTagged(), startTagged_) << "Ctrl+Z the second time undoes the tag";
  ctrlTap(kZKey, /*shift=*/true);
  EXPECT_NE(edgeTagged(), startTagged_) << "Ctrl+Shift+Z redoes the tag";
  EXPECT_DOUBLE_EQ(session_->scene().forces.gravity.y(), g0_) << "and only the tag";
  ctrlTap(kYKey);
  EXPECT_DOUBLE_EQ(session_->scene().forces.gravity.y(), -3.0) << "Ctrl+Y redoes the parameter edit";
}

TEST_F(SharedUndoPanels, TheToolsPanelsUndoIsTheSameHistory) {
  tagThenEditGravity();
  ASSERT_TRUE(probe_.rects.count("tools/undo")) << "the Tools panel shows its Undo";
  clickWidget("tools/undo", drawUi());
  EXPECT_DOUBLE_EQ(session_->scene().forces.gravity.y(), g0_) << "the latest edit, a parameter, is undone first";
  EXPECT_NE(edgeTagged(), startTagged_);
  clickWidget("tools/undo", drawUi());
  EXPECT_EQ(edgeTagged(), startTagged_);
}

}  // namespace
}  // namespace weft::test
