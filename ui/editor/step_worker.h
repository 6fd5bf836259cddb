#pragma once
// Steps the editor's world on a thread of its own, so the window draws at the display's rate and
// the panels answer while a step takes longer than a frame (issue 21, item 6).
//
// The handoff, in one rule: while steps are owed, only the worker touches the world. The UI
// thread reads the latest snapshot (world_snapshot.h, published after every step) and hands its
// changes to the world (live edits, the grab, a dragged tool, sharp tags, a thrown ball) to
// apply(): carried out at once while the worker is idle, else queued and carried out by the
// worker between two steps, in the order they were made. Code that must read the world itself
// (picking on a click, a reset) first waits for the step in flight to end.
//
// Health: after every step the worker runs the health check `weft run` runs (sim/health_check.h)
// and reports its first failure; the user's changes (a grab pulls, a thrown ball brings energy,
// an edit of the wind) restart its energy baseline, since they are input the check cannot see.
//
// Resuming (the timeline, item 7): every output frame stepped comes with a copy of the world
// at its end (World::clone), which the timeline caches beside the frame's snapshot (thinned
// evenly when memory runs short, frame_cache.h). Going back to a cached frame puts a copy of that
// frame's world in place of the live one, made on the worker: the simulation continues from the
// frame's own state, nothing is re-simulated. When that frame's copy was thinned away, the
// nearest earlier copy is stepped forward to the frame, every change applied since replayed
// where it landed (each change is logged with the step it landed after; World::step is
// deterministic), so the world is the frame's exactly; never from t = 0 unless that is nearest.
// The log is kept from the oldest world copy still held anywhere on (the timeline's, a resume's):
// a resume starts from such a copy and replays only what landed at or after its step, so what
// landed before the oldest one can never be replayed again and is dropped. While frame 0's copy
// is held that is the whole session, so the log is kept small and paid for:
// - a change that only sets a value (a dragged grab's target, a dragged tool's position) replaces
//   the same setter's change logged right before it between the same two steps: a drag while
//   paused logs one change, not one a frame;
// - every change states the bytes its captures hold, and the timeline counts the log's bytes in
//   its budget (FrameCache::setChangeLog): past the budget frames go as for snapshots, and the log
//   shrinks when the oldest copy goes. Memory stays within the budget; every frame kept still
//   resumes exactly.
//
// Determinism: the worker runs World::step exactly as `weft run` does, one after another; only
// when an edit lands (between which two steps) depends on timing, as it does for any user.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "editor/world_snapshot.h"
#include "sim/health_check.h"
#include "sim/world.h"

namespace weft::editor {

// What the worker did since it was last asked, for the playback meter and the status bar.
struct StepResult {
  std::vector<double> stepMs;          // wall ms of each step taken
  std::optional<double> nonFiniteAt;   // s: stepping stopped on a non-finite state at this time
  std::optional<HealthFailure> unhealthy;  // the health check's first failure (stepping goes on)
  // Every output frame stepped (for the timeline): its snapshot and a copy of the world to resume from.
  struct Frame {
    long long frame = 0;
    std::shared_ptr<const WorldSnapshot> snapshot;
    std::shared_ptr<const World> world;
  };
  std::vector<Frame> frames;
  std::optional<long long> rewoundTo;  // a resume finished: the world is back at this step
};

// A change to the world made by the user (an edit, the grab, a dragged tool, tags, a thrown ball).
struct WorldChange {
  std::function<void(World&)> apply;
  // Non-empty: the change only sets the value this names ("grab target", "tool 2 position"),
  // whatever was set before; a later change with the same setter, logged right after it between
  // the same two steps, replaces it in the log (replaying both or the last gives the same world).
  std::string setter;
  std::size_t bytes = 0;  // heap bytes its captures hold (a scene, a tag set), for the budget
};

class StepWorker {
 public:
  // Starts the thread, idle, on `world`.
  explicit StepWorker(std::unique_ptr<World> world);
  // Drops the owed steps after the one running (and a resume in progress), and joins the thread.
  ~StepWorker();
  StepWorker(const StepWorker&) = delete;
  StepWorker& operator=(const StepWorker&) = delete;

  // Replaces the world (a reset built a new one): waits for the step in flight, drops the owed
  // steps, a resume in progress, the queued edits (they were for the old world) and the
  // uncollected result.
  void attach(std::unique_ptr<World> world);

