#pragma once
// One undo history for everything the user edits in the editor: the scene document and the sharp
// tags of every tool tagged while the scene is open (each a document of its own, as its tags may
// live in a file beside the tool's mesh). An artist expects Ctrl+Z to take back the latest edit
// whichever panel or click made it, and a tag, then a parameter, then Ctrl+Z twice to undo both in
// reverse order; and a tag on the sword, then picking the hammer, then Ctrl+Z to take back the
// sword's tag. The documents keep their own snapshots (so each is saved and marked clean on its
// own) on one shared EditClock (edit_history.h); the functions here pick, by its ticks, the
// document whose step is the latest to undo or the last undone to redo. The Edit menu, Ctrl+Z /
// Ctrl+Shift+Z / Ctrl+Y and the Scene and Tools panels' Undo and Redo buttons all call these.
#include <string>

#include "editor/editor_session.h"
#include "editor/sharp_tag_edits.h"
#include "editor/tool_tag_editors.h"

namespace weft::editor {

// The editor's history: the scene's, every kept tool's tags (ToolTagEditor joins the session's
// clock when it is made) and every cloth's painted tear strength (EditorSession::strengthPainting,
// a stroke a step, labelled "paint tear strength on CLOTH"). A tool's step is labelled with the tool's name ("toggle sharp vertex 3
// on sword"), and undoing or redoing it makes that tool the current one, so the Tools panel and
// the viewport show what changed.
bool canUndoLatest(const EditorSession& session, const ToolTagEditors& tools);
bool canRedoLatest(const EditorSession& session, const ToolTagEditors& tools);
std::string latestUndoLabel(const EditorSession& session, const ToolTagEditors& tools);  // "" when none
std::string latestRedoLabel(const EditorSession& session, const ToolTagEditors& tools);  // "" when none
void undoLatest(EditorSession& session, ToolTagEditors& tools);  // no-op when nothing to undo
void redoLatest(EditorSession& session, ToolTagEditors& tools);  // no-op when nothing to redo

// The same with one tool (none: only the scene), on the session's clock.
bool canUndoLatest(const EditorSession& session, const ToolTagEditor* tool);
bool canRedoLatest(const EditorSession& session, const ToolTagEditor* tool);
std::string latestUndoLabel(const EditorSession& session, const ToolTagEditor* tool);  // "" when none
std::string latestRedoLabel(const EditorSession& session, const ToolTagEditor* tool);  // "" when none
void undoLatest(EditorSession& session, ToolTagEditor* tool);  // no-op when nothing to undo
void redoLatest(EditorSession& session, ToolTagEditor* tool);  // no-op when nothing to redo

}  // namespace weft::editor
