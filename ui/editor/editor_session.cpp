#include "editor_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "editor/installed_data.h"
#include "scene/scene_json.h"
#include "sim/finite_state.h"
#include "sim/live_edit.h"
#include "util/input_error.h"

namespace weft::editor {

namespace {

// What a scene copy holds, roughly: the structs, and for their tables, names and key lists 2 kB a
// cloth (a material's measured table and tear table) and 512 B an obstacle.
std::size_t sceneBytes(const Scene& scene) {
  return sizeof(Scene) + scene.cloths.size() * (sizeof(ClothSpec) + 2048) + scene.obstacles.size() * (sizeof(ObstacleSpec) + 512);
}

Scene parse(const nlohmann::json& j, const std::filesystem::path& file) {
  return parseScene(j, file, defaultSearchPaths(file));
}

}  // namespace

int editorSolverThreads(int requested) {
  const int machine = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::clamp(requested, 1, std::max(1, machine - 1));
}

Scene EditorSession::forTheWorld(const Scene& scene) const {
  Scene runnable = withPaintedMaps(scene);
  runnable.solver.threads = editorSolverThreads(runnable.solver.threads);
  return runnable;
}

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
  if (!document_.history().canUndo()) return;  // nothing to re-apply: the timeline stays as it is
  const std::string label = document_.history().undoLabel();
  refusal_.reset();
  document_.history().undo();
  applyDocument("undo " + label);
}

void EditorSession::redo() {
  if (!document_.history().canRedo()) return;
  const std::string label = document_.history().redoLabel();
  refusal_.reset();
  document_.history().redo();
  applyDocument("redo " + label);
}

// Every state in the history parsed when it was committed, so parsing it again cannot fail.
void EditorSession::applyDocument(const std::string& label) {
  Scene parsed = parse(document_.json(), document_.file());
  followClothNames(parsed);  // a painting stays with its cloth when cloths are removed or added
  Scene edited = forTheWorld(parsed);  // what the brush painted stays, whatever the file names
  // A tool's tags saved into the file the scene now names (sharp_tag_edits.h) change only where
  // the tags come from: live when the world's tool already has them (the tags files are read then,
  // so only for an edit the scene alone would reset for).
  if (needsReset(liveScene_, edited) && needsReset(liveScene_, edited, world())) {
    resetPending_ = true;
    status = label + ": applies after a reset";
  } else {
    // Between steps: the worker may be in the middle of one.
    // Shared, not copied: a slider dragged while playing logs a change every frame.
    auto shared = std::make_shared<const Scene>(edited);
    applyToWorld(WorldChange{[shared](World& world) { applyLiveEdits(world, *shared); }, {}, sceneBytes(edited)});
    liveScene_ = edited;
    resetPending_ = false;
    status = label + ": applied live";
  }
  scene_ = std::move(parsed);
}

void EditorSession::reset() {
  rebuildWorld();
  status = "reset to t = 0";
}

void EditorSession::rebuildWorld() {
  const Scene painted = forTheWorld(scene_);
  auto world = std::make_unique<World>(painted);
  if (worker_) {
    collectSteps();
    worker_->attach(std::move(world));
  } else {
    worker_ = std::make_unique<StepWorker>(std::move(world));
  }
  liveScene_ = painted;
  frameSteps_ = std::max<long long>(weft::stepsPerFrame(scene_), 1);
  frames_.clear();
  frames_.add(0, worker_->snapshot(), worker_->copyWhenIdle());
  lastResume_.reset();
  shownFrame_.reset();
  rewinding_ = false;
  ++worldGeneration_;
  resetPending_ = false;
  stopped_ = false;
  unhealthy_.reset();
  pendingSteps_ = 0.0;
  meteredTime_ = 0.0;
}

EditorSession::~EditorSession() = default;

const World& EditorSession::world() const { return worker_->idleWorld(); }

World& EditorSession::world() {
  World& world = worker_->worldWhenIdle();
  collectSteps();
  return world;
}

const World& EditorSession::worldBetweenSteps() { return worker_->worldBetweenSteps(); }

std::shared_ptr<const WorldSnapshot> EditorSession::view() const {
  if (shownFrame_) {
    if (auto cached = frames_.find(*shownFrame_)) return cached;
  }
  return worker_->snapshot();
}

void EditorSession::applyToWorld(WorldChange change) {
  const std::optional<long long> from =
      shownFrame_ && !rewinding_ && *shownFrame_ < liveFrame() ? frames_.worldFrameAtOrBefore(*shownFrame_) : std::nullopt;
  if (from) {
    // Changing the world while looking at an earlier frame: the world goes back to that frame's
    // own state (a copy of the world kept with it, or with the nearest frame before it, stepped
    // forward), with the scene as the document has it now, and continues from there.
    worker_->resumeFrom(frames_.worldAt(*from), *shownFrame_ * frameSteps_);
    lastResume_ = Resume{*shownFrame_, *from};
    auto scene = std::make_shared<const Scene>(liveScene_);
    worker_->apply(WorldChange{[scene](World& world) { applyLiveEdits(world, *scene); }, {}, sceneBytes(*scene)});
    frames_.invalidateAfter(*shownFrame_);
    rewinding_ = true;
    stopped_ = false;
  } else if (shownFrame_ && !rewinding_) {
    shownFrame_.reset();  // a frame kept without its world: the change lands on the live world, shown
  }
  worker_->apply(std::move(change));
  countChangeLog();
}

