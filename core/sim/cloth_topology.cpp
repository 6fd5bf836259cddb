#include "sim/cloth_topology.h"

#include <algorithm>
#include <optional>

namespace weft {
namespace {

void refreshMembranes(Cloth& cloth, const TopologyChange& change) {
  cloth.membranes.resize(cloth.mesh.tris.size());
  for (int t : change.changedTriangles) cloth.membranes[t] = makeMembraneElement(cloth.mesh.tris[t], cloth.weftAngleRad);
}

// Inserts `vertex` (not yet in it) into a track, keeping its vertices sorted.
void addToTrack(PinTrack& track, int vertex, const Vec3& start) {
  const auto slot = std::lower_bound(track.vertices.begin(), track.vertices.end(), vertex);
  const auto offset = slot - track.vertices.begin();
  track.vertices.insert(slot, vertex);
  track.start.insert(track.start.begin() + offset, start);
}

// The vertex's start in the track, or none when the track does not hold it.
std::optional<Vec3> startIn(const PinTrack& track, int vertex) {
  const auto found = std::lower_bound(track.vertices.begin(), track.vertices.end(), vertex);
  if (found == track.vertices.end() || *found != vertex) return std::nullopt;
  return track.start[found - track.vertices.begin()];
}

// A point inserted between two pinned vertices joins every track of the first end, from the start
// interpolated between the ends' (the second end's start from the same track when it holds it,
// else from the first track that does: an edge between two pins takes the first end's script).
// Then a copy, which is the same material point as its original, follows the same script from the
// same start. Splits first: a split point may be separated by the same tear.
void extendPinTracks(Cloth& cloth, const TopologyChange& change) {
  for (const PinnedSplit& split : change.pinnedSplits) {
    std::optional<Vec3> anyToStart;
    for (const PinTrack& track : cloth.pins) {
      if ((anyToStart = startIn(track, split.to))) break;
    }
    for (PinTrack& track : cloth.pins) {
      const std::optional<Vec3> fromStart = startIn(track, split.from);
      if (!fromStart) continue;
      const std::optional<Vec3> toStart = startIn(track, split.to);
      const Vec3 end = toStart ? *toStart : anyToStart ? *anyToStart : *fromStart;
      addToTrack(track, split.vertex, (1.0 - split.fraction) * *fromStart + split.fraction * end);
    }
  }
  for (const auto& [original, copy] : change.vertexCopies) {
    for (PinTrack& track : cloth.pins) {
      if (const std::optional<Vec3> start = startIn(track, original)) addToTrack(track, copy, *start);
    }
  }
}

}  // namespace

void applyTopologyChange(Cloth& cloth, const TopologyChange& change) {
  applyTopologyChangeButHinges(cloth, change);
  refreshHingesAfter(cloth, {change.changedEdges});
}

void applyTopologyChangeButHinges(Cloth& cloth, const TopologyChange& change) {
  refreshMembranes(cloth, change);
  extendPinTracks(cloth, change);
}

void refreshHingesAfter(Cloth& cloth, const std::vector<std::vector<int>>& changedEdgesInOrder) {
  // rebuildElements builds no hinges either without bending.
  if (!bendingEnabled(cloth.material.bending) || changedEdgesInOrder.empty()) return;
  // One pass over the hinges of the cloth, with a flag (the last change) per edge, not a search of
  // the lists per hinge (the search was most of a tear's bookkeeping).
  // Per edge, the last change that listed it: its hinge is that change's (an earlier change's was
  // dropped by a later one), and a hinge from before every change survives only if none listed it.
  std::vector<int> lastChange(cloth.mesh.edges.size(), -1);
  for (std::size_t i = 0; i < changedEdgesInOrder.size(); ++i) {
    for (int e : changedEdgesInOrder[i]) lastChange[e] = static_cast<int>(i);
  }
  std::erase_if(cloth.hinges, [&](const BendingHinge& h) {
    return h.edge >= 0 && h.edge < static_cast<int>(lastChange.size()) && lastChange[h.edge] >= 0;
  });
  for (std::size_t i = 0; i < changedEdgesInOrder.size(); ++i) {
    for (int e : changedEdgesInOrder[i]) {
      if (lastChange[e] != static_cast<int>(i)) continue;
      if (std::optional<BendingHinge> hinge = makeBendingHinge(cloth.mesh, e, cloth.weftAngleRad)) {
        cloth.hinges.push_back(*hinge);
      }
    }
  }
}

}  // namespace weft
