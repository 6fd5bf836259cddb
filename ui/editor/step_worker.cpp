#include "step_worker.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "sim/finite_state.h"

namespace weft::editor {

StepWorker::StepWorker(std::unique_ptr<World> world)
    : world_(std::move(world)),
      frameSteps_(std::max<long long>(stepsPerFrame(world_->scene()), 1)),
      snapshot_(snapshotOf(*world_)),
      health_(std::in_place, *world_, frameSteps_),
      thread_([this] { run(); }) {}

StepWorker::~StepWorker() {
  abandonResume_ = true;
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void StepWorker::attach(std::unique_ptr<World> world) {
  abandonResume_ = true;
  std::unique_lock lock(mutex_);
  owed_ = 0;  // steps of the old world are not wanted: only the one running is waited for
  held_ = false;
  resumeFrom_.reset();
  idle_.wait(lock, [&] { return !running_; });
  std::unique_ptr<World> old = std::exchange(world_, std::move(world));
  frameSteps_ = std::max<long long>(stepsPerFrame(world_->scene()), 1);
  changeLog_.clear();
  copies_.clear();
  queued_.clear();
  result_ = StepResult{};
  snapshot_ = snapshotOf(*world_);
  snapshotStale_ = false;
  health_.emplace(*world_, frameSteps_);
  rebaseHealth_ = false;
  abandonResume_ = false;
}

void StepWorker::resumeFrom(std::shared_ptr<const World> frameWorld, long long step) {
  if (!frameWorld) return;
  {
    std::lock_guard lock(mutex_);
    resumeStep_ = std::max(step, frameWorld->stepCount());
    resumeFrom_ = std::move(frameWorld);
    owed_ = 0;
    held_ = false;
  }
  wake_.notify_all();
}

std::shared_ptr<const World> StepWorker::copyWhenIdle() {
  std::shared_ptr<const World> copy = idleWorld().clone();
  std::lock_guard lock(mutex_);
  handedOut(copy);
  return copy;
}

void StepWorker::applyLogged(WorldChange change) {
  change.apply(*world_);
  const long long step = world_->stepCount();
  if (!change.setter.empty() && !changeLog_.empty() && changeLog_.back().step == step &&
      changeLog_.back().change.setter == change.setter) {
    changeLog_.back().change = std::move(change);  // it sets what the one before it set
  } else {
    changeLog_.push_back({step, std::move(change)});
  }
  snapshotStale_ = true;
  rebaseHealth_ = true;
  forgetUnreplayable();
}

void StepWorker::handedOut(const std::shared_ptr<const World>& copy) {
  copies_.emplace_back(copy->stepCount(), copy);
  forgetUnreplayable();
}

// A resume replays the changes logged at or after its copy's step (resume()), and starts only from
// a copy handed out and still held; with none held, any later copy is taken at a later step than
// the world's now. Copies gone are forgotten here too, so the watch list stays as long as the
// timeline's.
void StepWorker::forgetUnreplayable() {
  if (running_) return;  // the world is stepping (or a resume holds the log): next time
  std::erase_if(copies_, [](const auto& copy) { return copy.second.expired(); });
  long long oldest = world_->stepCount();
  for (const auto& [step, copy] : copies_) oldest = std::min(oldest, step);
  std::erase_if(changeLog_, [&](const Logged& logged) { return logged.step < oldest; });
}

std::size_t StepWorker::loggedChanges() const {
  std::lock_guard lock(mutex_);
  return changeLog_.size();
}

std::vector<StepWorker::LoggedBytes> StepWorker::loggedBytes() const {
  std::lock_guard lock(mutex_);
  std::vector<LoggedBytes> bytes;
  bytes.reserve(changeLog_.size());
  // The entry, the std::function's own heap block (the captures of a lambda past its small
  // buffer), the setter's name and what the change says its captures hold.
  constexpr std::size_t kFunctionHeap = 64;
  for (const Logged& logged : changeLog_) {
    bytes.push_back({logged.step, sizeof(Logged) + kFunctionHeap + logged.change.setter.capacity() + logged.change.bytes});
  }
  return bytes;
}

void StepWorker::ask(long long steps, long long maxOwed) {
  {
    std::lock_guard lock(mutex_);
    if (steps <= 0) return;
    owed_ = std::max(std::min(owed_ + steps, maxOwed), owed_ > 0 ? owed_ : 0LL);
  }
  wake_.notify_all();
}

long long StepWorker::owed() const {
  std::lock_guard lock(mutex_);
  return owed_ + (resumeFrom_ ? 1 : 0);  // a resume counts as work owed
}

void StepWorker::wait() {
  std::unique_lock lock(mutex_);
  held_ = false;  // waiting for every owed step lets the worker take them
  wake_.notify_all();
  idle_.wait(lock, [&] { return idle(); });
}

std::optional<StepResult> StepWorker::takeResult() {
  std::lock_guard lock(mutex_);
  if (result_.stepMs.empty() && !result_.nonFiniteAt && !result_.unhealthy && !result_.rewoundTo) return std::nullopt;
  std::optional<StepResult> result = std::move(result_);
  result_ = StepResult{};
  return result;
}

void StepWorker::apply(WorldChange change) {
  std::lock_guard lock(mutex_);
  if (!uiOwnsWorld()) {
    queued_.push_back(std::move(change));
    return;
  }
  applyLogged(std::move(change));
}

World& StepWorker::worldWhenIdle() {
  std::unique_lock lock(mutex_);
  held_ = false;  // waiting for every owed step lets the worker take them
  wake_.notify_all();
  idle_.wait(lock, [&] { return idle(); });
  snapshotStale_ = true;
  rebaseHealth_ = true;
  return *world_;
}

const World& StepWorker::idleWorld() {
  std::unique_lock lock(mutex_);
  held_ = false;
  wake_.notify_all();
  idle_.wait(lock, [&] { return idle(); });
  return *world_;
}

const World& StepWorker::worldBetweenSteps() {
  std::unique_lock lock(mutex_);
  held_ = true;
  idle_.wait(lock, [&] { return !running_ && !resumeFrom_; });
  applyQueued(lock);  // the user's earlier changes come first
  return *world_;
}

void StepWorker::release() {
  {
    std::lock_guard lock(mutex_);
    held_ = false;
  }
  wake_.notify_all();
}

std::shared_ptr<const WorldSnapshot> StepWorker::snapshot() {
  std::lock_guard lock(mutex_);
  if (uiOwnsWorld() && snapshotStale_) {
    snapshot_ = snapshotOf(*world_, snapshot_.get());
    snapshotStale_ = false;
  }
  return snapshot_;
}

// The UI's queued changes, in order. Runs on the worker between steps, holding the lock (edits are
// short; the UI thread's apply() waits for them rather than racing them).
void StepWorker::applyQueued(std::unique_lock<std::mutex>& lock) {
  (void)lock;
  if (queued_.empty()) return;
  for (auto& edit : queued_) applyLogged(std::move(edit));
  queued_.clear();
  snapshot_ = snapshotOf(*world_, snapshot_.get());
}

void StepWorker::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return quit_ || resumeFrom_ || (owed_ > 0 && !held_); });
    if (quit_) return;
    if (resumeFrom_) {
      resume(lock);
      continue;
    }
    applyQueued(lock);
    running_ = true;
    World& world = *world_;
    std::shared_ptr<const WorldSnapshot> previous = snapshot_;
    const bool rebase = std::exchange(rebaseHealth_, false);
    lock.unlock();  // the step itself runs unlocked: the UI thread reads snapshots meanwhile
    if (rebase && health_) health_.emplace(world, stepsPerFrame(world.scene()));
    const auto begin = std::chrono::steady_clock::now();
    world.step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    const bool finite = stateIsFinite(world);
    std::optional<HealthFailure> unhealthy;
    if (health_ && !health_->afterStep(world)) {
      unhealthy = health_->failure();
      health_.reset();  // reported once, as `weft run` reports it
    }
    std::shared_ptr<const WorldSnapshot> next = snapshotOf(world, previous.get());
    const bool frameEnds = world.stepCount() % frameSteps_ == 0;
    std::shared_ptr<const World> frameWorld = frameEnds ? std::shared_ptr<const World>(world.clone()) : nullptr;
    lock.lock();
    running_ = false;
    snapshot_ = std::move(next);
    result_.stepMs.push_back(1000.0 * seconds);
    if (frameEnds) {
      handedOut(frameWorld);
      result_.frames.push_back({world.stepCount() / frameSteps_, snapshot_, std::move(frameWorld)});
    }
    if (unhealthy) result_.unhealthy = std::move(unhealthy);
    // Not below 0: a reset (attach) or a resume while this step ran already dropped the owed
    // steps, this one included; -1 would leave the worker asleep and every wait for idle waiting.
    owed_ = std::max(owed_ - 1, 0LL);
    if (!finite) {
      result_.nonFiniteAt = world.time();
      owed_ = 0;
    }
    if (owed_ == 0) applyQueued(lock);  // nothing the user did waits for the next steps
    idle_.notify_all();  // a step ended: worldBetweenSteps may go on
  }
}

