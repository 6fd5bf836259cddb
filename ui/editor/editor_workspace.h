#pragma once
// What the editor has open, and what it owes the user's unsaved work across crashes: the scene
// session, the autosave store, and the autosaves still to offer back. The rules:
// - an autosave holds the scene's unsaved edits and its tools' unsaved sharp tags, and recovering
//   it brings back both (the tags as unsaved edits of their tools);
// - every autosave found at start is offered, the open scene's first; one for another scene can
//   be recovered (that scene opens with the edits), discarded, or kept for later;
// - opening a scene that has an autosave offers it at once (recover or discard: the prompt stays
//   until the user chooses, so new edits never overwrite it unseen);
// - an autosave is deleted only when the user saved, explicitly discarded it, or discarded the
//   edits it holds at an unsaved-changes prompt; one this session never wrote is never deleted.
// No GL here: the app's loop and the headless tests drive it alike.
#include <cstdint>
#include <filesystem>
#include <memory>

#include "editor/autosave.h"
#include "editor/editor_session.h"
#include "editor/editor_ui.h"
#include "editor/tool_tag_editors.h"

namespace weft::editor {

class EditorWorkspace {
 public:
  // Starts on `session` and queues in `ui` every autosave in the store worth offering.
  EditorWorkspace(std::unique_ptr<EditorSession> session, Autosave autosave, EditorUi& ui);

  EditorSession& session() { return *session_; }
  const EditorSession& session() const { return *session_; }
  const Autosave& autosave() const { return autosave_; }

  // After each UI frame: carries out the recovery and open choices the user made. Returns true
  // when the session was replaced by another (the app re-frames its camera).
  bool applyChoices(EditorUi& ui);

  // Every few seconds: writes the user's unsaved edits to the autosave, the scene's and every
  // tool's unsaved sharp tags (in the scene or in files of their own). (Edits made before the
  // first frame, such as --set overrides, are the starting point and are not autosaved.)
  void writeAutosave(const ToolTagEditors& tools);
  // Each frame: once the document and every tool's tags are clean again (saved, saved as, undone
  // to the saved state), the autosave this session wrote has done its job and is removed.
  void forgetAutosaveWhenClean(const ToolTagEditors& tools);

  // The user quit on purpose (after the unsaved-changes prompt): the autosave this session wrote
  // goes, any other stays.
  void quitConfirmed();

 private:
  void replaceSession(std::unique_ptr<EditorSession> next, bool recovered);
  // The recovered tags go to the new session's tools (the old scene's are gone with it).
  void recoverToolTags(const Recovery& recovery, ToolTagEditors& tools);
  void offerAutosaveOf(const std::filesystem::path& scene, EditorUi& ui);

  std::unique_ptr<EditorSession> session_;
  Autosave autosave_;
  std::uint64_t startRevision_ = 0;  // the history revision the user's own edits start after
  bool recovered_ = false;           // the session holds recovered edits: autosaved from the start
  std::filesystem::path wroteAutosaveOf_;  // the file whose autosave this session wrote (empty: none)
};

}  // namespace weft::editor
