// Taps shorter than a frame reach ImGui: the queue hands a press and its release to two frames,
// in order, where ImGui 1.86 alone (sampling "down now") would see neither.
#include "editor/input_queue.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "support/editor_panels_fixture.h"

namespace weft::editor {
namespace {

using test::EditorPanelsTest;
using test::HeadlessImGui;

ui::ButtonEvent key(int code, bool down) { return ui::ButtonEvent{false, code, down, 0.0, 0.0}; }

TEST(InputQueue, ATapIsDownForOneFrameThenUp) {
  ImGuiIO io;
  InputQueue queue;
  queue.add({key(GLFW_KEY_S, true), key(GLFW_KEY_S, false)});  // both between two frames
  queue.applyTo(io);
  EXPECT_TRUE(io.KeysDown[GLFW_KEY_S]);
  queue.applyTo(io);
  EXPECT_FALSE(io.KeysDown[GLFW_KEY_S]);
  EXPECT_TRUE(queue.empty());
}

TEST(InputQueue, KeepsTheOrderAcrossKeysAndModifiers) {
  ImGuiIO io;
  InputQueue queue;
  // Ctrl+S tapped quickly: ctrl down, s down, s up, ctrl up, all in one frame.
  queue.add({key(GLFW_KEY_LEFT_CONTROL, true), key(GLFW_KEY_S, true), key(GLFW_KEY_S, false),
             key(GLFW_KEY_LEFT_CONTROL, false)});
  queue.applyTo(io);
  EXPECT_TRUE(io.KeyCtrl);
  EXPECT_TRUE(io.KeysDown[GLFW_KEY_S]) << "S is down while Ctrl is";
  queue.applyTo(io);
  EXPECT_FALSE(io.KeysDown[GLFW_KEY_S]);
  EXPECT_FALSE(io.KeyCtrl);
}

TEST(InputQueue, AClickLandsWhereTheButtonWentDown) {
  ImGuiIO io;
  InputQueue queue;
  queue.add({ui::ButtonEvent{true, 0, true, 120.0, 40.0}, ui::ButtonEvent{true, 0, false, 125.0, 41.0}});
  io.MousePos = ImVec2(600, 600);  // where the cursor is when the frame starts
  queue.applyTo(io);
  EXPECT_TRUE(io.MouseDown[0]);
  EXPECT_EQ(io.MousePos.x, 120.0f);
  EXPECT_TRUE(queue.mouseDown(0));
  queue.applyTo(io);
  EXPECT_FALSE(io.MouseDown[0]);
  EXPECT_EQ(io.MousePos.x, 125.0f);
}

// Through a real panel: "20" typed and Enter tapped within one frame still sets the value.
TEST_F(EditorPanelsTest, AnEnterTappedWithinOneFrameIsNotLost) {
  ImGuiIO& io = ImGui::GetIO();
  InputQueue queue;
  auto frame = [&] {
    queue.applyTo(io);
    drawUi()();
  };
  imgui_->click(probe_.centre("tear/2"), drawUi());
  for (char c : std::string("20")) io.AddInputCharacter(static_cast<unsigned>(c));
  queue.add({key(HeadlessImGui::kEnterKey, true), key(HeadlessImGui::kEnterKey, false)});
  for (int i = 0; i < 3; ++i) imgui_->frame(frame);
  EXPECT_DOUBLE_EQ(session_->scene().cloths[0].material.tearTable->strength[2], 20.0) << session_->status;
}

}  // namespace
}  // namespace weft::editor