void EditorSession::countChangeLog() {
  std::vector<FrameCache::LoggedChange> log;
  for (const StepWorker::LoggedBytes& logged : worker_->loggedBytes()) log.push_back({logged.step / frameSteps_, logged.bytes});
  frames_.setChangeLog(std::move(log));
}

long long EditorSession::liveFrame() const { return worker_->snapshot()->stepCount / frameSteps_; }

void EditorSession::showFrame(long long frame) {
  paused = true;
  const std::optional<long long> nearest = frames_.nearest(frame);
  if (!nearest) return;
  const std::shared_ptr<const WorldSnapshot> live = worker_->snapshot();
  if (*nearest == frames_.lastFrame() && live->stepCount == *nearest * frameSteps_ && !rewinding_) {
    shownFrame_.reset();  // the newest frame is the live world
  } else {
    shownFrame_ = *nearest;
  }
}

void EditorSession::collectSteps() {
  const std::optional<StepResult> result = worker_->takeResult();
  if (!result) return;
  for (double ms : result->stepMs) meter_.addSteps(1, ms);
  if (result->rewoundTo) {
    rewinding_ = false;
    shownFrame_.reset();  // the world is at the shown frame again: live from here
    frames_.invalidateAfter(*result->rewoundTo / frameSteps_);
    meteredTime_ = worker_->snapshot()->time;
  }
  for (const StepResult::Frame& frame : result->frames) frames_.add(frame.frame, frame.snapshot, frame.world);
  countChangeLog();
  if (result->unhealthy && !unhealthy_) {
    unhealthy_ = result->unhealthy;
    status = "warning: " + healthWarning(*unhealthy_);
  }
  if (result->nonFiniteAt && !stopped_) {
    stopped_ = true;
    status = "the simulation became non-finite at t = " + std::to_string(*result->nonFiniteAt) +
             " s; reset, or take a smaller time step";
  }
}

void EditorSession::advanceFrame(double wallSeconds) {
  worker_->release();  // a click's pick held it
  collectSteps();
  if (shownFrame_ && !rewinding_) {
    // Playing from an earlier frame: the cached frames first, at the scene's frame rate, then
    // the simulation where it left off.
    if (!paused) {
      frameClock_ += std::max(speed, 0.0) * std::clamp(wallSeconds, 0.0, kMaxFrameSeconds) /
                     (frameSteps_ * liveScene_.solver.dt);
      const auto whole = static_cast<long long>(std::floor(frameClock_ + 1e-9));
      frameClock_ -= static_cast<double>(whole);
      if (whole > 0) {
        const long long next = *shownFrame_ + whole;
        if (next >= frames_.lastFrame()) {
          shownFrame_.reset();
        } else {
          shownFrame_ = frames_.nearest(next);
        }
      }
    }
    meter_.frame(wallSeconds, 0.0);
    return;
  }
  // What this frame shows: the steps finished before it (those asked for now are the next
  // frames' to show).
  const double shown = worker_->snapshot()->time;
  meter_.frame(wallSeconds, std::max(shown - meteredTime_, 0.0));
  meteredTime_ = shown;
  if (!paused && !stopped_ && !rewinding_) {
    const double dt = liveScene_.solver.dt;
    pendingSteps_ += std::max(speed, 0.0) * std::clamp(wallSeconds, 0.0, kMaxFrameSeconds) / dt;
    // 1e-9: (1/30) / (1/60) must be 2 steps, not 1.999... of them.
    const double whole = std::floor(pendingSteps_ + 1e-9);
    pendingSteps_ = std::max(pendingSteps_ - whole, 0.0);
    const auto maxOwed = static_cast<long long>(std::floor(std::max(speed, 0.0) * kMaxFrameSeconds / dt + 1e-9));
    worker_->ask(static_cast<long long>(whole), std::max(maxOwed, 1LL));  // beyond that: dropped, not owed
  }
}

void EditorSession::stepOnce() {
  worker_->release();
  collectSteps();
  if (shownFrame_ && !rewinding_) {  // through the cached frames first
    const long long next = *shownFrame_ + 1;
    if (next >= frames_.lastFrame()) {
      showFrame(frames_.lastFrame());
    } else {
      shownFrame_ = frames_.nearest(next);
    }
    return;
  }
  if (!stopped_) worker_->ask(1, worker_->owed() + 1);
}

bool EditorSession::savesIntoInstalledData() const { return isInstalledData(document_.file()); }

void EditorSession::save() {
  if (savesIntoInstalledData()) {
    throw std::runtime_error(document_.file().filename().string() +
                             " is a scene shipped with Weft, used by everyone: Save as... to keep your version elsewhere");
  }
  saveStrengthMaps(document_.file(), false);  // the painted maps beside it, the scene naming them
  document_.save();
  status = "saved " + document_.file().string();
}

void EditorSession::saveAs(const std::filesystem::path& file) {
  std::error_code ec;
  if (!file.parent_path().empty()) std::filesystem::create_directories(file.parent_path(), ec);  // else the save says why
  document_.saveAs(file);
  // Every painted map beside the new file, the scene naming it (read from there: after the move).
  saveStrengthMaps(file, true);
  if (document_.dirty()) document_.save();
  status = "saved " + file.string();
}

}  // namespace weft::editor
