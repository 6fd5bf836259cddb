#include "frame_cache.h"

#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

namespace weft::editor {

namespace {
template <typename T>
std::size_t vectorBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}
}  // namespace

std::size_t snapshotBytes(const WorldSnapshot& snapshot) {
  std::size_t bytes = sizeof(WorldSnapshot);
  for (const ClothMesh& mesh : snapshot.cloths) {
    bytes += sizeof(ClothMesh) + vectorBytes(mesh.x) + vectorBytes(mesh.v) + vectorBytes(mesh.mass) +
             vectorBytes(mesh.pinned) + vectorBytes(mesh.tris) + vectorBytes(mesh.edges);
  }
  for (const ui::ObstacleView& o : snapshot.render.obstacles) {
    bytes += sizeof(o) + vectorBytes(o.vertices) + vectorBytes(o.triangles) + vectorBytes(o.sharpEdges) +
             vectorBytes(o.sharpVertices);
  }
  for (const ui::ClothView& c : snapshot.render.cloths) bytes += sizeof(c) + vectorBytes(c.pinTravel);
  return bytes;
}

void FrameCache::add(long long frame, std::shared_ptr<const WorldSnapshot> snapshot, std::shared_ptr<const World> world) {
  if (!snapshot) return;
  if (auto it = frames_.find(frame); it != frames_.end()) {
    bytes_ -= it->second.snapshotBytes + it->second.worldBytes;
    frames_.erase(it);
  }
  Entry entry;
  entry.snapshotBytes = snapshotBytes(*snapshot);
  entry.worldBytes = world ? world->approximateBytes() : 0;
  entry.snapshot = std::move(snapshot);
  entry.world = std::move(world);
  bytes_ += entry.snapshotBytes + entry.worldBytes;
  frames_.emplace(frame, std::move(entry));
  fitBudget();
}

void FrameCache::setBudget(std::size_t budgetBytes) {
  budgetBytes_ = budgetBytes;
  fitBudget();
}

void FrameCache::setChangeLog(std::vector<LoggedChange> log) {
  changeLog_ = std::move(log);
  fitBudget();
}

std::size_t FrameCache::changeLogBytes() const {
  long long from = -1;  // the oldest frame keeping a copy: the worker keeps the log from there on
  for (const auto& [frame, entry] : frames_) {
    if (entry.world) {
      from = frame;
      break;
    }
  }
  if (from < 0) return 0;
  std::size_t bytes = 0;
  for (const LoggedChange& change : changeLog_) bytes += change.frame >= from ? change.bytes : 0;
  return bytes;
}

void FrameCache::fitBudget() {
  // Thinning copies leaves the log as it is (the first frame's copy stays).
  while (bytes() > budgetBytes_ && dropOneWorld()) {
  }
  // No world copy left to drop: the oldest frames go first, the first frame (frame 0, or the one
  // the log is kept from once frame 0 went) last, the newest never.
  while (bytes() > budgetBytes_ && frames_.size() > 1) {
    auto oldest = frames_.begin();
    if ((oldest->first == 0 || oldest->second.world) && frames_.size() > 2) oldest = std::next(oldest);
    bytes_ -= oldest->second.snapshotBytes + oldest->second.worldBytes;
    frames_.erase(oldest);
  }
}

bool FrameCache::dropOneWorld() {
  // Kept copies in frame order; the first frame's (frame 0's) and the newest frame's stay.
  std::vector<std::map<long long, Entry>::iterator> kept;
  for (auto it = frames_.begin(); it != frames_.end(); ++it) {
    if (it->second.world) kept.push_back(it);
  }
  const long long newest = frames_.empty() ? -1 : frames_.rbegin()->first;
  std::optional<std::size_t> drop;
  long long smallestGap = 0;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const long long frame = kept[i]->first;
    if (frame == frames_.begin()->first || frame == newest) continue;
    // The gap its neighbours would leave between them (the first kept copy's left neighbour is
    // the timeline's start); the smallest gap goes, the older one on a tie.
    const long long before = i > 0 ? kept[i - 1]->first : frames_.begin()->first;
    const long long after = i + 1 < kept.size() ? kept[i + 1]->first : newest;
    const long long gap = after - before;
    if (!drop || gap < smallestGap) {
      drop = i;
      smallestGap = gap;
    }
  }
  if (!drop) return false;
  Entry& entry = kept[*drop]->second;
  bytes_ -= entry.worldBytes;
  entry.world.reset();
  entry.worldBytes = 0;
  return true;
}

std::shared_ptr<const WorldSnapshot> FrameCache::find(long long frame) const {
  const auto it = frames_.find(frame);
  return it == frames_.end() ? nullptr : it->second.snapshot;
}

std::shared_ptr<const World> FrameCache::worldAt(long long frame) const {
  const auto it = frames_.find(frame);
  return it == frames_.end() ? nullptr : it->second.world;
}

std::optional<long long> FrameCache::worldFrameAtOrBefore(long long frame) const {
  for (auto it = frames_.upper_bound(frame); it != frames_.begin();) {
    --it;
    if (it->second.world) return it->first;
  }
  return std::nullopt;
}

std::size_t FrameCache::worldCount() const {
  std::size_t count = 0;
  for (const auto& [frame, entry] : frames_) count += entry.world ? 1 : 0;
  return count;
}

void FrameCache::invalidateAfter(long long frame) {
  for (auto it = frames_.upper_bound(frame); it != frames_.end();) {
    bytes_ -= it->second.snapshotBytes + it->second.worldBytes;
    it = frames_.erase(it);
  }
}

void FrameCache::clear() {
  frames_.clear();
  changeLog_.clear();
  bytes_ = 0;
}

long long FrameCache::firstFrame() const { return frames_.empty() ? -1 : frames_.begin()->first; }
long long FrameCache::lastFrame() const { return frames_.empty() ? -1 : frames_.rbegin()->first; }

std::optional<long long> FrameCache::nearest(long long frame) const {
  if (frames_.empty()) return std::nullopt;
  const auto after = frames_.lower_bound(frame);
  if (after == frames_.begin()) return after->first;
  const auto before = std::prev(after);
  if (after == frames_.end()) return before->first;
  return (frame - before->first <= after->first - frame) ? before->first : after->first;
}

}  // namespace weft::editor
