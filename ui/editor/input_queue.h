#pragma once
// ImGui 1.86 samples keys and mouse buttons as "down now", once a frame, and has no input queue:
// a key tapped between two frames (pressed and released within one) never looks pressed, so an
// Enter in a text field or a Ctrl+S is lost. This queue keeps the window's presses, releases and
// typed characters in order and hands them to ImGui over as many frames as it takes for each to
// be seen, in order, as the user made them:
//  - at most one change per key or button a frame: every tap is down for one frame, up in a later one;
//  - at most one press a frame (of a key other than Ctrl, Shift, Alt or Super, or of a button):
//    keys pressed in a roll (the next one down before the last one is up) still reach ImGui one
//    after the other, not as one chord;
//  - no modifier changes after the frame's press: a key pressed with Ctrl held is seen with Ctrl
//    down, even when Ctrl is released before the key (Ctrl up, then S up) within the same frame;
//  - a mouse button's change has a frame to itself: the widget under it changes state (a field
//    takes the keyboard) before a character or key typed after the click arrives;
//  - characters arrive in order with the keys and clicks (the window hands them over,
//    glfw_window.h): before, ImGui's backend gave it each character at once, so "20" typed right
//    after a click on a field reached ImGui before the click had given the field the keyboard,
//    and was lost.
// Events left over wait for the next frame, in order. However slow the frames, nothing is lost
// and nothing overtakes.
#include <array>
#include <deque>
#include <vector>

#include <imgui.h>

#include "window_input.h"

namespace weft::editor {

class InputQueue {
 public:
  void add(const std::vector<ui::ButtonEvent>& events);
  // Between the platform backend's NewFrame and ImGui::NewFrame: sets io.KeysDown, the modifier
  // flags and io.MouseDown from the queued events (the cursor to where a button changed) and adds
  // the queued characters, taking events in order under the rules above.
  void applyTo(ImGuiIO& io);
  bool empty() const { return pending_.empty(); }
  bool mouseDown(int button) const { return mouseDown_[static_cast<std::size_t>(button)]; }

 private:
  std::deque<ui::ButtonEvent> pending_;
  std::array<bool, 512> keyDown_{};  // as ImGui was last told (io.KeysDown has 512 entries)
  std::array<bool, 5> mouseDown_{};
};

}  // namespace weft::editor