  // Replaces the world by a copy of `frameWorld` (a cached frame's, see above: a copy this worker
  // handed out, since the log is kept only as far back as those go) stepped forward to `step`
  // (none: as it is), on the worker, and returns at once; owed steps are dropped, changes applied
  // after the call land on the result.
  void resumeFrom(std::shared_ptr<const World> frameWorld, long long step);
  // A copy of the world as it is now, once the owed steps are taken (frame 0 of the timeline).
  std::shared_ptr<const World> copyWhenIdle();

  // Asks for `steps` more steps and returns at once. The steps still owed never exceed
  // `maxOwed`: when the worker is that far behind, further steps are dropped, not owed (a heavy
  // scene falls behind real time instead of owing ever more). A non-finite state drops every
  // owed step.
  void ask(long long steps, long long maxOwed);
  long long owed() const;  // steps asked for and not yet taken
  bool busy() const { return owed() > 0; }
  // Blocks until every step asked for is taken.
  void wait();
  // What was done since the last call (step times, a non-finite stop); none when nothing was.
  std::optional<StepResult> takeResult();

  // Changes the world between steps (see above). `edit` runs on the UI thread or the worker's.
  void apply(WorldChange change);
  void apply(std::function<void(World&)> edit) { apply(WorldChange{std::move(edit), {}, 0}); }
  // The world for the UI thread to read or change directly. worldWhenIdle waits for every owed
  // step; worldBetweenSteps only for the step in flight, and holds the worker until release()
  // (a click picks on the world without waiting for a heavy scene's owed steps). The snapshot is
  // refreshed afterwards, since the caller may change the world.
  World& worldWhenIdle();  // changes made through it are not logged: use apply()
  const World& idleWorld();
  const World& worldBetweenSteps();
  void release();

  // What the world looked like after the latest step or change.
  std::shared_ptr<const WorldSnapshot> snapshot();

  // Changes kept for a resume to replay (see above): bounded by the oldest world copy held.
  std::size_t loggedChanges() const;
  // The log for the timeline's budget: each change's step (the step it landed after) and bytes.
  struct LoggedBytes {
    long long step = 0;
    std::size_t bytes = 0;
  };
  std::vector<LoggedBytes> loggedBytes() const;

 private:
  void run();
  void applyQueued(std::unique_lock<std::mutex>& lock);
  bool uiOwnsWorld() const { return !running_ && !resumeFrom_ && (owed_ == 0 || held_); }  // under mutex_
  bool idle() const { return !running_ && !resumeFrom_ && owed_ == 0; }                    // under mutex_
  void applyLogged(WorldChange change);  // under mutex_, the world not stepping
  void resume(std::unique_lock<std::mutex>& lock);
  void handedOut(const std::shared_ptr<const World>& copy);  // under mutex_
  void forgetUnreplayable();                                 // under mutex_

  mutable std::mutex mutex_;
  std::condition_variable wake_;  // steps owed, or quit
  std::condition_variable idle_;  // a step ended
  std::unique_ptr<World> world_;
  long long frameSteps_ = 1;  // steps of an output frame
  std::shared_ptr<const World> resumeFrom_;  // asked for, not yet done
  long long resumeStep_ = 0;                 // ... stepped forward to this step
  struct Logged {
    long long step = 0;  // landed after this step
    WorldChange change;
  };
  std::vector<Logged> changeLog_;
  // Every world copy handed out (frames, copyWhenIdle) and the step it was taken at; watched, not
  // owned: the timeline decides how long a copy lives, and with it how far back the log goes.
  std::vector<std::pair<long long, std::weak_ptr<const World>>> copies_;
  long long owed_ = 0;  // steps asked for and not yet taken (the one running included)
  StepResult result_;
  std::vector<WorldChange> queued_;
  std::shared_ptr<const WorldSnapshot> snapshot_;
  bool snapshotStale_ = false;  // the UI thread changed the world since the snapshot was taken
  std::optional<HealthCheck> health_;  // none after its first failure, until attach()
  bool rebaseHealth_ = false;          // the UI changed the world: the check starts afresh
  bool running_ = false;  // a step is running (unlocked) on the worker
  bool held_ = false;     // worldBetweenSteps: no step starts until release()
  bool quit_ = false;
  // A reset or the end of the session abandons a resume in progress (it may be stepping a copy
  // forward) instead of waiting for it; read by the worker between the resume's steps.
  std::atomic<bool> abandonResume_{false};
  std::thread thread_;  // last: started once everything above is ready
};

}  // namespace weft::editor
