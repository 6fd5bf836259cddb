#include "editor/shared_undo.h"

namespace weft::editor {

namespace {

const EditHistory& sceneHistory(const EditorSession& session) { return session.document().history(); }

// The tool's step is the one to undo when it was committed after the scene's.
bool toolStepIsLatest(const EditorSession& session, const ToolTagEditor* tool) {
  return tool != nullptr && tool->document().history().canUndo() &&
         tool->document().history().undoTick() > sceneHistory(session).undoTick();
}

// The tool's step is the one to redo when it was undone after the scene's.
bool toolStepWasUndoneLast(const EditorSession& session, const ToolTagEditor* tool) {
  return tool != nullptr && tool->document().history().canRedo() &&
         tool->document().history().redoTick() > sceneHistory(session).redoTick();
}

}  // namespace

bool canUndoLatest(const EditorSession& session, const ToolTagEditor* tool) {
  return sceneHistory(session).canUndo() || (tool != nullptr && tool->document().history().canUndo());
}

bool canRedoLatest(const EditorSession& session, const ToolTagEditor* tool) {
  return sceneHistory(session).canRedo() || (tool != nullptr && tool->document().history().canRedo());
}

std::string latestUndoLabel(const EditorSession& session, const ToolTagEditor* tool) {
  return toolStepIsLatest(session, tool) ? tool->document().history().undoLabel() : sceneHistory(session).undoLabel();
}

std::string latestRedoLabel(const EditorSession& session, const ToolTagEditor* tool) {
  return toolStepWasUndoneLast(session, tool) ? tool->document().history().redoLabel() : sceneHistory(session).redoLabel();
}

void undoLatest(EditorSession& session, ToolTagEditor* tool) {
  if (toolStepIsLatest(session, tool)) {
    tool->undo(session);
  } else {
    session.undo();
  }
}

void redoLatest(EditorSession& session, ToolTagEditor* tool) {
  if (toolStepWasUndoneLast(session, tool)) {
    tool->redo(session);
  } else {
    session.redo();
  }
}

}  // namespace weft::editor
