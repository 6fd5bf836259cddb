#pragma once
// The main menu bar: File / Edit / Playback / View / Help, holding what the panels and keys do,
// each item with its shortcut beside it. Items that the app carries out (quit, frame the scene)
// are requests in EditorUi; the rest act on the session directly, as the panels do.
#include "editor/editor_session.h"
#include "editor/editor_viewport.h"  // kMenuBarHeight
#include "editor/editor_ui.h"

namespace weft::editor {

void drawMenuBar(EditorSession& session, EditorUi& ui);

}  // namespace weft::editor
