#include "editor_session.h"

#include <cmath>

#include "scene/scene_json.h"
#include "sim/finite_state.h"
#include "sim/live_edit.h"
#include "util/input_error.h"

namespace weft::editor {

namespace {

Scene parse(const nlohmann::json& j, const std::filesystem::path& file) {
  return parseScene(j, file, defaultSearchPaths(file));
}

}  // namespace

EditorSession::EditorSession(const std::filesystem::path& sceneFile)
    : document_(JsonDocument::open(sceneFile)), scene_(parse(document_.json(), sceneFile)) {
  rebuildWorld();
}

EditorSession::EditorSession(const std::filesystem::path& sceneFile, nlohmann::json recovered)
    : document_(JsonDocument::open(sceneFile)), scene_(parse(recovered, sceneFile)) {
  // The recovered edits are one undoable step on top of the file, and unsaved.
  document_.history().commit(std::move(recovered), "recover autosaved edits");
  rebuildWorld();
}

EditResult EditorSession::edit(nlohmann::json next, const std::string& label, const std::string& mergeKey) {
  try {
    (void)parse(next, document_.file());
  } catch (const InputError& e) {
    status = "not applied: " + std::string(e.what());
    return {false, status};
  }
  document_.history().commit(std::move(next), label, mergeKey);
  applyDocument(label);
  return {true, status};
}

void EditorSession::undo() {
  const std::string label = document_.history().undoLabel();
  document_.history().undo();
  applyDocument("undo " + label);
}

void EditorSession::redo() {
  const std::string label = document_.history().redoLabel();
  document_.history().redo();
  applyDocument("redo " + label);
}

// Every state in the history parsed when it was committed, so parsing it again cannot fail.
void EditorSession::applyDocument(const std::string& label) {
  Scene edited = parse(document_.json(), document_.file());
  if (needsReset(world_->scene(), edited)) {
    resetPending_ = true;
    status = label + ": applies after a reset";
  } else {
    applyLiveEdits(*world_, edited);
    resetPending_ = false;
    status = label + ": applied live";
  }
  scene_ = std::move(edited);
}

void EditorSession::reset() {
  rebuildWorld();
  status = "reset to t = 0";
}

void EditorSession::rebuildWorld() {
  world_ = std::make_unique<World>(scene_);
  ++worldGeneration_;
  resetPending_ = false;
  stopped_ = false;
  pendingSteps_ = 0.0;
}

void EditorSession::advance(long long steps) {
  for (long long s = 0; s < steps && !stopped_; ++s) {
    world_->step();
    if (!stateIsFinite(*world_)) {
      stopped_ = true;
      status = "the simulation became non-finite at t = " + std::to_string(world_->time()) +
               " s; reset, or take a smaller time step";
    }
  }
}

void EditorSession::advanceFrame() {
  if (paused || stopped_) return;
  pendingSteps_ += std::max(speed, 0.0) * stepsPerFrame(world_->scene());
  const double whole = std::floor(pendingSteps_);
  pendingSteps_ -= whole;
  advance(static_cast<long long>(whole));
}

void EditorSession::stepOnce() {
  if (!stopped_) advance(1);
}

void EditorSession::save() {
  document_.save();
  status = "saved " + document_.file().string();
}

void EditorSession::saveAs(const std::filesystem::path& file) {
  document_.saveAs(file);
  status = "saved " + file.string();
}

}  // namespace weft::editor
