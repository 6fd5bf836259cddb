#include "editor_app.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <utility>

#include "command.h"
#include "editor/editor_session.h"
#include "editor/editor_ui.h"
#include "editor/editor_settings.h"
#include "editor/editor_viewport.h"
#include "editor/editor_workspace.h"
#include "editor/headless_recorder.h"
#include "editor/input_queue.h"
#include "editor/menu_bar.h"
#include "editor/scene_browser.h"
#include "editor/viewport_interaction.h"
#include "glfw_window.h"
#include "imgui_layer.h"
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

ui::OrbitCamera startCamera(const editor::EditorSession& session, const editor::ViewportRect& rect) {
  return ui::defaultCamera(session.view()->render, session.scene().output.camera, rect.aspect());
}

// What a shortcut asks of the app beyond the session.
struct ShortcutResult {
  bool quit = false;         // Esc with nothing open (no popup, no browser)
  bool frameScene = false;   // F
};

// Keyboard shortcuts, when no text field has the keyboard. Esc closes an open popup (a combo's
// list; the prompts answer Esc themselves) before it means quit.
ShortcutResult applyShortcuts(editor::EditorSession& session, editor::PanelState& panels, const ui::WindowInput& input) {
  ShortcutResult result;
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) {
    if (input.pressed(ui::Key::kEscape)) ImGui::ClosePopupsExceptModals();
    return result;
  }
  // The scene and preset browser is a window, not a popup: Esc closes it too before it means quit
  // (an artist closes what is open first, as with any other window of the editor).
  if (panels.browserOpen && input.pressed(ui::Key::kEscape)) {
    panels.browserOpen = false;
    return result;
  }
  if (io.WantCaptureKeyboard) return result;
  if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) result.frameScene = true;
  // The timeline: Left and Right step through the cached frames, End goes back to the live one.
  const long long shownFrame = session.shownFrame().value_or(session.liveFrame());
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) session.showFrame(std::max(shownFrame - 1, 0LL));
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) session.showFrame(shownFrame + 1);
  if (ImGui::IsKeyPressed(GLFW_KEY_END, false)) session.showLive();
  editor::applyEditShortcuts(session, panels);  // Ctrl+Z, Ctrl+Y, Ctrl+Shift+Z
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S)) editor::saveScene(session, panels);  // a shipped scene: Save as
  for (ui::Key key : input.keysPressed) {
    switch (key) {
      case ui::Key::kEscape: result.quit = true; return result;
      case ui::Key::kSpace: session.paused = !session.paused; break;
      case ui::Key::kN:
        session.paused = true;
        session.stepOnce();
        break;
      case ui::Key::kR: session.reset(); break;
    }
  }
  return result;
}

