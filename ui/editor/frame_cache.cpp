#include "frame_cache.h"

#include <cmath>
#include <iterator>

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
    bytes_ -= it->second.bytes;
    frames_.erase(it);
  }
  const std::size_t size = snapshotBytes(*snapshot) + (world ? world->approximateBytes() : 0);
  frames_.emplace(frame, Entry{std::move(snapshot), std::move(world), size});
  bytes_ += size;
  // Over budget: the oldest frames go first, frame 0 last, the newest never.
  while (bytes_ > budgetBytes_ && frames_.size() > 1) {
    auto oldest = frames_.begin();
    if (oldest->first == 0 && frames_.size() > 2) oldest = std::next(oldest);
    bytes_ -= oldest->second.bytes;
    frames_.erase(oldest);
  }
}

std::shared_ptr<const WorldSnapshot> FrameCache::find(long long frame) const {
  const auto it = frames_.find(frame);
  return it == frames_.end() ? nullptr : it->second.snapshot;
}

std::shared_ptr<const World> FrameCache::worldAt(long long frame) const {
  const auto it = frames_.find(frame);
  return it == frames_.end() ? nullptr : it->second.world;
}

void FrameCache::invalidateAfter(long long frame) {
  for (auto it = frames_.upper_bound(frame); it != frames_.end();) {
    bytes_ -= it->second.bytes;
    it = frames_.erase(it);
  }
}

void FrameCache::clear() {
  frames_.clear();
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
