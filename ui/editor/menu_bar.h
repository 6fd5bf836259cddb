#pragma once
// The main menu bar: File / Edit / Playback / View / Help, holding what the panels and keys do,
// each item with its shortcut beside it. Items that the app carries out (quit, frame the scene)
// are requests in EditorUi; the rest act on the session directly, as the panels do.
#include "editor/editor_session.h"
#include "editor/editor_viewport.h"  // kMenuBarHeight
#include "editor/editor_ui.h"

namespace weft::editor {

void drawMenuBar(EditorSession& session, EditorUi& ui);

// The Edit menu's keys, between ImGui::NewFrame and Render when no text field has the keyboard:
// Ctrl+Z undoes the latest edit, scene or sharp tag alike (shared_undo.h); Ctrl+Y and
// Ctrl+Shift+Z redo. ImGui's key map names the keys (the GLFW backend fills it).
void applyEditShortcuts(EditorSession& session, PanelState& state);

}  // namespace weft::editor
