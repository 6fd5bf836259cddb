#pragma once
// The sharp tags of every tool the user has tagged while this scene is open: one ToolTagEditor per
// obstacle, kept until the scene is left. Picking another tool in the Tools panel only changes
// which one is current, so the first tool's unsaved tags and their undo steps are still there when
// it is picked again (the product rule: the editor never loses a user's edits). The current one is
// what the Tools panel and the viewport's tag clicks work on. The shared Undo (shared_undo.h)
// reaches every one's steps, the autosave keeps every one's unsaved tags (autosave.h), and the
// unsaved-changes prompts (quit, open another scene) ask about all of them.
//
// An editor belongs to its obstacle, not to an index: when obstacles before it are removed or
// added (the Scene panel, or an undo or redo of that), follow() moves it to the obstacle's new
// index, so its tags, undo steps, autosave and saves still go to that obstacle. A removed
// obstacle's editor goes with it: set aside, out of the Undo, the autosave and the prompts (the
// scene's removal is the unsaved edit then; saving the scene without the tool drops its tags with
// it). Undoing the removal brings the obstacle back, and its editor with its unsaved tags and undo
// steps.
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "editor/autosave.h"
#include "editor/editor_session.h"
#include "editor/sharp_tag_edits.h"

namespace weft::editor {

class ToolTagEditors {
 public:
  ToolTagEditor* current();  // none: no tool picked
  const ToolTagEditor* current() const;

  // Makes the tool at `obstacle` current: its kept editor, or a new one read from the world.
  // Throws as ToolTagEditor's constructor does (a generated shape); then nothing changes.
  ToolTagEditor& select(const EditorSession& session, int obstacle);
  void deselect();  // no tool is current; every editor is kept
  // The scene's obstacles may have changed since the last call (a removal, an addition, an undo or
  // redo of one): each kept editor follows its obstacle to its index now, matched by name in
  // order (the old and new lists of names aligned, so only those after a removed or added obstacle
  // move). An editor whose obstacle is gone is set aside; one set aside comes back when an obstacle
  // of its name and mesh is back (the removal undone). Cheap when nothing changed: the editor calls
  // it every frame, and after every scene edit, undo and redo that can move obstacles.
  void follow(const EditorSession& session);
  void clear();  // another scene was opened: the prompt settled every unsaved tag first

  // After a reset (the world rebuilt, its obstacles holding the files' tags again): every kept
  // editor's tags are put back into the world, as the user left them (ToolTagEditor::reapply).
  // An editor whose tool is gone from the scene is dropped; returns the names of those that held
  // unsaved tags.
  std::vector<std::string> reapplyAfterReset(EditorSession& session);

  // Every kept editor of an obstacle in the scene, by obstacle index (not those set aside): what
  // the shared Undo looks through.
  std::vector<ToolTagEditor*> editors();
  std::vector<const ToolTagEditor*> editors() const;

  // The unsaved tags of every tool, for the autosave (none: every tool's tags are saved).
  std::vector<UnsavedToolTags> unsavedTags() const;
  // Recovery from an autosave, on the scene it was recovered into: each tool's tags become its
  // kept editor's, unsaved (ToolTagEditor::recover); none is made current. A tool no longer at its
  // index (by name), no longer a mesh, or whose mesh cannot have the tags, is skipped; returns the
  // names of those.
  std::vector<std::string> recover(EditorSession& session, const std::vector<UnsavedToolTags>& tags);

  // The tools whose tags were edited and are not saved (in their file or in the scene), by name.
  std::vector<std::string> unsavedToolNames() const;
  // Saves those tags where the Tools panel's "Save tags" would, without asking: in the scene when
  // they live there, beside the scene for a tool shipped with Weft (its file is shared by other
  // scenes), else in the tool's tags file (ToolTagEditor::saveToToolFile: beside the scene when
  // another obstacle reads that file). A tool kept in or beside the scene edits the scene,
  // which the caller saves next. Throws on the first that cannot be saved (those before it are).
  void saveUnsaved(EditorSession& session);

 private:
  struct Kept {
    Kept(const EditorSession& session, int obstacle);
    ToolTagEditor editor;
    int worldGeneration;                // the world its tags were last applied to (EditorSession::worldGeneration)
    std::filesystem::path meshPath;     // the obstacle's mesh, to know it again when it comes back
  };
  std::map<int, std::unique_ptr<Kept>> kept_;  // by obstacle index
  std::vector<std::unique_ptr<Kept>> aside_;   // of obstacles removed from the scene, latest last
  std::vector<std::string> names_;             // the scene's obstacles' names when last followed
  int current_ = -1;                           // the current tool's obstacle index (-1: none)
};

}  // namespace weft::editor
