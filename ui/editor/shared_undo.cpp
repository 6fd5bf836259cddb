#include "editor/shared_undo.h"

#include <vector>

namespace weft::editor {

namespace {

const EditHistory& sceneHistory(const EditorSession& session) { return session.document().history(); }

// The tool whose step is the one to undo: of the tools with a step, the one committed latest, when
// that was after the scene's latest. None: the scene's (if any).
template <typename Tool>
Tool* toolToUndo(const EditorSession& session, const std::vector<Tool*>& tools) {
  Tool* latest = nullptr;
  std::uint64_t tick = sceneHistory(session).undoTick();
  for (Tool* tool : tools) {
    const EditHistory& history = tool->document().history();
    if (history.canUndo() && history.undoTick() > tick) {
      latest = tool;
      tick = history.undoTick();
    }
  }
  return latest;
}

// The tool whose step is the one to redo: undone last, after the scene's last undone step.
template <typename Tool>
Tool* toolToRedo(const EditorSession& session, const std::vector<Tool*>& tools) {
  Tool* latest = nullptr;
  std::uint64_t tick = sceneHistory(session).redoTick();
  for (Tool* tool : tools) {
    const EditHistory& history = tool->document().history();
    if (history.canRedo() && history.redoTick() > tick) {
      latest = tool;
      tick = history.redoTick();
    }
  }
  return latest;
}

template <typename Tool>
bool anyCanUndo(const EditorSession& session, const std::vector<Tool*>& tools) {
  if (sceneHistory(session).canUndo()) return true;
  for (Tool* tool : tools) {
    if (tool->document().history().canUndo()) return true;
  }
  return false;
}

template <typename Tool>
bool anyCanRedo(const EditorSession& session, const std::vector<Tool*>& tools) {
  if (sceneHistory(session).canRedo()) return true;
  for (Tool* tool : tools) {
    if (tool->document().history().canRedo()) return true;
  }
  return false;
}

std::string undoLabel(const EditorSession& session, const std::vector<const ToolTagEditor*>& tools) {
  const ToolTagEditor* tool = toolToUndo(session, tools);
  return tool ? tool->document().history().undoLabel() + " on " + tool->name() : sceneHistory(session).undoLabel();
}

std::string redoLabel(const EditorSession& session, const std::vector<const ToolTagEditor*>& tools) {
  const ToolTagEditor* tool = toolToRedo(session, tools);
  return tool ? tool->document().history().redoLabel() + " on " + tool->name() : sceneHistory(session).redoLabel();
}

std::vector<const ToolTagEditor*> oneTool(const ToolTagEditor* tool) {
  return tool ? std::vector<const ToolTagEditor*>{tool} : std::vector<const ToolTagEditor*>{};
}

std::vector<ToolTagEditor*> oneTool(ToolTagEditor* tool) {
  return tool ? std::vector<ToolTagEditor*>{tool} : std::vector<ToolTagEditor*>{};
}

}  // namespace

bool canUndoLatest(const EditorSession& session, const ToolTagEditors& tools) { return anyCanUndo(session, tools.editors()); }
bool canRedoLatest(const EditorSession& session, const ToolTagEditors& tools) { return anyCanRedo(session, tools.editors()); }
std::string latestUndoLabel(const EditorSession& session, const ToolTagEditors& tools) {
  return undoLabel(session, tools.editors());
}
std::string latestRedoLabel(const EditorSession& session, const ToolTagEditors& tools) {
  return redoLabel(session, tools.editors());
}

void undoLatest(EditorSession& session, ToolTagEditors& tools) {
  if (ToolTagEditor* tool = toolToUndo(session, tools.editors())) {
    tools.select(session, tool->obstacle());  // kept already: shows it in the Tools panel
    tool->undo(session);
  } else {
    session.undo();
    tools.follow(session);  // an obstacle removed or added: the tag editors follow theirs
  }
}

void redoLatest(EditorSession& session, ToolTagEditors& tools) {
  if (ToolTagEditor* tool = toolToRedo(session, tools.editors())) {
    tools.select(session, tool->obstacle());
    tool->redo(session);
  } else {
    session.redo();
    tools.follow(session);
  }
}

bool canUndoLatest(const EditorSession& session, const ToolTagEditor* tool) { return anyCanUndo(session, oneTool(tool)); }
bool canRedoLatest(const EditorSession& session, const ToolTagEditor* tool) { return anyCanRedo(session, oneTool(tool)); }
std::string latestUndoLabel(const EditorSession& session, const ToolTagEditor* tool) {
  return undoLabel(session, oneTool(tool));
}
std::string latestRedoLabel(const EditorSession& session, const ToolTagEditor* tool) {
  return redoLabel(session, oneTool(tool));
}

void undoLatest(EditorSession& session, ToolTagEditor* tool) {
  if (ToolTagEditor* latest = toolToUndo(session, oneTool(tool))) {
    latest->undo(session);
  } else {
    session.undo();
  }
}

void redoLatest(EditorSession& session, ToolTagEditor* tool) {
  if (ToolTagEditor* latest = toolToRedo(session, oneTool(tool))) {
    latest->redo(session);
  } else {
    session.redo();
  }
}

}  // namespace weft::editor
