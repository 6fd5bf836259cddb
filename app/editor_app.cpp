#include "editor_app.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>

#include "command.h"
#include "editor/editor_session.h"
#include "editor/editor_ui.h"
#include "editor/editor_viewport.h"
#include "editor/headless_recorder.h"
#include "editor/viewport_interaction.h"
#include "glfw_window.h"
#include "orbit_controls.h"
#include "png_writer.h"
#include "render_view.h"
#include "scene/scene_json.h"
#include "scene_renderer.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kAutosaveEvery = std::chrono::seconds(5);

ui::OrbitCamera startCamera(const World& world, const editor::ViewportRect& rect) {
  return ui::defaultCamera(ui::renderViewOf(world), world.scene().output.camera, rect.aspect());
}

// ImGui for the window's lifetime: created after the window (its GLFW backend chains to the
// window's own callbacks), destroyed before it.
struct ImGuiLayer {
  explicit ImGuiLayer(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // panel layout is not written next to the user's files
    ImGui::StyleColorsLight();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;
};

// Keyboard shortcuts, when no text field has the keyboard. Returns false when the user asked to
// quit.
bool applyShortcuts(editor::EditorSession& session, const ui::WindowInput& input) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return true;
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Z)) session.undo();
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Y)) session.redo();
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S)) {
    try {
      session.save();
    } catch (const std::exception& e) {
      session.status = e.what();
    }
  }
  for (ui::Key key : input.keysPressed) {
    switch (key) {
      case ui::Key::kEscape: return false;
      case ui::Key::kSpace: session.paused = !session.paused; break;
      case ui::Key::kN:
        session.paused = true;
        session.stepOnce();
        break;
      case ui::Key::kR: session.reset(); break;
    }
  }
  return true;
}

// The mouse over the scene (not over a panel): grab, drag a tool or tag sharp first, and what
// they leave to the orbit camera. B (or the tools panel's button) throws a ball at the cursor.
void viewportMouse(editor::EditorSession& session, editor::EditorUi& ui, ui::OrbitCamera& camera,
                   ui::OrbitControls& controls, editor::ViewportInteraction& interaction, const ui::GlfwWindow& window,
                   const editor::ViewportRect& rect) {
  const ImGuiIO& io = ImGui::GetIO();
  // Window coordinates to framebuffer pixels (they differ on high-DPI displays).
  const ui::PixelSize fb = window.framebufferSize();
  const ui::PixelSize win = window.windowSize();
  const double scale = win.width > 0 ? static_cast<double>(fb.width) / win.width : 1.0;
  ui::MouseState mouse = window.input().mouse;
  mouse.x = mouse.x * scale - rect.x;
  mouse.y = mouse.y * scale - rect.y;
  const bool overScene = !io.WantCaptureMouse && rect.contains(mouse.x + rect.x, mouse.y + rect.y);
  if (!overScene && !interaction.grabbing()) mouse.left = false;
  ui::MouseState forCamera = window.input().mouse;
  const bool taken = interaction.update(session, camera, mouse, io.KeyAlt, rect.width, rect.height,
                                        ui.panels.tagMode && ui.panels.tool ? &*ui.panels.tool : nullptr);
  if (overScene && !taken) controls.update(camera, forCamera, win.height);
  const bool throwKey = !io.WantCaptureKeyboard && ImGui::IsKeyPressed(GLFW_KEY_B);
  if (ui.panels.throwBallRequested || (throwKey && overScene)) {
    const double x = ui.panels.throwBallRequested ? 0.5 * rect.width : mouse.x;
    const double y = ui.panels.throwBallRequested ? 0.5 * rect.height : mouse.y;
    interaction.throwBall(session, camera, x, y, rect.width, rect.height);
    ui.panels.throwBallRequested = false;
  }
}

std::unique_ptr<editor::EditorSession> openSession(const EditorOptions& options) {
  auto session = std::make_unique<editor::EditorSession>(options.scene);
  if (!options.overrides.empty()) {
    nlohmann::json edited = session->json();
    applyOverrides(edited, options.overrides, options.scene.string());
    const editor::EditResult result = session->edit(std::move(edited), "--set overrides");
    if (!result.accepted) throw InputError(options.scene.string(), "--set", result.message);
    session->reset();
  }
  return session;
}

}  // namespace

