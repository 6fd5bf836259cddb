#include "editor/input_queue.h"

#include <GLFW/glfw3.h>

namespace weft::editor {

namespace {

bool isModifier(int key) {
  switch (key) {
    case GLFW_KEY_LEFT_CONTROL:
    case GLFW_KEY_RIGHT_CONTROL:
    case GLFW_KEY_LEFT_SHIFT:
    case GLFW_KEY_RIGHT_SHIFT:
    case GLFW_KEY_LEFT_ALT:
    case GLFW_KEY_RIGHT_ALT:
    case GLFW_KEY_LEFT_SUPER:
    case GLFW_KEY_RIGHT_SUPER: return true;
    default: return false;
  }
}

}  // namespace

void InputQueue::add(const std::vector<ui::ButtonEvent>& events) {
  for (const ui::ButtonEvent& e : events) {
    const std::size_t limit = e.mouse ? mouseDown_.size() : keyDown_.size();
    if (e.character != 0 || (e.code >= 0 && static_cast<std::size_t>(e.code) < limit)) pending_.push_back(e);
  }
}

void InputQueue::applyTo(ImGuiIO& io) {
  std::array<bool, 512> keyChanged{};
  std::array<bool, 5> mouseChanged{};
  bool anyChange = false;  // a key or button changed this frame
  bool pressed = false;    // a key (not a modifier) or a button went down this frame
  bool clicked = false;    // a button changed this frame: nothing more this frame
  while (!pending_.empty() && !clicked) {
    const ui::ButtonEvent& e = pending_.front();
    if (e.character != 0) {
      io.AddInputCharacter(e.character);
      pending_.pop_front();
      continue;
    }
    const auto code = static_cast<std::size_t>(e.code);
    bool& changed = e.mouse ? mouseChanged[code] : keyChanged[code];
    if (changed) break;  // its second change this frame: the rest waits, keeping the order
    bool& down = e.mouse ? mouseDown_[code] : keyDown_[code];
    if (down != e.down) {
      const bool press = e.down && (e.mouse || !isModifier(e.code));
      if (press && pressed) break;     // the second tap of this frame: the next frame's
      // A modifier changed after this frame's press: the press keeps the modifiers it was made
      // with. xdotool's ctrl+s (and a quick hand) releases Ctrl before S; had S gone down in the
      // same frame as Ctrl went up, ImGui would see a plain S, and the save was lost.
      if (pressed && !e.mouse && isModifier(e.code)) break;
      if (e.mouse && anyChange) break;  // a click starts a frame of its own
      down = e.down;
      changed = true;
      anyChange = true;
      pressed = pressed || press;
      if (e.mouse) {
        io.MousePos = ImVec2(static_cast<float>(e.x), static_cast<float>(e.y));
        clicked = true;
      }
    }
    pending_.pop_front();
  }
  for (std::size_t k = 0; k < keyDown_.size(); ++k) io.KeysDown[k] = keyDown_[k];
  for (std::size_t b = 0; b < mouseDown_.size(); ++b) io.MouseDown[b] = mouseDown_[b];
  io.KeyCtrl = keyDown_[GLFW_KEY_LEFT_CONTROL] || keyDown_[GLFW_KEY_RIGHT_CONTROL];
  io.KeyShift = keyDown_[GLFW_KEY_LEFT_SHIFT] || keyDown_[GLFW_KEY_RIGHT_SHIFT];
  io.KeyAlt = keyDown_[GLFW_KEY_LEFT_ALT] || keyDown_[GLFW_KEY_RIGHT_ALT];
  io.KeySuper = keyDown_[GLFW_KEY_LEFT_SUPER] || keyDown_[GLFW_KEY_RIGHT_SUPER];
}

}  // namespace weft::editor
