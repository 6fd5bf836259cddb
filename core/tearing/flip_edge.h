#pragma once
// Edge flips in material space: how a split that left a thin triangle beside a crack is repaired
// (Pfaff et al. 2014 restore quality around the crack tip by splitting and flipping edges; a flip
// turns the diagonal of the quad of two triangles to the other diagonal). A flip moves no vertex:
// the cloth's material domain and its world shape stay as they are; only how the quad is cut in
// two changes. The quad's four lumped masses are patched for the new areas and a uniform velocity
// correction of its four vertices keeps the momentum exact.
#include <vector>

#include "mesh/cloth_mesh.h"
#include "mesh/topology_change.h"

namespace weft {

// Flips `edge` when it is interior, not torn or cut, its quad is strictly convex in material space,
// its ends have one rest position in both triangles (no seam), and the smaller of the two
// triangles' smallest angles grows. Returns whether it flipped.
bool flipIfBetter(ClothMesh& mesh, int edge, double areaDensity, TopologyChange& change);

// Flips edges of and around `triangles` (except `keep`) while a flip improves a pair, at most
// `maxPasses` passes over them. Returns whether any edge flipped.
bool improveByFlips(ClothMesh& mesh, std::vector<int> triangles, const std::vector<int>& keep, double areaDensity,
                    TopologyChange& change, int maxPasses = 8);

// Appends what flips changed (their triangles, edges and lumped masses: all a flip changes) to a
// tear's change, unsorted: the tear sorts its lists once it is done.
void appendFlips(TopologyChange& into, const TopologyChange& flips);

}  // namespace weft