// The mouse over the scene (not over a panel): grab, drag a tool or tag sharp first, and what
// they leave to the orbit camera. B (or the tools panel's button) throws a ball at the cursor.
void viewportMouse(editor::EditorSession& session, editor::EditorUi& ui, ui::OrbitCamera& camera,
                   ui::OrbitControls& controls, editor::ViewportInteraction& interaction, const ui::GlfwWindow& window,
                   const editor::InputQueue& queue, const editor::ViewportRect& rect) {
  const ImGuiIO& io = ImGui::GetIO();
  // Window coordinates to framebuffer pixels (they differ on high-DPI displays).
  const ui::PixelSize fb = window.framebufferSize();
  const ui::PixelSize win = window.windowSize();
  const double scale = win.width > 0 ? static_cast<double>(fb.width) / win.width : 1.0;
  // Buttons as the queue hands them out, so a click shorter than a frame is still a press and a
  // release (the window's own states would show neither).
  ui::MouseState buttons = window.input().mouse;
  buttons.left = queue.mouseDown(0);
  buttons.right = queue.mouseDown(1);
  buttons.middle = queue.mouseDown(2);
  ui::MouseState mouse = buttons;
  mouse.x = mouse.x * scale - rect.x;
  mouse.y = mouse.y * scale - rect.y;
  const bool overScene = !io.WantCaptureMouse && rect.contains(mouse.x + rect.x, mouse.y + rect.y);
  if (!overScene && !interaction.grabbing()) mouse.left = false;
  ui::MouseState forCamera = buttons;
  // The Material panel's tear strength brush: a left drag on a cloth paints (tag mode first).
  interaction.setPaintBrush(ui.panels.paintMode && !ui.panels.tagMode ? &ui.panels.brush : nullptr);
  const bool taken = interaction.update(session, camera, mouse, {io.KeyAlt, io.KeyShift}, rect.width, rect.height,
                                        ui.panels.tagMode ? ui.panels.tools.current() : nullptr);
  if (overScene && !taken) controls.update(camera, forCamera, win.height);
  if (const auto box = interaction.box()) {  // tag mode's Shift + drag
    const ImVec2 a(static_cast<float>((rect.x + box->x0) / scale), static_cast<float>((rect.y + box->y0) / scale));
    const ImVec2 b(static_cast<float>((rect.x + box->x1) / scale), static_cast<float>((rect.y + box->y1) / scale));
    ImGui::GetForegroundDrawList()->AddRectFilled(a, b, IM_COL32(255, 165, 0, 40));
    ImGui::GetForegroundDrawList()->AddRect(a, b, IM_COL32(230, 130, 0, 255));
  }
  if (const auto& brush = interaction.brushOutline(); brush && overScene) {  // the tear strength brush
    const ImVec2 c(static_cast<float>((rect.x + brush->x) / scale), static_cast<float>((rect.y + brush->y) / scale));
    const float r = static_cast<float>(brush->radiusPixels / scale);
    ImGui::GetForegroundDrawList()->AddCircle(c, r, IM_COL32(20, 20, 20, 200), 48, 2.0f);
    ImGui::GetForegroundDrawList()->AddCircle(c, r, IM_COL32(255, 255, 255, 220), 48, 1.0f);
  }
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
  const int requested = session->scene().solver.threads;
  if (editor::editorSolverThreads(requested) != requested) {
    std::fprintf(stderr,
                 "weft edit: solver.threads = %d leaves no core of this machine for drawing; stepping with %d "
                 "(same results)\n",
                 requested, editor::editorSolverThreads(requested));
  }
  return session;
}

// What the window shows, for --print-changes: the step on screen and whether it is the live world
// or a frame of the timeline's cache.
std::string shownState(const editor::EditorSession& session) {
  const long long step = session.view()->stepCount;
  const long long frame = step / session.stepsPerFrame();
  return "step " + std::to_string(step) + " (frame " + std::to_string(frame) + ", " +
         (session.shownFrame() ? "cached" : "live") + ")";
}

}  // namespace

