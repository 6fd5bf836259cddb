#include "editor_ui.h"

#include <imgui.h>

#include "editor/editor_viewport.h"

namespace weft::editor {

namespace {

// Panels start in a column down the left and right of the viewport; the user can move them.
void placeNext(float x, float y, float width, float height) {
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_FirstUseEver);
}

void drawStatusBar(const EditorSession& session) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - 24));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, 24));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::Text("%s%s  |  %s%s", session.document().file().filename().string().c_str(), session.dirty() ? " (unsaved)" : "",
              session.resetPending() ? "RESET NEEDED to apply the last edit  |  " : "", session.status.c_str());
  ImGui::End();
}

// What the user chose at an unsaved-changes prompt.
enum class UnsavedChoice { Undecided, Proceed, Cancel };

// Unsaved edits are saved or given up on purpose before the document is left (quit, open
// another scene). Proceed: saved, discarded, or nothing to save. A failed save cancels.
UnsavedChoice askAboutUnsavedEdits(EditorSession& session, const char* title, const char* saveLabel,
                                   const char* discardLabel) {
  if (!session.dirty()) return UnsavedChoice::Proceed;
  UnsavedChoice choice = UnsavedChoice::Undecided;
  ImGui::OpenPopup(title);
  if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s has unsaved changes.", session.document().file().filename().string().c_str());
    if (ImGui::Button(saveLabel)) {
      try {
        session.save();
        choice = UnsavedChoice::Proceed;
      } catch (const std::exception& e) {
        session.status = e.what();
        choice = UnsavedChoice::Cancel;
      }
    }
    ImGui::SameLine();
    if (ImGui::Button(discardLabel)) choice = UnsavedChoice::Proceed;
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) choice = UnsavedChoice::Cancel;
    if (choice != UnsavedChoice::Undecided) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  return choice;
}

void drawQuitPrompt(EditorSession& session, EditorUi& ui) {
  if (ui.quit != QuitPrompt::Asking) return;
  switch (askAboutUnsavedEdits(session, "Unsaved changes", "Save and quit", "Discard and quit")) {
    case UnsavedChoice::Proceed: ui.quit = QuitPrompt::Confirmed; break;
    case UnsavedChoice::Cancel: ui.quit = QuitPrompt::None; break;
    case UnsavedChoice::Undecided: break;
  }
}

void drawOpenPrompt(EditorSession& session, EditorUi& ui) {
  if (ui.panels.openRequest.empty() || ui.open == OpenPrompt::Confirmed) return;
  ui.open = OpenPrompt::Asking;
  switch (askAboutUnsavedEdits(session, "Open another scene", "Save, then open", "Discard them, open")) {
    case UnsavedChoice::Proceed: ui.open = OpenPrompt::Confirmed; break;
    case UnsavedChoice::Cancel:
      ui.open = OpenPrompt::None;
      ui.panels.openRequest.clear();
      break;
    case UnsavedChoice::Undecided: break;
  }
}

void drawRecoveryPrompt(EditorUi& ui) {
  if (!ui.recovery || ui.recoveryChoice != RecoveryChoice::Undecided) return;
  ImGui::OpenPopup("Recover unsaved edits?");
  if (ImGui::BeginPopupModal("Recover unsaved edits?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("Weft stopped with unsaved edits to %s (autosaved %s).", ui.recovery->original.string().c_str(),
                ui.recovery->savedAt.c_str());
    if (ImGui::Button("Recover them")) {
      ui.recoveryChoice = RecoveryChoice::Recover;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard them")) {
      ui.recoveryChoice = RecoveryChoice::Discard;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

}  // namespace

void drawEditorUi(EditorSession& session, EditorUi& ui) {
  // An undo or a removal can take away the selected cloth or obstacle.
  const int cloths = static_cast<int>(session.scene().cloths.size());
  if (ui.panels.cloth >= cloths) ui.panels.cloth = cloths - 1;
  if (ui.panels.obstacle >= static_cast<int>(session.scene().obstacles.size())) ui.panels.obstacle = -1;
  // Columns as editor_viewport.h lays them out, so the scene shows between them.
  const float m = kPanelMargin;
  const float left = m, leftWidth = kLeftColumnWidth - 2 * m;
  const float right = ImGui::GetIO().DisplaySize.x - kRightColumnWidth + m;
  placeNext(left, 8, leftWidth, 290);
  drawScenePanel(session, ui.panels);
  placeNext(left, 306, leftWidth, 150);
  drawPlaybackPanel(session, ui.panels);
  placeNext(left, 464, leftWidth, 230);
  drawSolverPanel(session, ui.panels);
  placeNext(left, 702, leftWidth, 170);
  drawToolsPanel(session, ui.panels);
  placeNext(right, 8, kRightColumnWidth - 2 * m, 420);
  drawMaterialPanel(session, ui.panels);
  placeNext(right, 436, 250, 430);
  drawTearTablePanel(session, ui.panels);
  placeNext(right + 256, 436, 204, 260);
  drawWeftPanel(session, ui.panels);
  drawStatusBar(session);
  drawQuitPrompt(session, ui);
  drawOpenPrompt(session, ui);
  drawRecoveryPrompt(ui);
}

}  // namespace weft::editor