// Copies the frame's world, and steps the copy forward to the step asked for with the logged
// changes replayed where they landed, unlocked (running_): the UI reads the snapshot meanwhile
// and queues its changes, which land on the result. The cached frame's own world stays as it is,
// for the next time the timeline goes back there.
void StepWorker::resume(std::unique_lock<std::mutex>& lock) {
  const std::shared_ptr<const World> from = std::move(resumeFrom_);
  resumeFrom_.reset();
  const long long target = resumeStep_;
  // Changes that landed after the copy was taken: after its step (the copy is taken right after
  // the step, before any change lands there), up to the target.
  std::vector<Logged> log = std::move(changeLog_);
  changeLog_.clear();
  running_ = true;
  lock.unlock();
  std::unique_ptr<World> world = from->clone();
  std::size_t next = 0;
  while (next < log.size() && log[next].step < world->stepCount()) ++next;  // already in the copy
  std::vector<Logged> kept(log.begin(), log.begin() + static_cast<std::ptrdiff_t>(next));
  for (;;) {
    for (; next < log.size() && log[next].step == world->stepCount(); ++next) {
      log[next].change.apply(*world);
      kept.push_back(log[next]);
    }
    if (world->stepCount() >= target || abandonResume_) break;
    world->step();
  }
  if (abandonResume_) {  // a reset or the end of the session: the old world stays until replaced
    lock.lock();
    changeLog_ = std::move(log);
    running_ = false;
    idle_.notify_all();
    return;
  }
  std::shared_ptr<const WorldSnapshot> snapshot = snapshotOf(*world);
  lock.lock();
  running_ = false;
  std::unique_ptr<World> old = std::exchange(world_, std::move(world));
  changeLog_ = std::move(kept);  // what landed later is gone with the frames after this one
  snapshot_ = std::move(snapshot);
  snapshotStale_ = false;
  health_.emplace(*world_, frameSteps_);
  rebaseHealth_ = false;
  result_.frames.clear();  // stepped before the resume: gone with it
  result_.rewoundTo = world_->stepCount();
  applyQueued(lock);
  idle_.notify_all();
  lock.unlock();
  old.reset();  // a large world is freed without holding the UI up
  lock.lock();
}

}  // namespace weft::editor
