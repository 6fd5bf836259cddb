#include "editor_ui.h"

#include <imgui.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "editor/editor_viewport.h"
#include "editor/menu_bar.h"

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
  ImGui::Text("%s%s  |  %s", session.document().file().filename().string().c_str(), session.dirty() ? " (unsaved)" : "",
              session.resetPending() ? "RESET NEEDED to apply the last edit  |  " : "");
  ImGui::SameLine(0.0f, 0.0f);
  // A refused edit stays red here until the next edit, whatever else happens meanwhile.
  if (const auto& refusal = session.refusal()) {
    ImGui::TextColored(kRefusedColour, "%s not applied: %s", refusal->label.c_str(), refusal->message.c_str());
  } else {
    ImGui::TextUnformatted(session.status.c_str());
  }
  ImGui::End();
}

// Esc answers the open prompt (as its Cancel or Later button) instead of quitting the editor. Not
// in the frame the prompt appears: the Esc that asked to quit opened the quit prompt, and would
// otherwise cancel it in the same frame, so Esc with unsaved edits did nothing at all.
bool escapePressed() {
  return !ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
}

// A scene opens paused at t = 0; one line over the viewport says what to press.
void drawStartHint(const EditorSession& session) {
  if (!session.paused || session.view()->stepCount != 0) return;
  const char* hint = "Paused at t = 0:  Space plays, N steps, R resets, F frames";
  const ImVec2 size = ImGui::CalcTextSize(hint);
  const float x = 0.5f * (kLeftColumnWidth + ImGui::GetIO().DisplaySize.x - kRightColumnWidth) - 0.5f * size.x;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const float y = kMenuBarHeight + 10.0f;
  draw->AddRectFilled(ImVec2(x - 8, y - 3), ImVec2(x + size.x + 8, y + size.y + 3), IM_COL32(255, 255, 255, 215), 4.0f);
  draw->AddText(ImVec2(x, y), IM_COL32(30, 30, 30, 255), hint);
}

// What the user chose at an unsaved-changes prompt.
enum class UnsavedChoice { Undecided, Proceed, Cancel };

// "sword, knife"
std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// Unsaved edits, the scene's and the tools' sharp tags (kept in files of their own), are saved or
// given up on purpose before the document is left (quit, open another scene). Proceed: saved,
// discarded, or nothing to save. A failed save cancels.
UnsavedChoice askAboutUnsavedEdits(EditorSession& session, PanelState& panels, const char* title, const char* saveLabel,
                                   const char* discardLabel) {
  const std::vector<std::string> tagged = panels.tools.unsavedToolNames();
  if (!session.dirty() && tagged.empty()) return UnsavedChoice::Proceed;
  UnsavedChoice choice = UnsavedChoice::Undecided;
  ImGui::OpenPopup(title);
  if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (session.dirty()) ImGui::Text("%s has unsaved changes.", session.document().file().filename().string().c_str());
    if (!tagged.empty()) {
      ImGui::Text("The sharp tags of %s are not saved.", joined(tagged).c_str());
      ImGui::TextUnformatted("(Save puts them where the Tools panel's Save tags does; a shipped tool's, beside the scene.)");
    }
    if (ImGui::Button(saveLabel)) {
      try {
        panels.tools.saveUnsaved(session);  // first: tags kept in or beside the scene edit it
        if (session.dirty()) session.save();
        choice = UnsavedChoice::Proceed;
      } catch (const std::exception& e) {
        session.status = e.what();
        choice = UnsavedChoice::Cancel;
      }
    }
    recordWidget(panels, "unsaved/save");
    ImGui::SameLine();
    if (ImGui::Button(discardLabel)) choice = UnsavedChoice::Proceed;
    recordWidget(panels, "unsaved/discard");
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escapePressed()) choice = UnsavedChoice::Cancel;
    recordWidget(panels, "unsaved/cancel");
    if (choice != UnsavedChoice::Undecided) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  return choice;
}

void drawQuitPrompt(EditorSession& session, EditorUi& ui) {
  if (ui.quit != QuitPrompt::Asking) return;
  switch (askAboutUnsavedEdits(session, ui.panels, "Unsaved changes", "Save and quit", "Discard and quit")) {
    case UnsavedChoice::Proceed: ui.quit = QuitPrompt::Confirmed; break;
    case UnsavedChoice::Cancel: ui.quit = QuitPrompt::None; break;
    case UnsavedChoice::Undecided: break;
  }
}