int runEditor(const EditorOptions& options) {
  // A bad scene is reported before any window opens.
  editor::EditorUi ui;
  editor::EditorWorkspace workspace(openSession(options), editor::Autosave(options.autosaveDir), ui);
  for (const editor::Recovery& r : ui.recoveries) {
    std::string tools;  // the tools whose unsaved sharp tags come back with it
    for (const editor::UnsavedToolTags& tags : r.toolTags) tools += (tools.empty() ? " and the sharp tags of " : ", ") + tags.tool;
    std::printf("weft edit: offering unsaved edits to %s%s back (autosaved %s in %s)\n", r.original.string().c_str(),
                tools.c_str(), r.savedAt.c_str(), r.autosaveFile.string().c_str());
  }
  const std::filesystem::path settingsFile = editor::defaultSettingsFile();
  ui.panels.settings = editor::loadEditorSettings(settingsFile);
  const editor::EditorSettings settingsAtStart = ui.panels.settings;
  // Recording runs this same binary headless (`weft run --png --video`) on the edited scene.
  editor::HeadlessRecorder recorder(std::filesystem::read_symlink("/proc/self/exe"));
  ui.panels.recorder = &recorder;

  ui::WindowSettings settings;
  settings.title = "Weft: " + workspace.session().scene().name;
  settings.width = 1440;  // room for the panels on both sides of the scene
  settings.height = 900;
  ui::GlfwWindow window(settings);
  ImGuiLayer imgui(window.handle());
  window.takeBackCharacters();  // characters go through the input queue, in order with the keys
  ui::SceneRenderer renderer;
  // The browser's thumbnails are textures of this window's context, drawn by the same renderer.
  editor::SceneBrowser browser(editor::browserFolders(workspace.session().document().file()), editor::ThumbnailCache());
  ui.panels.browser = &browser;
  auto viewportRect = [&] {
    const ui::PixelSize size = window.framebufferSize();
    return editor::sceneViewport(size.width, size.height);
  };
  ui::OrbitCamera camera = startCamera(workspace.session(), viewportRect());
  ui::OrbitControls controls;
  editor::ViewportInteraction interaction;
  editor::InputQueue inputQueue;
  workspace.session().paused = !options.play;

  auto drawFrame = [&] {
    window.bindDefaultFramebuffer();
    const ui::PixelSize size = window.framebufferSize();
    if (size.width > 0 && size.height > 0) {  // zero while minimized
      // The latest step's snapshot: drawing never waits for the step the worker is running.
      const std::shared_ptr<const editor::WorldSnapshot> shown = workspace.session().view();
      ui::RenderView view = shown->render;
      // In tag mode, the feature a click would toggle, highlighted before the click.
      const editor::ToolTagEditor* tagged = ui.panels.tools.current();
      if (const auto& hovered = interaction.hovered();
          hovered && tagged != nullptr && tagged->obstacle() < static_cast<int>(view.obstacles.size())) {
        ui::ObstacleView& tool = view.obstacles[static_cast<std::size_t>(tagged->obstacle())];
        if (hovered->isVertex()) {
          tool.highlightVertices.push_back(hovered->vertex);
        } else {
          tool.highlightEdges.push_back(hovered->edge);
        }
      }
      // Painting the tear strength: each cloth with a map drawn tinted by it (weak red, strong blue).
      if (ui.panels.paintMode) {
        editor::EditorSession& painted = workspace.session();
        for (int c = 0; c < static_cast<int>(view.cloths.size()); ++c) {
          const editor::StrengthPainting* painting = painted.findStrengthPainting(c);
          if (painting == nullptr && c < static_cast<int>(painted.scene().cloths.size()) &&
              painted.scene().cloths[static_cast<std::size_t>(c)].tearStrengthMap) {
            painting = &painted.strengthPainting(c);  // the map the scene loads, shown before a stroke
          }
          if (painting != nullptr) view.cloths[static_cast<std::size_t>(c)].strengthTint = painting->sharedMap();
        }
      }
      editor::drawSceneViewport(renderer, view, camera, viewportRect(), size.width, size.height);
    }
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  };

  // ImGui lays a new window out in its first frame and settles it in the next ones (a scrollbar
  // appears once the content is measured): the editor says it is ready after this many.
  constexpr int kFramesToSettle = 3;
  Clock::time_point lastAutosave = Clock::now();
  Clock::time_point lastFrame = Clock::now();
  int displayed = 0;
  const Clock::time_point started = Clock::now();
  std::string printedState;   // --print-changes: what was last said to be on screen
  std::string printedStatus;
  bool printedBrowserOpen = false;
  while (ui.quit != editor::QuitPrompt::Confirmed) {
    editor::EditorSession* session = &workspace.session();
    window.pollEvents();
    inputQueue.add(window.input().buttonEvents);
    if (window.shouldClose()) {
      window.cancelClose();  // the prompt decides
      ui.quit = editor::QuitPrompt::Asking;
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    inputQueue.applyTo(ImGui::GetIO());
    ImGui::NewFrame();
    const ShortcutResult shortcut = applyShortcuts(*session, ui.panels, window.input());
    if (shortcut.quit) ui.quit = editor::QuitPrompt::Asking;
    if (shortcut.frameScene || ui.frameScene) {
      camera = editor::frameSelection(session->view()->render, ui.panels.obstacle, camera, viewportRect().aspect());
    }
    ui.frameScene = false;
    viewportMouse(*session, ui, camera, controls, interaction, window, inputQueue, viewportRect());
    editor::drawEditorUi(*session, ui);
    ImGui::Render();

    if (workspace.applyChoices(ui)) {
      session = &workspace.session();
      session->paused = true;  // every scene opens paused at t = 0
      camera = startCamera(*session, viewportRect());
      window.setTitle("Weft: " + session->scene().name);
      browser.setFolders(editor::browserFolders(session->document().file()));
    }
    workspace.forgetAutosaveWhenClean(ui.panels.tools);
    // Real time: the simulation advances by as long as the last frame took (at the target speed).
    const Clock::time_point now = Clock::now();
    const double frameSeconds = std::chrono::duration<double>(now - lastFrame).count();
    lastFrame = now;
    if (displayed > 0) {
      const bool wasStopped = session->stopped();
      const bool wasUnhealthy = session->unhealthy().has_value();
      session->advanceFrame(frameSeconds);
      if (session->stopped() && !wasStopped) std::cerr << "weft edit: " << session->status << "\n";
      if (session->unhealthy() && !wasUnhealthy) {
        std::cerr << "weft edit: warning: " << healthWarning(*session->unhealthy()) << "\n";
      }
    }

    // Lazily, one a frame and only while the browser shows them: a thumbnail read from the cache
    // or drawn (its scene built at t = 0) offscreen, before this frame draws.
    if (ui.panels.browserOpen) browser.makeNextThumbnail(renderer);
    drawFrame();
    window.swapBuffers();
    ++displayed;
    if (displayed == std::min(kFramesToSettle, options.frames.value_or(kFramesToSettle))) {
      // Once the window shows the scene and its panels, settled: a click lands on a widget from
      // here (the window tests wait for this line before they click).
      std::printf("weft edit: %s (%s)\n", options.scene.string().c_str(), window.glRenderer().c_str());
      std::fflush(stdout);
    }
    if (options.printChanges && displayed >= kFramesToSettle) {
      // Said after the swap: the frame showing it has been handed to the display.
      const std::string state = shownState(*session);
      if (state != printedState) std::printf("weft edit: shows %s\n", state.c_str());
      if (session->status != printedStatus) std::printf("weft edit: status: %s\n", session->status.c_str());
      if (ui.panels.browserOpen != printedBrowserOpen) {
        std::printf("weft edit: browser %s\n", ui.panels.browserOpen ? "open" : "closed");
      }
      printedState = state;
      printedStatus = session->status;
      printedBrowserOpen = ui.panels.browserOpen;
      std::fflush(stdout);
    }
    if (Clock::now() - lastAutosave > kAutosaveEvery) {
      try {
        workspace.writeAutosave(ui.panels.tools);
      } catch (const std::exception& e) {
        session->status = std::string("autosave failed: ") + e.what();
      }
      lastAutosave = Clock::now();
    }
    if (options.frames && displayed >= *options.frames) break;
  }
  // For scripts and the window tests: the display kept its rate while the worker stepped.
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  std::printf("weft edit: %d frames in %.2f s (%.1f fps), the scene at step %lld\n", displayed, seconds,
              seconds > 0 ? displayed / seconds : 0.0, workspace.session().view()->stepCount);
  std::fflush(stdout);
  // Quitting on purpose, saved or discarded: the autosave this session wrote has done its job.
  // (Stopped by --frames, a script's run, the autosave is left as the last timed write made it.)
  if (ui.quit == editor::QuitPrompt::Confirmed) workspace.quitConfirmed();
  if (!(ui.panels.settings == settingsAtStart)) {
    try {
      editor::saveEditorSettings(ui.panels.settings, settingsFile);
    } catch (const std::exception& e) {
      std::cerr << "weft edit: cannot remember the editor's settings: " << e.what() << "\n";
    }
  }
  editor::EditorSession* session = &workspace.session();

  if (!options.screenshot.empty()) {
    (void)std::as_const(*session).world();  // the steps asked for are in the picture, whatever the timing
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
