#include "editor_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

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
    status = label + " not applied: " + std::string(e.what());
    refusal_ = Refusal{label, e.what()};
    return {false, status};
  }
  refusal_.reset();
  document_.history().commit(std::move(next), label, mergeKey);
  applyDocument(label);
  return {true, status};
}

void EditorSession::undo() {
  const std::string label = document_.history().undoLabel();
  refusal_.reset();
  document_.history().undo();
  applyDocument("undo " + label);
}

void EditorSession::redo() {
  const std::string label = document_.history().redoLabel();
  refusal_.reset();
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

void EditorSession::advance(long long steps, double budgetSeconds) {
  double spent = 0.0;
  for (long long s = 0; s < steps && !stopped_ && spent < budgetSeconds; ++s) {
    const auto start = std::chrono::steady_clock::now();
    world_->step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    spent += seconds;
    meter_.addSteps(1, 1000.0 * seconds);
    if (!stateIsFinite(*world_)) {
      stopped_ = true;
      status = "the simulation became non-finite at t = " + std::to_string(world_->time()) +
               " s; reset, or take a smaller time step";
    }
  }
}

void EditorSession::advanceFrame(double wallSeconds) {
  const double before = world_->time();
  if (!paused && !stopped_) {
    const double owed = std::max(speed, 0.0) * std::clamp(wallSeconds, 0.0, kMaxFrameSeconds);
    pendingSteps_ += owed / world_->scene().solver.dt;
    // 1e-9: (1/30) / (1/60) must be 2 steps, not 1.999... of them.
    const double whole = std::floor(pendingSteps_ + 1e-9);
    pendingSteps_ = std::max(pendingSteps_ - whole, 0.0);
    advance(static_cast<long long>(whole), kStepBudgetSeconds);  // steps over budget are dropped, not owed
  }
  meter_.frame(wallSeconds, std::max(world_->time() - before, 0.0));
}

void EditorSession::stepOnce() {
  if (!stopped_) advance(1, std::numeric_limits<double>::infinity());
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
