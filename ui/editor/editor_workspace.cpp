#include "editor/editor_workspace.h"

#include <algorithm>
#include <system_error>
#include <utility>

#include "util/input_error.h"

namespace weft::editor {

namespace fs = std::filesystem;

namespace {

fs::path canonicalOf(const fs::path& file) {
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(file, ec);
  return ec ? file : resolved;
}

}  // namespace

EditorWorkspace::EditorWorkspace(std::unique_ptr<EditorSession> session, Autosave autosave, EditorUi& ui)
    : session_(std::move(session)), autosave_(std::move(autosave)) {
  startRevision_ = session_->document().history().revision();
  ui.recoveries = autosave_.all();
  // The open scene's autosave first: it must be settled before its edits go on.
  const fs::path open = canonicalOf(session_->document().file());
  std::stable_partition(ui.recoveries.begin(), ui.recoveries.end(),
                        [&](const Recovery& r) { return r.original == open; });
}

void EditorWorkspace::replaceSession(std::unique_ptr<EditorSession> next, bool recovered) {
  session_ = std::move(next);
  startRevision_ = session_->document().history().revision();
  recovered_ = recovered;
  // Recovered edits live in that scene's autosave, which is now this session's to keep or remove.
  wroteAutosaveOf_ = recovered ? session_->document().file() : fs::path();
}

void EditorWorkspace::offerAutosaveOf(const fs::path& scene, EditorUi& ui) {
  const fs::path key = canonicalOf(scene);
  std::erase_if(ui.recoveries, [&](const Recovery& r) { return r.original == key; });
  if (std::optional<Recovery> found = autosave_.find(scene)) ui.recoveries.insert(ui.recoveries.begin(), *found);
}

bool EditorWorkspace::applyChoices(EditorUi& ui) {
  bool replaced = false;
  if (!ui.recoveries.empty() && ui.recoveryChoice != RecoveryChoice::Undecided) {
    const Recovery offered = ui.recoveries.front();
    ui.recoveries.erase(ui.recoveries.begin());
    const bool openScene = offered.original == canonicalOf(session_->document().file());
    switch (ui.recoveryChoice) {
      case RecoveryChoice::Recover:
        if (openScene) {
          try {
            replaceSession(std::make_unique<EditorSession>(session_->document().file(), offered.document), true);
            session_->status = "recovered the unsaved edits autosaved " + offered.savedAt;
            recoverToolTags(offered, ui.panels.tools);
            replaced = true;
          } catch (const InputError& e) {
            ui.recoveries.insert(ui.recoveries.begin(), offered);  // still there, still offered
            session_->status = std::string("cannot recover: ") + e.what();
          }
        } else {
          // Through the open prompt, which first asks about this scene's own unsaved edits.
          ui.panels.openRequest = offered.original;
          ui.openRecovered = offered;
        }
        break;
      case RecoveryChoice::Discard:
        autosave_.discard(offered.original);
        session_->status = "discarded the autosaved edits to " + offered.original.filename().string();
        break;
      case RecoveryChoice::Later:
        session_->status = "kept the autosaved edits to " + offered.original.filename().string() +
                           " for later (offered when it is opened)";
        break;
      case RecoveryChoice::Undecided: break;
    }
    ui.recoveryChoice = RecoveryChoice::Undecided;
  }

  if (ui.open == OpenPrompt::Confirmed) {
    const fs::path request = ui.panels.openRequest;
    try {
      std::unique_ptr<EditorSession> opened = ui.openRecovered
                                                  ? std::make_unique<EditorSession>(request, ui.openRecovered->document)
                                                  : std::make_unique<EditorSession>(request);
      // The scene left behind was saved or its edits discarded at the prompt (or it had none).
      if (!wroteAutosaveOf_.empty()) autosave_.discard(wroteAutosaveOf_);
      const bool recovered = ui.openRecovered.has_value();
      replaceSession(std::move(opened), recovered);
      ui.panels.cloth = 0;
      ui.panels.obstacle = -1;
      ui.panels.tools.clear();  // their unsaved tags were saved or discarded at the prompt
      if (recovered) {
        session_->status = "opened " + request.filename().string() + " with its recovered edits";
        recoverToolTags(*ui.openRecovered, ui.panels.tools);
      } else {
        offerAutosaveOf(request, ui);
      }
      replaced = true;
    } catch (const InputError& e) {
      session_->status = std::string("cannot open: ") + e.what();
    }
    ui.open = OpenPrompt::None;
    ui.panels.openRequest.clear();
    ui.openRecovered.reset();
  } else if (ui.open == OpenPrompt::None && ui.panels.openRequest.empty()) {
    ui.openRecovered.reset();  // the open was cancelled: the autosave stays where it was
  }
  return replaced;
}

void EditorWorkspace::recoverToolTags(const Recovery& recovery, ToolTagEditors& tools) {
  tools.clear();
  const std::string status = session_->status;  // each recovered tool's commit says it too
  const std::vector<std::string> skipped = tools.recover(*session_, recovery.toolTags);
  session_->status = status;
  if (recovery.toolTags.size() > skipped.size()) session_->status += ", and the tools' unsaved sharp tags";
  if (!skipped.empty()) {
    std::string names;
    for (const std::string& name : skipped) names += (names.empty() ? "" : ", ") + name;
    session_->status += "; the autosaved tags of " + names + " were not recovered: the tool is gone from the scene, or its mesh no longer has the tagged vertices";
  }
}

void EditorWorkspace::writeAutosave(const ToolTagEditors& tools) {
  const std::vector<UnsavedToolTags> toolTags = tools.unsavedTags();
  // Tags are the user's own edits from the first one (none exists before the first frame).
  if (!recovered_ && session_->document().history().revision() == startRevision_ && toolTags.empty() &&
      session_->unsavedStrengthMaps().empty())
    return;
  if (!session_->dirty() && toolTags.empty()) return;
  session_->autosave(autosave_, toolTags);
  wroteAutosaveOf_ = session_->document().file();
}

void EditorWorkspace::forgetAutosaveWhenClean(const ToolTagEditors& tools) {
  if (wroteAutosaveOf_.empty()) return;
  // Saved as another file: the autosave under the old name would be offered for the wrong file.
  const bool unsaved = session_->dirty() || !tools.unsavedToolNames().empty();
  if (unsaved && wroteAutosaveOf_ == session_->document().file()) return;
  autosave_.discard(wroteAutosaveOf_);
  wroteAutosaveOf_.clear();
}

void EditorWorkspace::quitConfirmed() {
  if (!wroteAutosaveOf_.empty()) autosave_.discard(wroteAutosaveOf_);
  wroteAutosaveOf_.clear();
}

}  // namespace weft::editor
