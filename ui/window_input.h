#pragma once
// What the user did with the mouse and keyboard since the last poll, as plain data: the window
// (glfw_window) fills it, the camera controls and the viewer read it. No GLFW types, so the
// controls can be tested without a window.
#include <vector>

namespace weft::ui {

// The keys the viewer reacts to; other keys are not reported.
enum class Key { kSpace, kN, kR, kEscape };

struct MouseState {
  double x = 0.0, y = 0.0;  // cursor in window coordinates: pixels from the top-left corner
  bool left = false;        // buttons held down
  bool right = false;
  bool middle = false;
  double scrollY = 0.0;     // wheel clicks since the last poll; positive turns away from the user
};

// One press or release, or a typed character, in the order the window received it. `code` is the
// key's code as the windowing library numbers it (GLFW's, which is also what ImGui's key map
// indexes) or the mouse button (0 left, 1 right, 2 middle); x and y are the cursor at that moment.
// A typed character (`character` not 0, its Unicode code point) follows the press of its key;
// its code and down are unused.
struct ButtonEvent {
  bool mouse = false;
  int code = 0;
  bool down = false;
  double x = 0.0, y = 0.0;
  unsigned character = 0;
};

struct WindowInput {
  MouseState mouse;
  std::vector<Key> keysPressed;  // in order, since the last poll (key repeat included)
  // Every key and mouse button press and release, and every typed character, since the last
  // poll, in order: a tap shorter than a frame is both a press and a release here, where the
  // states above see neither.
  std::vector<ButtonEvent> buttonEvents;

  bool pressed(Key key) const {
    for (Key k : keysPressed) {
      if (k == key) return true;
    }
    return false;
  }
};

}  // namespace weft::ui
