#pragma once
// Dear ImGui driven headless for the editor's tests: an ImGui context rendered by the OpenGL 3
// backend into an offscreen framebuffer of the current EGL context, with simulated mouse and
// keyboard input through ImGui 1.86's input API (io.MousePos, io.MouseDown, io.KeysDown,
// io.AddInputCharacter). Each frame() is one ImGui frame; input set before it is what the
// widgets see in it.
#include <GL/gl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <functional>
#include <string>
#include <vector>

#include "offscreen_framebuffer.h"
#include "support/snapshot.h"

namespace weft::test {

class HeadlessImGui {
 public:
  static constexpr int kEnterKey = 257;   // any free index of io.KeysDown, mapped to ImGuiKey_Enter
  static constexpr int kEscapeKey = 256;  // likewise for ImGuiKey_Escape

  HeadlessImGui(int width, int height) : width_(width), height_(height), framebuffer_(width, height, 1) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.KeyMap[ImGuiKey_Enter] = kEnterKey;
    io.KeyMap[ImGuiKey_Escape] = kEscapeKey;
    ImGui::StyleColorsLight();
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~HeadlessImGui() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
  }
  HeadlessImGui(const HeadlessImGui&) = delete;
  HeadlessImGui& operator=(const HeadlessImGui&) = delete;

  // One frame: `drawScene` (optional) draws into the framebuffer first, then the UI on top.
  void frame(const std::function<void()>& drawUi, const std::function<void()>& drawScene = {}) {
    ImGuiIO& io = ImGui::GetIO();
    io.DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    drawUi();
    ImGui::Render();
    framebuffer_.bind();
    if (drawScene) {
      drawScene();
    } else {
      glClearColor(0.9f, 0.9f, 0.9f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

  // A click takes two frames: the button goes down in one and up in the next.
  void click(const ImVec2& at, const std::function<void()>& drawUi) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = at;
    frame(drawUi);  // hover first, as a real pointer would
    io.MouseDown[0] = true;
    frame(drawUi);
    io.MouseDown[0] = false;
    frame(drawUi);
  }

  // Types into the focused text field and presses Enter.
  void typeAndEnter(const std::string& text, const std::function<void()>& drawUi) {
    ImGuiIO& io = ImGui::GetIO();
    for (char c : text) io.AddInputCharacter(static_cast<unsigned>(c));
    frame(drawUi);
    io.KeysDown[kEnterKey] = true;
    frame(drawUi);
    io.KeysDown[kEnterKey] = false;
    frame(drawUi);
  }

  // A key tapped: down in one frame, up in the next.
  void tap(int key, const std::function<void()>& drawUi) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeysDown[key] = true;
    frame(drawUi);
    io.KeysDown[key] = false;
    frame(drawUi);
  }

  RgbaImage image() { return RgbaImage{width_, height_, framebuffer_.readPixels()}; }
  ui::OffscreenFramebuffer& framebuffer() { return framebuffer_; }

 private:
  int width_;
  int height_;
  ui::OffscreenFramebuffer framebuffer_;
};

}  // namespace weft::test
