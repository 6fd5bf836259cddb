#pragma once
// ImGui 1.86 samples keys and mouse buttons as "down now", once a frame, and has no input queue:
// a key tapped between two frames (pressed and released within one) never looks pressed, so an
// Enter in a text field or a Ctrl+S is lost. This queue keeps the window's presses and releases
// in order and hands ImGui at most one change per key or button a frame, so every tap is down
// for one frame and up in a later one. Events left over wait for the next frame, in order.
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
  // flags and io.MouseDown from the queued events (the cursor to where a button changed), taking
  // events in order until one would change a key or button already changed in this frame.
  void applyTo(ImGuiIO& io);
  bool empty() const { return pending_.empty(); }
  bool mouseDown(int button) const { return mouseDown_[static_cast<std::size_t>(button)]; }

 private:
  std::deque<ui::ButtonEvent> pending_;
  std::array<bool, 512> keyDown_{};  // as ImGui was last told (io.KeysDown has 512 entries)
  std::array<bool, 5> mouseDown_{};
};

}  // namespace weft::editor
