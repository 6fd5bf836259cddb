#include "editor/menu_bar.h"

#include <imgui.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "editor/installed_data.h"
#include "editor/shared_undo.h"

namespace weft::editor {

namespace {

void drawFileMenu(EditorSession& session, EditorUi& ui) {
  const bool open = ImGui::BeginMenu("File");
  recordWidget(ui.panels, "menu/file");
  if (!open) return;
  if (ImGui::MenuItem("Browse scenes and presets...", nullptr, false, ui.panels.browser != nullptr)) {
    ui.panels.browserOpen = true;
  }
  if (ImGui::MenuItem("Open...")) ui.openDialog = true;
  if (ImGui::MenuItem("Save", "Ctrl+S")) saveScene(session, ui.panels);
  if (ImGui::MenuItem("Save as...")) {
    // The dialog starts where the scene is, under its name (as a desktop Save As does): the
    // artist edits the name or the folder instead of typing a whole path from nothing. A shipped
    // scene suggests the user's own copy instead, as Save does.
    if (ui.panels.saveAsPath[0] == '\0' && !session.document().file().empty()) {
      const std::filesystem::path start = session.savesIntoInstalledData() ? suggestedSceneCopy(session.document().file())
                                                                           : session.document().file();
      std::snprintf(ui.panels.saveAsPath, sizeof ui.panels.saveAsPath, "%s", start.string().c_str());
    }
    ui.saveAsDialog = true;
  }
  recordWidget(ui.panels, "menu/saveas");
  ImGui::Separator();
  if (ImGui::MenuItem("Save material as preset...")) {
    ui.panels.presetFolder[0] = '\0';  // the material panel fills in the suggested folder
    ui.panels.presetDialog = true;
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Quit", "Esc")) ui.quit = QuitPrompt::Asking;
  ImGui::EndMenu();
}

void drawEditMenu(EditorSession& session, PanelState& state) {
  const bool open = ImGui::BeginMenu("Edit");
  recordWidget(state, "menu/edit");
  if (!open) return;
  ToolTagEditors& tools = state.tools;
  if (ImGui::MenuItem(("Undo " + latestUndoLabel(session, tools)).c_str(), "Ctrl+Z", false, canUndoLatest(session, tools))) {
    undoLatest(session, tools);
  }
  recordWidget(state, "menu/undo");
  if (ImGui::MenuItem(("Redo " + latestRedoLabel(session, tools)).c_str(), "Ctrl+Y", false, canRedoLatest(session, tools))) {
    redoLatest(session, tools);
  }
  recordWidget(state, "menu/redo");
  ImGui::EndMenu();
}

void drawPlaybackMenu(EditorSession& session) {
  if (!ImGui::BeginMenu("Playback")) return;
  if (ImGui::MenuItem(session.paused ? "Play" : "Pause", "Space")) session.paused = !session.paused;
  if (ImGui::MenuItem("Step", "N")) {
    session.paused = true;
    session.stepOnce();
  }
  if (ImGui::MenuItem("Reset to t = 0", "R")) session.reset();
  ImGui::EndMenu();
}

void drawViewMenu(EditorUi& ui) {
  const bool open = ImGui::BeginMenu("View");
  recordWidget(ui.panels, "menu/view");
  if (!open) return;
  if (ImGui::MenuItem(ui.panels.obstacle >= 0 ? "Frame the selected obstacle" : "Frame the scene", "F")) {
    ui.frameScene = true;
  }
  recordWidget(ui.panels, "menu/frame");
  ImGui::EndMenu();
}

void drawHelpMenu(EditorUi& ui) {
  if (!ImGui::BeginMenu("Help")) return;
  if (ImGui::MenuItem("Mouse and keys")) ui.helpOpen = true;
  ImGui::EndMenu();
}

// A path typed into a small modal; true when the user confirmed it.
bool pathDialog(const char* title, const char* button, char* path, std::size_t size, bool& open, const std::string& note) {
  if (open) ImGui::OpenPopup(title);
  bool confirmed = false;
  if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (!note.empty()) {
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 420.0f);
      ImGui::TextUnformatted(note.c_str());
      ImGui::PopTextWrapPos();
    }
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(420);
    const bool entered = ImGui::InputTextWithHint("##path", "path/to/scene.json", path, size,
                                                  ImGuiInputTextFlags_AutoSelectAll | ImGuiInputTextFlags_EnterReturnsTrue);
    if ((ImGui::Button(button) || entered) && path[0] != '\0') confirmed = true;
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) open = false;
    if (confirmed) open = false;
    if (!open) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  return confirmed;
}

void drawHelp(EditorUi& ui) {
  if (ui.helpOpen) ImGui::OpenPopup("Mouse and keys");
  if (!ImGui::BeginPopupModal("Mouse and keys", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextUnformatted(
      "In the scene (outside the panels):\n"
      "  left drag on the cloth   pull it (a long pull tears it)\n"
      "  left drag elsewhere      orbit\n"
      "  right or middle drag     pan\n"
      "  wheel                    zoom\n"
      "  Alt + left drag          move a kinematic tool\n"
      "  B                        throw a ball at the cursor\n"
      "Keys (outside text fields):\n"
      "  Space play / pause    N step    R reset to t = 0 (the camera stays)    F frame the scene\n"
      "  Ctrl+Z undo (scene edits and sharp tags alike)    Ctrl+Y or Ctrl+Shift+Z redo    Ctrl+S save\n"
      "  Esc closes an open popup, else quits (asking first about unsaved edits)");
  if (ImGui::Button("Close") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ui.helpOpen = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace

void applyEditShortcuts(EditorSession& session, PanelState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.KeyCtrl) return;
  ToolTagEditors& tools = state.tools;  // every tool's tags: the one history (shared_undo.h)
  // Shift+Z is checked before Z alone: with Shift held, Ctrl+Z redoes (as in most editors).
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Z))) {
    if (io.KeyShift) {
      redoLatest(session, tools);
    } else {
      undoLatest(session, tools);
    }
  }
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Y))) redoLatest(session, tools);
}

void drawMenuBar(EditorSession& session, EditorUi& ui) {
  if (ImGui::BeginMainMenuBar()) {
    drawFileMenu(session, ui);
    drawEditMenu(session, ui.panels);
    drawPlaybackMenu(session);
    drawViewMenu(ui);
    drawHelpMenu(ui);
    ImGui::EndMainMenuBar();
  }
  if (pathDialog("Open scene", "Open", ui.panels.openPath, sizeof ui.panels.openPath, ui.openDialog, "")) {
    ui.panels.openRequest = std::filesystem::absolute(ui.panels.openPath);
  }
  if (std::exchange(ui.panels.saveAsRequested, false)) ui.saveAsDialog = true;
  const std::string shipped = session.savesIntoInstalledData()
                                  ? session.document().file().filename().string() +
                                        " ships with Weft and is used by every user: your version goes to another file."
                                  : std::string();
  if (pathDialog("Save scene as", "Save", ui.panels.saveAsPath, sizeof ui.panels.saveAsPath, ui.saveAsDialog, shipped)) {
    try {
      session.saveAs(std::filesystem::absolute(ui.panels.saveAsPath));
    } catch (const std::exception& e) {
      session.status = e.what();
    }
  }
  drawHelp(ui);
}

}  // namespace weft::editor
