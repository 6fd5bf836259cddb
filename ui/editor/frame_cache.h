#pragma once
// The timeline's memory (issue 21, item 7): at every output frame simulated, a snapshot of the
// world (positions and topology, as world_snapshot.h copies them), so the scrub bar shows any of
// them again without simulating, and a copy of the world itself (World::clone), so an edit made
// while looking at the frame continues the simulation from that frame's state. Bounded: past
// the byte budget the oldest frames are dropped (never frame 0, the start a scrub most often goes
// back to), and the panel shows the budget. Changing the world while looking at an earlier frame
// drops every frame after it (invalidateAfter). Plain data, no GL and no ImGui.
#include <cstddef>
#include <map>
#include <memory>
#include <optional>

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
  void invalidateAfter(long long frame);
  void clear();

  bool empty() const { return frames_.empty(); }
  long long firstFrame() const;  // -1 when empty
  long long lastFrame() const;   // -1 when empty
  std::size_t frameCount() const { return frames_.size(); }
  std::size_t bytes() const { return bytes_; }
  std::size_t budgetBytes() const { return budgetBytes_; }
  // The cached frame nearest `frame` (ties: the earlier one); none when empty.
  std::optional<long long> nearest(long long frame) const;

  static constexpr std::size_t kDefaultBudgetBytes = std::size_t{512} << 20;  // 512 MiB

 private:
  struct Entry {
    std::shared_ptr<const WorldSnapshot> snapshot;
    std::shared_ptr<const World> world;
    std::size_t bytes = 0;
  };
  std::map<long long, Entry> frames_;
  std::size_t bytes_ = 0;
  std::size_t budgetBytes_;
};

// What a snapshot holds in memory, approximately (its vectors' contents), for the budget.
std::size_t snapshotBytes(const WorldSnapshot& snapshot);

}  // namespace weft::editor
