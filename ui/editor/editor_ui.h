#pragma once
// The editor's user interface around the viewport: every panel, a status bar, and the prompts
// that keep a user's work (unsaved changes on quit, recovery of an autosave). Draws with ImGui
// between ImGui::NewFrame and ImGui::Render; the platform layer (the GLFW window, or a headless
// EGL context in tests) owns the frame.
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "editor/autosave.h"
#include "editor/editor_session.h"
#include "editor/panels/panels.h"

namespace weft::editor {

enum class QuitPrompt { None, Asking, Confirmed };
enum class OpenPrompt { None, Asking, Confirmed };
// What the user chose for the first autosave offered: recover its edits (opening its scene if
// another is open), discard it, or keep it for later (only for another scene than the open one).
enum class RecoveryChoice { Undecided, Recover, Discard, Later };

struct EditorUi {
  PanelState panels;
  QuitPrompt quit = QuitPrompt::None;   // the app sets Asking when the window wants to close
  OpenPrompt open = OpenPrompt::None;   // Confirmed: the app opens panels.openRequest
  std::vector<Recovery> recoveries;     // autosaves to offer back, the first one shown
  RecoveryChoice recoveryChoice = RecoveryChoice::Undecided;  // for recoveries.front()
  // With panels.openRequest: that scene opens with these recovered edits, its tools' tags
  // included (the workspace sets it).
  std::optional<Recovery> openRecovered;
  bool frameScene = false;    // View > Frame the scene: the app re-frames its camera and clears it
  bool openDialog = false;    // File > Open...
  bool saveAsDialog = false;  // File > Save as...
  bool helpOpen = false;      // Help > Mouse and keys
};

void drawEditorUi(EditorSession& session, EditorUi& ui);

}  // namespace weft::editor
