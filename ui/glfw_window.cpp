#include "glfw_window.h"

#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <cstring>

namespace weft::ui {
namespace {

bool environmentSet(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0';
}

// GLFW's description of the last error on this thread, or `fallback` when it recorded none.
std::string lastGlfwError(const std::string& fallback) {
  const char* description = nullptr;
  if (glfwGetError(&description) != GLFW_NO_ERROR && description != nullptr) return description;
  return fallback;
}

WindowInput& inputOf(GLFWwindow* window) { return *static_cast<WindowInput*>(glfwGetWindowUserPointer(window)); }

void onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  WindowInput& input = inputOf(window);
  if (action != GLFW_REPEAT) {
    ButtonEvent event{false, key, action == GLFW_PRESS, 0.0, 0.0};
    glfwGetCursorPos(window, &event.x, &event.y);
    input.buttonEvents.push_back(event);
  }
  if (action == GLFW_RELEASE) return;
  switch (key) {
    case GLFW_KEY_SPACE: if (action == GLFW_PRESS) input.keysPressed.push_back(Key::kSpace); break;
    case GLFW_KEY_N: input.keysPressed.push_back(Key::kN); break;  // held down, it keeps stepping
    case GLFW_KEY_R: if (action == GLFW_PRESS) input.keysPressed.push_back(Key::kR); break;
    case GLFW_KEY_ESCAPE: input.keysPressed.push_back(Key::kEscape); break;
    default: break;
  }
}

void onCharacter(GLFWwindow* window, unsigned codepoint) {
  ButtonEvent event;
  event.character = codepoint;
  inputOf(window).buttonEvents.push_back(event);
}

void onScroll(GLFWwindow* window, double /*dx*/, double dy) { inputOf(window).mouse.scrollY += dy; }

void onMouseButton(GLFWwindow* window, int button, int action, int /*mods*/) {
  ButtonEvent event{true, button, action == GLFW_PRESS, 0.0, 0.0};
  glfwGetCursorPos(window, &event.x, &event.y);
  inputOf(window).buttonEvents.push_back(event);
}

}  // namespace

GlfwWindow::GlfwWindow(const WindowSettings& settings) : title_(settings.title) {
  // Without either variable GLFW (built for X11 on Debian) can only fail; say it plainly.
  if (!environmentSet("DISPLAY") && !environmentSet("WAYLAND_DISPLAY")) {
    throw WindowUnavailable("no display: neither DISPLAY nor WAYLAND_DISPLAY is set");
  }
  if (glfwInit() != GLFW_TRUE) {
    throw WindowUnavailable("GLFW could not start: " + lastGlfwError("no reason given"));
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);  // macOS needs it; elsewhere it costs nothing
  glfwWindowHint(GLFW_SAMPLES, settings.samples);
  window_ = glfwCreateWindow(settings.width, settings.height, settings.title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string reason = lastGlfwError("no reason given");
    glfwTerminate();
    throw WindowUnavailable("no OpenGL 3.3 core window: " + reason);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(settings.vsync ? 1 : 0);
  glfwSetWindowUserPointer(window_, &input_);
  glfwSetKeyCallback(window_, onKey);
  glfwSetScrollCallback(window_, onScroll);
  glfwSetMouseButtonCallback(window_, onMouseButton);
  glfwSetCharCallback(window_, onCharacter);
}

void GlfwWindow::takeBackCharacters() { glfwSetCharCallback(window_, onCharacter); }

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void GlfwWindow::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void GlfwWindow::cancelClose() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

void GlfwWindow::pollEvents() {
  input_.keysPressed.clear();
  input_.buttonEvents.clear();
  input_.mouse.scrollY = 0.0;
  glfwPollEvents();
  // Position and buttons are states, read once per poll; presses and scrolling are events and
  // come through the callbacks so that none is missed between polls.
  glfwGetCursorPos(window_, &input_.mouse.x, &input_.mouse.y);
  input_.mouse.left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  input_.mouse.right = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  input_.mouse.middle = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
}

PixelSize GlfwWindow::framebufferSize() const {
  PixelSize size;
  glfwGetFramebufferSize(window_, &size.width, &size.height);
  return size;
}

PixelSize GlfwWindow::windowSize() const {
  PixelSize size;
  glfwGetWindowSize(window_, &size.width, &size.height);
  return size;
}

void GlfwWindow::setTitle(const std::string& title) {
  if (title == title_) return;  // the window manager needs no round trip for an unchanged title
  title_ = title;
  glfwSetWindowTitle(window_, title_.c_str());
}

void GlfwWindow::bindDefaultFramebuffer() {
  const PixelSize size = framebufferSize();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, size.width, size.height);
}

std::vector<std::uint8_t> GlfwWindow::readBackBuffer() const {
  const PixelSize size = framebufferSize();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);  // a multisampled default framebuffer is resolved by the read
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  const std::size_t row = static_cast<std::size_t>(size.width) * 4;
  std::vector<std::uint8_t> bottomUp(row * static_cast<std::size_t>(size.height));
  glReadPixels(0, 0, size.width, size.height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  // GL's rows start at the bottom; images start at the top.
  std::vector<std::uint8_t> topDown(bottomUp.size());
  for (int y = 0; y < size.height; ++y) {
    std::memcpy(topDown.data() + static_cast<std::size_t>(y) * row,
                bottomUp.data() + static_cast<std::size_t>(size.height - 1 - y) * row, row);
  }
  return topDown;
}

void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }

std::string GlfwWindow::glRenderer() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer != nullptr ? renderer : "unknown";
}

}  // namespace weft::ui
