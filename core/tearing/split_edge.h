#pragma once
// Inserting a vertex on an edge: the edge's one or two triangles are each split in two.
//
// Triangle (u, w, c), split on side u -> w at the new vertex q, becomes (u, q, c), which keeps the
// triangle's id, and (q, w, c), appended. The split edge keeps its id for the half at the
// side's `from` end; the other half and each spoke q-c are appended. Both halves inherit the
// edge's torn/cut tags, so a split border stays border.
#include <array>
#include <vector>

#include "mesh/cloth_mesh.h"
#include "mesh/topology_change.h"

namespace weft {

// Where on an edge to split it: side `side` of triangle `triangle` (from v[side] to v[side+1]),
// at `fraction` of the way from v[side] (0 < fraction < 1).
struct EdgeSplitPoint {
  int triangle = kNone;
  int side = 0;
  double fraction = 0.5;
};

// The rest shapes (counter-clockwise corner coordinates) of the triangles the split would make,
// without changing the mesh: what the tear's guards judge.
std::vector<std::array<Vec2, 3>> restShapesAfterSplit(const ClothMesh& mesh, const EdgeSplitPoint& at);

// Splits the edge and returns the new vertex. Its position interpolates the endpoints', its rest
// coordinates in each triangle interpolate that triangle's endpoint coordinates, and the lumped
// masses of the triangles' corners are updated for the new areas (`areaDensity` kg/m^2) with
// momentum kept exactly (see split_edge.cpp). When both endpoints are pinned the new vertex is
// pinned too, and listed in change.pinnedSplits.
int splitEdge(ClothMesh& mesh, const EdgeSplitPoint& at, double areaDensity, TopologyChange& change);

}  // namespace weft
