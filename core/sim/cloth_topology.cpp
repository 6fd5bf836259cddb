#include "sim/cloth_topology.h"

#include <algorithm>
#include <optional>

namespace weft {
namespace {

void refreshMembranes(Cloth& cloth, const TopologyChange& change) {
  cloth.membranes.resize(cloth.mesh.tris.size());
  for (int t : change.changedTriangles) cloth.membranes[t] = makeMembraneElement(cloth.mesh.tris[t], cloth.weftAngleRad);
}

// One pass over the hinges to drop the changed edges' (a hinge depends only on its edge's two
// triangles), then one new hinge per changed interior edge. changedEdges is sorted.
void refreshHinges(Cloth& cloth, const TopologyChange& change) {
  if (!bendingEnabled(cloth.material.bending)) return;  // rebuildElements builds none either
  const std::vector<int>& edges = change.changedEdges;
  // A flag per edge, not a search of the list per hinge: this pass runs once per tear over every
  // hinge of the cloth, and the search was most of a tear's bookkeeping.
  std::vector<char> changed(cloth.mesh.edges.size(), 0);
  for (int e : edges) changed[e] = 1;
  std::erase_if(cloth.hinges, [&](const BendingHinge& h) {
    return h.edge >= 0 && h.edge < static_cast<int>(changed.size()) && changed[h.edge];
  });
  for (int e : edges) {
    if (std::optional<BendingHinge> hinge = makeBendingHinge(cloth.mesh, e, cloth.weftAngleRad)) {
      cloth.hinges.push_back(*hinge);
    }
  }
}

// A copy is the same material point as its original, so it follows the same script from the
// same start.
void extendPinTracks(Cloth& cloth, const TopologyChange& change) {
  for (const auto& [original, copy] : change.vertexCopies) {
    for (PinTrack& track : cloth.pins) {
      const auto found = std::lower_bound(track.vertices.begin(), track.vertices.end(), original);
      if (found == track.vertices.end() || *found != original) continue;
      const Vec3 start = track.start[found - track.vertices.begin()];
      const auto slot = std::lower_bound(track.vertices.begin(), track.vertices.end(), copy);
      const auto offset = slot - track.vertices.begin();
      track.vertices.insert(slot, copy);
      track.start.insert(track.start.begin() + offset, start);
    }
  }
}

}  // namespace

void applyTopologyChange(Cloth& cloth, const TopologyChange& change) {
  refreshMembranes(cloth, change);
  refreshHinges(cloth, change);
  extendPinTracks(cloth, change);
}

}  // namespace weft
