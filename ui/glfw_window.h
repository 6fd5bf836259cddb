#pragma once
// A desktop window with an OpenGL 3.3 core context (GLFW), for the live viewer and, later, the
// editor. The renderer draws into its default framebuffer exactly as it draws into an
// OffscreenFramebuffer headless.
//
// GLFW is process-wide: glfwInit here, glfwTerminate in the destructor, so there is one
// GlfwWindow at a time. Input arrives as plain data (window_input.h); no GLFW type leaves the
// .cpp. GLFW's errors are read back with glfwGetError rather than through an error callback: the
// callback carries no user pointer and would need a global to store the message in.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "window_input.h"

struct GLFWwindow;

namespace weft::ui {

// No window could be opened: no display, or GLFW or the GL context failed. what() says which,
// with GLFW's own message when there is one. Callers fall back to headless rendering.
struct WindowUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct WindowSettings {
  std::string title = "Weft";
  int width = 1280;   // screen coordinates
  int height = 800;   // screen coordinates
  int samples = 4;    // MSAA samples asked for (a hint: a display without them gives fewer)
  bool vsync = true;  // swap at the display's refresh rate
};

struct PixelSize {
  int width = 0;
  int height = 0;
};

class GlfwWindow {
 public:
  // Opens the window and makes its context current on this thread. Throws WindowUnavailable.
  explicit GlfwWindow(const WindowSettings& settings = WindowSettings{});
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  bool shouldClose() const;  // the user closed the window (or requestClose was called)
  void requestClose();
  void cancelClose();  // the user chose to stay (e.g. at an unsaved-changes prompt)

  // For Dear ImGui's GLFW backend, which installs its callbacks after (and chaining to) ours.
  GLFWwindow* handle() const { return window_; }

  // Forgets the previous poll's key presses and scrolling, then gathers what happened since.
  void pollEvents();
  // Typed characters reach the program only through input().buttonEvents, in order with the key
  // and button events: call after a library that installed its own character callback (the
  // ImGui GLFW backend, which would hand ImGui each character at once, ahead of the clicks and
  // keys queued before it).
  void takeBackCharacters();
  const WindowInput& input() const { return input_; }

  PixelSize framebufferSize() const;  // pixels: what to render at
  PixelSize windowSize() const;       // screen coordinates: the mouse's units
  void setTitle(const std::string& title);

  // Binds the default framebuffer (the back buffer) with the viewport covering all of it.
  void bindDefaultFramebuffer();
  // The back buffer as RGBA8 rows top-down, framebuffer-sized; call after drawing, before swap.
  std::vector<std::uint8_t> readBackBuffer() const;
  void swapBuffers();

  std::string glRenderer() const;  // GL_RENDERER of the window's context

 private:
  GLFWwindow* window_ = nullptr;
  WindowInput input_;  // the callbacks write here (through GLFW's window user pointer)
  std::string title_;
};

}  // namespace weft::ui
