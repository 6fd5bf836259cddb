#pragma once
// One undo history for everything the user edits in the editor: the scene document and the sharp
// tags of the tool being tagged (a document of its own, as its tags may live in a file beside the
// tool's mesh). An artist expects Ctrl+Z to take back the latest edit whichever panel or click made
// it, and a tag, then a parameter, then Ctrl+Z twice to undo both in reverse order. The two
// documents keep their own snapshots (so each is saved and marked clean on its own) on one shared
// EditClock (edit_history.h); the functions here pick, by its ticks, the document whose step is
// the latest to undo or the last undone to redo. The Edit menu, Ctrl+Z / Ctrl+Shift+Z / Ctrl+Y and
// the Scene and Tools panels' Undo and Redo buttons all call these.
#include <string>

#include "editor/editor_session.h"
#include "editor/sharp_tag_edits.h"

namespace weft::editor {

// `tool` is the tool being tagged (none: only the scene), on the session's clock (ToolTagEditor
// joins it when it is made).
bool canUndoLatest(const EditorSession& session, const ToolTagEditor* tool);
bool canRedoLatest(const EditorSession& session, const ToolTagEditor* tool);
std::string latestUndoLabel(const EditorSession& session, const ToolTagEditor* tool);  // "" when none
std::string latestRedoLabel(const EditorSession& session, const ToolTagEditor* tool);  // "" when none
void undoLatest(EditorSession& session, ToolTagEditor* tool);  // no-op when nothing to undo
void redoLatest(EditorSession& session, ToolTagEditor* tool);  // no-op when nothing to redo

}  // namespace weft::editor
