#pragma once
// The editor's user interface around the viewport: every panel, a status bar, and the prompts
// that keep a user's work (unsaved changes on quit, recovery of an autosave). Draws with ImGui
// between ImGui::NewFrame and ImGui::Render; the platform layer (the GLFW window, or a headless
// EGL context in tests) owns the frame.
#include <optional>

#include "editor/autosave.h"
#include "editor/editor_session.h"
#include "editor/panels/panels.h"

namespace weft::editor {

enum class QuitPrompt { None, Asking, Confirmed };
enum class OpenPrompt { None, Asking, Confirmed };
enum class RecoveryChoice { Undecided, Recover, Discard };

struct EditorUi {
  PanelState panels;
  QuitPrompt quit = QuitPrompt::None;   // the app sets Asking when the window wants to close
  OpenPrompt open = OpenPrompt::None;   // Confirmed: the app opens panels.openRequest
  std::optional<Recovery> recovery;     // an autosave offered back at start
  RecoveryChoice recoveryChoice = RecoveryChoice::Undecided;
};

void drawEditorUi(EditorSession& session, EditorUi& ui);

}  // namespace weft::editor
