#include "editor/input_queue.h"

#include <GLFW/glfw3.h>

namespace weft::editor {

void InputQueue::add(const std::vector<ui::ButtonEvent>& events) {
  for (const ui::ButtonEvent& e : events) {
    const std::size_t limit = e.mouse ? mouseDown_.size() : keyDown_.size();
    if (e.code >= 0 && static_cast<std::size_t>(e.code) < limit) pending_.push_back(e);
  }
}

void InputQueue::applyTo(ImGuiIO& io) {
  std::array<bool, 512> keyChanged{};
  std::array<bool, 5> mouseChanged{};
  while (!pending_.empty()) {
    const ui::ButtonEvent& e = pending_.front();
    const auto code = static_cast<std::size_t>(e.code);
    bool& changed = e.mouse ? mouseChanged[code] : keyChanged[code];
    if (changed) break;  // its second change this frame: the rest waits, keeping the order
    bool& down = e.mouse ? mouseDown_[code] : keyDown_[code];
    if (down != e.down) {
      down = e.down;
      changed = true;
      if (e.mouse) io.MousePos = ImVec2(static_cast<float>(e.x), static_cast<float>(e.y));
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