int runEditor(const EditorOptions& options) {
  // A bad scene is reported before any window opens.
  std::unique_ptr<editor::EditorSession> session = openSession(options);
  editor::Autosave autosave(options.autosaveDir);
  editor::EditorUi ui;
  // Recording runs this same binary headless (`weft run --png --video`) on the edited scene.
  editor::HeadlessRecorder recorder(std::filesystem::read_symlink("/proc/self/exe"));
  ui.panels.recorder = &recorder;
  ui.recovery = autosave.find(std::filesystem::absolute(options.scene));

  ui::WindowSettings settings;
  settings.title = "Weft: " + session->scene().name;
  settings.width = 1440;  // room for the panels on both sides of the scene
  settings.height = 900;
  ui::GlfwWindow window(settings);
  ImGuiLayer imgui(window.handle());
  ui::SceneRenderer renderer;
  auto viewportRect = [&] {
    const ui::PixelSize size = window.framebufferSize();
    return editor::sceneViewport(size.width, size.height);
  };
  ui::OrbitCamera camera = startCamera(session->world(), viewportRect());
  ui::OrbitControls controls;
  editor::ViewportInteraction interaction;
  std::printf("weft edit: %s (%s)\n", options.scene.string().c_str(), window.glRenderer().c_str());
  std::fflush(stdout);

  auto drawFrame = [&] {
    window.bindDefaultFramebuffer();
    const ui::PixelSize size = window.framebufferSize();
    if (size.width > 0 && size.height > 0) {  // zero while minimized
      editor::drawSceneViewport(renderer, ui::renderViewOf(session->world()), camera, viewportRect(), size.width,
                                size.height);
    }
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  };

  // Edits made from the command line (--set) are the session's starting point: they are unsaved,
  // but only the user's own edits on top of them are worth offering back after a crash.
  std::uint64_t startRevision = session->document().history().revision();
  Clock::time_point lastAutosave = Clock::now();
  int displayed = 0;
  while (ui.quit != editor::QuitPrompt::Confirmed) {
    window.pollEvents();
    if (window.shouldClose()) {
      window.cancelClose();  // the prompt decides
      ui.quit = editor::QuitPrompt::Asking;
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (!applyShortcuts(*session, window.input())) ui.quit = editor::QuitPrompt::Asking;
    viewportMouse(*session, ui, camera, controls, interaction, window, viewportRect());
    editor::drawEditorUi(*session, ui);
    ImGui::Render();

    if (ui.recoveryChoice == editor::RecoveryChoice::Recover && ui.recovery) {
      session = std::make_unique<editor::EditorSession>(options.scene, ui.recovery->document);
      startRevision = ~std::uint64_t{0};  // recovered edits are the user's: keep them autosaved
      ui.recovery.reset();
    } else if (ui.recoveryChoice == editor::RecoveryChoice::Discard && ui.recovery) {
      autosave.discard(ui.recovery->original);
      ui.recovery.reset();
    }
    if (ui.open == editor::OpenPrompt::Confirmed) {
      try {
        auto opened = std::make_unique<editor::EditorSession>(ui.panels.openRequest);
        autosave.discard(std::filesystem::absolute(session->document().file()));
        session = std::move(opened);
        startRevision = session->document().history().revision();
        ui.panels.cloth = 0;
        camera = startCamera(session->world(), viewportRect());
        ui.panels.tool.reset();
      } catch (const InputError& e) {
        session->status = std::string("cannot open: ") + e.what();
      }
      ui.open = editor::OpenPrompt::None;
      ui.panels.openRequest.clear();
    }
    if (displayed > 0) {
      const bool wasStopped = session->stopped();
      session->advanceFrame();
      if (session->stopped() && !wasStopped) std::cerr << "weft edit: " << session->status << "\n";
    }

    drawFrame();
    window.swapBuffers();
    ++displayed;
    if (Clock::now() - lastAutosave > kAutosaveEvery && session->document().history().revision() != startRevision) {
      try {
        session->autosave(autosave);
      } catch (const std::exception& e) {
        session->status = std::string("autosave failed: ") + e.what();
      }
      lastAutosave = Clock::now();
    }
    if (options.frames && displayed >= *options.frames) break;
  }
  // Quitting on purpose, saved or discarded: the autosave has done its job. (Stopped by --frames,
  // a script's run, the autosave is left as the last timed write made it.)
  if (ui.quit == editor::QuitPrompt::Confirmed) autosave.discard(std::filesystem::absolute(session->document().file()));

  if (!options.screenshot.empty()) {
    drawFrame();  // the back buffer is undefined after a swap: draw the last frame again
    const ui::PixelSize size = window.framebufferSize();
    try {
      ui::writePng(options.screenshot, window.readBackBuffer(), size.width, size.height);
      std::printf("wrote %s (%dx%d)\n", options.screenshot.string().c_str(), size.width, size.height);
    } catch (const std::exception& e) {
      std::cerr << "weft edit: --screenshot: cannot write " << options.screenshot.string() << ": " << e.what() << "\n";
      return kExitFailure;
    }
  }
  return session->stopped() ? kExitNonFinite : kExitOk;
}

}  // namespace weft::app
