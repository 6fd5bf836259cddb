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

// The cloth whose painted tear strength (EditorSession::strengthPainting) holds the step to undo:
// committed after `tick` (the latest of the scene's and the tools'), latest of all; -1: none.
int paintingToUndo(const EditorSession& session, std::uint64_t tick) {
  int latest = -1;
  for (int cloth : session.paintedCloths()) {
    const EditHistory& history = session.findStrengthPainting(cloth)->history();
    if (history.canUndo() && history.undoTick() > tick) {
      latest = cloth;
      tick = history.undoTick();
    }
  }
  return latest;
}

int paintingToRedo(const EditorSession& session, std::uint64_t tick) {
  int latest = -1;
  for (int cloth : session.paintedCloths()) {
    const EditHistory& history = session.findStrengthPainting(cloth)->history();
    if (history.canRedo() && history.redoTick() > tick) {
      latest = cloth;
      tick = history.redoTick();
    }
  }
  return latest;
}

bool anyPaintingCanUndo(const EditorSession& session) { return paintingToUndo(session, 0) >= 0; }
bool anyPaintingCanRedo(const EditorSession& session) { return paintingToRedo(session, 0) >= 0; }

template <typename Tool>
std::uint64_t latestUndoTick(const EditorSession& session, Tool* tool) {
  return tool ? tool->document().history().undoTick() : sceneHistory(session).undoTick();
}

template <typename Tool>
std::uint64_t latestRedoTick(const EditorSession& session, Tool* tool) {
  return tool ? tool->document().history().redoTick() : sceneHistory(session).redoTick();
}

std::string clothName(const EditorSession& session, int cloth) {
  return cloth < static_cast<int>(session.scene().cloths.size()) ? session.scene().cloths[static_cast<std::size_t>(cloth)].name
                                                                 : std::to_string(cloth);
}

std::string undoLabel(const EditorSession& session, const std::vector<const ToolTagEditor*>& tools) {
  const ToolTagEditor* tool = toolToUndo(session, tools);
  if (const int cloth = paintingToUndo(session, latestUndoTick(session, tool)); cloth >= 0)
    return session.findStrengthPainting(cloth)->history().undoLabel() + " on " + clothName(session, cloth);
  return tool ? tool->document().history().undoLabel() + " on " + tool->name() : sceneHistory(session).undoLabel();
}

std::string redoLabel(const EditorSession& session, const std::vector<const ToolTagEditor*>& tools) {
  const ToolTagEditor* tool = toolToRedo(session, tools);
  if (const int cloth = paintingToRedo(session, latestRedoTick(session, tool)); cloth >= 0)
    return session.findStrengthPainting(cloth)->history().redoLabel() + " on " + clothName(session, cloth);
  return tool ? tool->document().history().redoLabel() + " on " + tool->name() : sceneHistory(session).redoLabel();
}

std::vector<const ToolTagEditor*> oneTool(const ToolTagEditor* tool) {
  return tool ? std::vector<const ToolTagEditor*>{tool} : std::vector<const ToolTagEditor*>{};
}

std::vector<ToolTagEditor*> oneTool(ToolTagEditor* tool) {
  return tool ? std::vector<ToolTagEditor*>{tool} : std::vector<ToolTagEditor*>{};
}

}  // namespace

bool canUndoLatest(const EditorSession& session, const ToolTagEditors& tools) {
  return anyCanUndo(session, tools.editors()) || anyPaintingCanUndo(session);
}
bool canRedoLatest(const EditorSession& session, const ToolTagEditors& tools) {
  return anyCanRedo(session, tools.editors()) || anyPaintingCanRedo(session);
}
std::string latestUndoLabel(const EditorSession& session, const ToolTagEditors& tools) {
  return undoLabel(session, tools.editors());
}
std::string latestRedoLabel(const EditorSession& session, const ToolTagEditors& tools) {
  return redoLabel(session, tools.editors());
}

void undoLatest(EditorSession& session, ToolTagEditors& tools) {
  ToolTagEditor* tool = toolToUndo(session, tools.editors());
  if (const int cloth = paintingToUndo(session, latestUndoTick(session, tool)); cloth >= 0) {
    session.undoStrengthPainting(cloth);
  } else if (tool) {
    tools.select(session, tool->obstacle());  // kept already: shows it in the Tools panel
    tool->undo(session);
  } else {
    session.undo();
    tools.follow(session);  // an obstacle removed or added: the tag editors follow theirs
  }
}

void redoLatest(EditorSession& session, ToolTagEditors& tools) {
  ToolTagEditor* tool = toolToRedo(session, tools.editors());
  if (const int cloth = paintingToRedo(session, latestRedoTick(session, tool)); cloth >= 0) {
    session.redoStrengthPainting(cloth);
  } else if (tool) {
    tools.select(session, tool->obstacle());
    tool->redo(session);
  } else {
    session.redo();
    tools.follow(session);
  }
}

bool canUndoLatest(const EditorSession& session, const ToolTagEditor* tool) {
  return anyCanUndo(session, oneTool(tool)) || anyPaintingCanUndo(session);
}
bool canRedoLatest(const EditorSession& session, const ToolTagEditor* tool) {
  return anyCanRedo(session, oneTool(tool)) || anyPaintingCanRedo(session);
}
std::string latestUndoLabel(const EditorSession& session, const ToolTagEditor* tool) {
  return undoLabel(session, oneTool(tool));
}
std::string latestRedoLabel(const EditorSession& session, const ToolTagEditor* tool) {
  return redoLabel(session, oneTool(tool));
}

void undoLatest(EditorSession& session, ToolTagEditor* tool) {
  ToolTagEditor* latest = toolToUndo(session, oneTool(tool));
  if (const int cloth = paintingToUndo(session, latestUndoTick(session, latest)); cloth >= 0) {
    session.undoStrengthPainting(cloth);
  } else if (latest) {
    latest->undo(session);
  } else {
    session.undo();
  }
}

void redoLatest(EditorSession& session, ToolTagEditor* tool) {
  ToolTagEditor* latest = toolToRedo(session, oneTool(tool));
  if (const int cloth = paintingToRedo(session, latestRedoTick(session, latest)); cloth >= 0) {
    session.redoStrengthPainting(cloth);
  } else if (latest) {
    latest->redo(session);
  } else {
    session.redo();
  }
}

}  // namespace weft::editor
