// Taps shorter than a frame reach ImGui: the queue hands a press and its release to two frames,
// in order, where ImGui 1.86 alone (sampling "down now") would see neither; and however many
// taps, clicks and characters reach the window within one frame (a loaded machine's slow frame),
// ImGui sees them one after the other in the order they were made.
#include "editor/input_queue.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "support/editor_panels_fixture.h"

namespace weft::editor {
namespace {

using test::EditorPanelsTest;
using test::HeadlessImGui;

ui::ButtonEvent key(int code, bool down) { return ui::ButtonEvent{false, code, down, 0.0, 0.0}; }
ui::ButtonEvent button(bool down, ImVec2 at) { return ui::ButtonEvent{true, 0, down, at.x, at.y}; }
ui::ButtonEvent character(char c) {
  ui::ButtonEvent e;
  e.character = static_cast<unsigned>(c);
  return e;
}
std::string typed(const ImGuiIO& io) {
  std::string text;
  for (const ImWchar c : io.InputQueueCharacters) text += static_cast<char>(c);
  return text;
}

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

// Ctrl released before S (xdotool's ctrl+s releases in the order it pressed), the poll between
// Ctrl going down and S going down: S must still arrive with Ctrl held. Letting Ctrl's release
// into S's frame showed ImGui a plain S, and a Ctrl+S tap was lost (EditorWindow.KeyTaps...,
// about 1 run in 20 on a loaded machine).
TEST(InputQueue, AModifierReleasedBeforeItsKeyStaysDownForThePress) {
  ImGuiIO io;
  InputQueue queue;
  queue.add({key(GLFW_KEY_LEFT_CONTROL, true)});  // one poll
  queue.applyTo(io);
  EXPECT_TRUE(io.KeyCtrl);
  queue.add({key(GLFW_KEY_S, true), key(GLFW_KEY_LEFT_CONTROL, false), key(GLFW_KEY_S, false)});  // the next
  queue.applyTo(io);
  EXPECT_TRUE(io.KeysDown[GLFW_KEY_S]);
  EXPECT_TRUE(io.KeyCtrl) << "S went down with Ctrl held";
  queue.applyTo(io);
  EXPECT_FALSE(io.KeyCtrl);
  queue.applyTo(io);
  EXPECT_FALSE(io.KeysDown[GLFW_KEY_S]);
  EXPECT_TRUE(queue.empty());

  // The same with everything in one poll, and a modifier pressed after the key: not part of it.
  queue.add({key(GLFW_KEY_LEFT_CONTROL, true), key(GLFW_KEY_S, true), key(GLFW_KEY_LEFT_CONTROL, false),
             key(GLFW_KEY_S, false), key(GLFW_KEY_Z, true), key(GLFW_KEY_LEFT_SHIFT, true)});
  queue.applyTo(io);
  EXPECT_TRUE(io.KeyCtrl && io.KeysDown[GLFW_KEY_S]);
  for (int frame = 0; frame < 4 && !io.KeysDown[GLFW_KEY_Z]; ++frame) queue.applyTo(io);
  EXPECT_TRUE(io.KeysDown[GLFW_KEY_Z]);
  EXPECT_FALSE(io.KeyShift) << "Shift went down after Z";
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

// Enter, then Ctrl+S, both tapped within one frame: ImGui sees Enter down and up before Ctrl+S
// goes down (in one frame, a field that Enter closes would still hold the keyboard when Ctrl+S
// arrived, and the save would be lost).
TEST(InputQueue, TwoTapsWithinOneFrameArriveOneAfterTheOther) {
  ImGuiIO io;
  InputQueue queue;
  queue.add({key(GLFW_KEY_ENTER, true), key(GLFW_KEY_ENTER, false), key(GLFW_KEY_LEFT_CONTROL, true),
             key(GLFW_KEY_S, true), key(GLFW_KEY_S, false), key(GLFW_KEY_LEFT_CONTROL, false)});
  std::vector<std::pair<bool, bool>> frames;  // (Enter down, S down) in each frame
  for (int i = 0; i < 6 && !queue.empty(); ++i) {
    queue.applyTo(io);
    frames.emplace_back(io.KeysDown[GLFW_KEY_ENTER], io.KeysDown[GLFW_KEY_S] && io.KeyCtrl);
  }
  ASSERT_GE(frames.size(), 3u);
  EXPECT_EQ(frames[0], std::make_pair(true, false)) << "Enter first, alone";
  EXPECT_EQ(frames[1], std::make_pair(false, true)) << "then Ctrl+S, Enter already up";
  EXPECT_EQ(frames[2], std::make_pair(false, false));
  EXPECT_TRUE(queue.empty());
}

// A click on a field and "20" typed right after it, all within one frame: the characters wait
// until the click's frames are over (the field has the keyboard by then).
TEST(InputQueue, CharactersTypedAfterAClickWaitForIt) {
  ImGuiIO io;
  InputQueue queue;
  const ImVec2 at(100, 50);
  queue.add({button(true, at), button(false, at), key(GLFW_KEY_2, true), character('2'), key(GLFW_KEY_2, false),
             key(GLFW_KEY_0, true), character('0'), key(GLFW_KEY_0, false)});
  queue.applyTo(io);
  EXPECT_TRUE(io.MouseDown[0]);
  EXPECT_EQ(typed(io), "") << "the button's change has the frame to itself";
  io.InputQueueCharacters.resize(0);  // ImGui::EndFrame empties it
  queue.applyTo(io);
  EXPECT_FALSE(io.MouseDown[0]);
  EXPECT_EQ(typed(io), "");
  std::string text;
  for (int i = 0; i < 4; ++i) {
    io.InputQueueCharacters.resize(0);
    queue.applyTo(io);
    text += typed(io);
  }
  EXPECT_EQ(text, "20");
  EXPECT_TRUE(queue.empty());
}

// Keys pressed in a roll ("2" down, "0" down, "2" up, "0" up): one press a frame, in order.
TEST(InputQueue, KeysPressedInARollArriveOneAfterTheOther) {
  ImGuiIO io;
  InputQueue queue;
  queue.add({key(GLFW_KEY_2, true), key(GLFW_KEY_0, true), key(GLFW_KEY_2, false), key(GLFW_KEY_0, false)});
  queue.applyTo(io);
  EXPECT_TRUE(io.KeysDown[GLFW_KEY_2]);
  EXPECT_FALSE(io.KeysDown[GLFW_KEY_0]) << "0 waits for the next frame";
  queue.applyTo(io);
  EXPECT_TRUE(io.KeysDown[GLFW_KEY_0]);
  EXPECT_FALSE(io.KeysDown[GLFW_KEY_2]);
}

// A modifier held for a click (Shift+drag box select) is down in the click's frame.
TEST(InputQueue, AModifierPressedBeforeAClickIsHeldInItsFrame) {
  ImGuiIO io;
  InputQueue queue;
  queue.add({key(GLFW_KEY_LEFT_SHIFT, true), button(true, ImVec2(10, 10))});
  queue.applyTo(io);
  queue.applyTo(io);
  EXPECT_TRUE(io.KeyShift);
  EXPECT_TRUE(io.MouseDown[0]);
}

// Through a real panel: a click on a field, "20" typed and Enter tapped, all reaching the window
// within one frame (a slow frame on a loaded machine), set the value. With the characters handed
// to ImGui at once, ahead of the queued click, the field kept its old value.
TEST_F(EditorPanelsTest, AClickTypingAndEnterWithinOneFrameSetTheValue) {
  ImGuiIO& io = ImGui::GetIO();
  InputQueue queue;
  auto frame = [&] {
    queue.applyTo(io);
    drawUi()();
  };
  const ImVec2 field = probe_.centre("tear/2");
  io.MousePos = field;
  imgui_->frame(drawUi());  // the pointer rests on the field
  queue.add({button(true, field), button(false, field), character('2'), character('0'),
             key(HeadlessImGui::kEnterKey, true), key(HeadlessImGui::kEnterKey, false)});
  for (int i = 0; i < 6; ++i) imgui_->frame(frame);
  EXPECT_TRUE(queue.empty());
  EXPECT_DOUBLE_EQ(session_->scene().cloths[0].material.tearTable->strength[2], 20.0) << session_->status;
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