void drawOpenPrompt(EditorSession& session, EditorUi& ui) {
  if (ui.panels.openRequest.empty() || ui.open == OpenPrompt::Confirmed) return;
  ui.open = OpenPrompt::Asking;
  switch (askAboutUnsavedEdits(session, ui.panels, "Open another scene", "Save, then open", "Discard them, open")) {
    case UnsavedChoice::Proceed: ui.open = OpenPrompt::Confirmed; break;
    case UnsavedChoice::Cancel:
      ui.open = OpenPrompt::None;
      ui.panels.openRequest.clear();
      break;
    case UnsavedChoice::Undecided: break;
  }
}

// An autosave of the open scene must be recovered or discarded before editing goes on (new edits
// would otherwise replace it); one of another scene can also wait ("Later", or Esc) and is
// offered again when that scene is opened, or at the next start.
void drawRecoveryPrompt(const EditorSession& session, EditorUi& ui) {
  if (ui.recoveries.empty() || ui.recoveryChoice != RecoveryChoice::Undecided) return;
  const Recovery& offered = ui.recoveries.front();
  std::error_code ec;
  const bool openScene = offered.original == std::filesystem::weakly_canonical(session.document().file(), ec);
  ImGui::OpenPopup("Recover unsaved edits?");
  if (ImGui::BeginPopupModal("Recover unsaved edits?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("Weft stopped with unsaved edits to %s", offered.original.string().c_str());
    if (!offered.toolTags.empty()) {
      std::vector<std::string> tools;
      for (const UnsavedToolTags& tags : offered.toolTags) tools.push_back(tags.tool);
      ImGui::Text("and to the sharp tags of %s", joined(tools).c_str());
    }
    ImGui::Text("(autosaved %s).%s", offered.savedAt.c_str(),
                ui.recoveries.size() > 1 ? "  More autosaves follow." : "");
    if (ImGui::Button(openScene ? "Recover them" : "Open it with them")) ui.recoveryChoice = RecoveryChoice::Recover;
    recordWidget(ui.panels, "recovery/recover");
    ImGui::SameLine();
    if (ImGui::Button("Discard them")) ui.recoveryChoice = RecoveryChoice::Discard;
    recordWidget(ui.panels, "recovery/discard");
    if (!openScene) {
      ImGui::SameLine();
      if (ImGui::Button("Later (keep them)") || escapePressed()) ui.recoveryChoice = RecoveryChoice::Later;
      recordWidget(ui.panels, "recovery/later");
    }
    if (ui.recoveryChoice != RecoveryChoice::Undecided) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

}  // namespace

void drawEditorUi(EditorSession& session, EditorUi& ui) {
  // An undo or a removal can take away the selected cloth or obstacle.
  const int cloths = static_cast<int>(session.scene().cloths.size());
  if (ui.panels.cloth >= cloths) ui.panels.cloth = cloths - 1;
  if (ui.panels.obstacle >= static_cast<int>(session.scene().obstacles.size())) ui.panels.obstacle = -1;
  ui.panels.tools.follow(session);  // the tools' tag editors stay with their obstacles
  // Columns as editor_viewport.h lays them out, so the scene shows between them.
  drawMenuBar(session, ui);
  const float m = kPanelMargin;
  const float left = m, leftWidth = kLeftColumnWidth - 2 * m;
  const float right = ImGui::GetIO().DisplaySize.x - kRightColumnWidth + m;
  const float top = kMenuBarHeight + m;
  placeNext(left, top, leftWidth, 250);
  drawScenePanel(session, ui.panels);
  placeNext(left, top + 258, leftWidth, 192);  // room for the timeline
  drawPlaybackPanel(session, ui.panels);
  placeNext(left, top + 458, leftWidth, 208);
  drawSolverPanel(session, ui.panels);
  placeNext(left, top + 674, leftWidth, 170);
  drawToolsPanel(session, ui.panels);
  placeNext(right, top, kRightColumnWidth - 2 * m, 400);
  drawMaterialPanel(session, ui.panels);
  placeNext(right, top + 408, 250, 430);
  drawTearTablePanel(session, ui.panels);
  placeNext(right + 256, top + 408, 204, 260);
  drawWeftPanel(session, ui.panels);
  drawBrowserPanel(session, ui.panels);
  drawStatusBar(session);
  drawStartHint(session);
  // One modal at a time: quitting or opening first; a pending autosave is not lost by either.
  drawQuitPrompt(session, ui);
  if (ui.quit == QuitPrompt::None) drawOpenPrompt(session, ui);
  if (ui.quit == QuitPrompt::None && ui.open == OpenPrompt::None) drawRecoveryPrompt(session, ui);
}

}  // namespace weft::editor
