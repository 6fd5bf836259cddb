#pragma once
// The timeline's memory (issue 21, item 7): at every output frame simulated, a snapshot of the
// world (positions and topology, as world_snapshot.h copies them), so the scrub bar shows any of
// them again without simulating, and a copy of the world itself (World::clone), so an edit made
// while looking at a frame continues the simulation from there instead of from t = 0.
//
// Bounded by a byte budget, shown in the Playback panel. A world copy weighs several snapshots
// (its contact and tearing state: ~10 snapshots on a contact scene), so past the budget the
// copies go first, thinned evenly: the copy whose frame is closest to its kept neighbours' is
// dropped (never frame 0's or the newest frame's), so the kept copies stay spread over the whole
// timeline and a resume steps forward from the nearest one before a frame, never far. Only when
// no copy is left to drop do the oldest frames go (frame 0 last). Changing the world while
// looking at an earlier frame drops every frame after it (invalidateAfter). Plain data, no GL and
// no ImGui.
//
// The budget counts the step worker's change log too (the user's changes a resume replays,
// step_worker.h): the worker keeps it from the oldest world copy held on, so the cache counts the
// changes logged in or after its oldest frame keeping a copy. While frame 0 keeps its copy that
// is the session's changes (a few hundred bytes each): they take the place of frames, the oldest
// going first, and once frame 0 itself has to go the log shrinks to the frames left.
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "editor/world_snapshot.h"

namespace weft::editor {

class FrameCache {
 public:
  explicit FrameCache(std::size_t budgetBytes = kDefaultBudgetBytes) : budgetBytes_(budgetBytes) {}

  // Keeps `snapshot` and `world` (none: the frame is only shown, never resumed from) as output
  // frame `frame`, replacing what was there.
  void add(long long frame, std::shared_ptr<const WorldSnapshot> snapshot, std::shared_ptr<const World> world = nullptr);
  std::shared_ptr<const WorldSnapshot> find(long long frame) const;
  std::shared_ptr<const World> worldAt(long long frame) const;  // none when not cached or not kept
  // The latest frame at or before `frame` that keeps its world; none when there is none.
  std::optional<long long> worldFrameAtOrBefore(long long frame) const;
  void invalidateAfter(long long frame);
  void clear();
  void setBudget(std::size_t budgetBytes);  // drops what no longer fits, as add() does
  // The worker's change log, in order: the frame each change landed in and its bytes. Counted
  // from the oldest frame keeping a copy on; drops what no longer fits, as add() does.
  struct LoggedChange {
    long long frame = 0;
    std::size_t bytes = 0;
  };
  void setChangeLog(std::vector<LoggedChange> log);

  bool empty() const { return frames_.empty(); }
  long long firstFrame() const;  // -1 when empty
  long long lastFrame() const;   // -1 when empty
  std::size_t frameCount() const { return frames_.size(); }
  std::size_t worldCount() const;  // frames that keep their world
  std::size_t bytes() const { return bytes_ + changeLogBytes(); }  // within the budget
  std::size_t changeLogBytes() const;  // the part of bytes() the change log takes
  std::size_t budgetBytes() const { return budgetBytes_; }
  // The cached frame nearest `frame` (ties: the earlier one); none when empty.
  std::optional<long long> nearest(long long frame) const;

  static constexpr std::size_t kDefaultBudgetBytes = std::size_t{512} << 20;  // 512 MiB

 private:
  struct Entry {
    std::shared_ptr<const WorldSnapshot> snapshot;
    std::shared_ptr<const World> world;
    std::size_t snapshotBytes = 0;
    std::size_t worldBytes = 0;  // 0 when the world is not kept
  };
  void fitBudget();
  bool dropOneWorld();  // the evenly thinned one (see above); false when none may go

  std::map<long long, Entry> frames_;
  std::size_t bytes_ = 0;  // snapshots and copies
  std::vector<LoggedChange> changeLog_;
  std::size_t budgetBytes_;
};

// What a snapshot holds in memory, approximately (its vectors' contents), for the budget.
std::size_t snapshotBytes(const WorldSnapshot& snapshot);

}  // namespace weft::editor
