#pragma once
// What one topology change (a tear, later a cut) did to a mesh, so that the caches built on the
// mesh (membrane elements, bending hinges, pin tracks, the integrator's matrix pattern) can be
// patched locally instead of rebuilt. Ids refer to the mesh after the change; nothing is ever
// removed, so every id listed here is valid.
#include <utility>
#include <vector>

namespace weft {

// A vertex inserted on an edge whose two ends are pinned. Such an edge lies in a clamp's jaws, which
// hold every point of it, so the new vertex is pinned too and follows its ends' pin script from the
// start interpolated between theirs (sim/cloth_topology.h).
struct PinnedSplit {
  int vertex = -1;
  int from = -1;          // the split edge's ends
  int to = -1;
  double fraction = 0.5;  // where along from -> to
};

struct TopologyChange {
  std::vector<int> newVertices;                  // appended vertices (edge-split points and copies), ascending
  std::vector<std::pair<int, int>> vertexCopies;  // (original, copy) for each vertex separated in two, in order made
  std::vector<PinnedSplit> pinnedSplits;         // split points between two pinned vertices, in order made
                                                 // (before any copy of them in vertexCopies)
  std::vector<int> changedTriangles;             // triangles whose vertices or rest data changed, and new ones (sorted)
  std::vector<int> newTriangles;                 // the appended triangles (ascending)
  std::vector<int> changedEdges;                 // edges whose endpoints or triangles changed, edges of every
                                                 // changed triangle, and new edges (sorted): the hinges to refresh
  std::vector<int> newEdges;                     // the appended edges (ascending)
  std::vector<int> tornEdges;                    // both copies of every edge the tear opened (sorted)
  std::vector<int> crackEnds;                    // far end of each opened edge, after separation: where the crack
                                                 // now ends (a tear usually continues from there)
  std::vector<int> massChangedVertices;          // vertices whose lumped mass or velocity changed (sorted)
  std::vector<int> movedVertices;                // vertices moved in material space onto a tear line (their rest
                                                 // corners and world positions changed; sorted)

  bool empty() const { return changedTriangles.empty() && changedEdges.empty() && newVertices.empty(); }
};

// Adds `next`, a change made after `into`, to `into`: the result is what both did together to the
// mesh before `into` (lists merged, sorted, without repeats; copies and crack ends in order). As
// nothing is ever removed, a cache patched once with the sum equals one patched with each.
void accumulateTopologyChange(TopologyChange& into, const TopologyChange& next);

}  // namespace weft
