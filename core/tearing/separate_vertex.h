#pragma once
// Opening edges and separating the vertices that are left with more than one fan.
//
// A tear first opens each cut edge: the edge keeps its first triangle and an appended copy takes
// the second, so both become border edges (tagged torn). The vertices at the ends of the opened
// edges may then have triangles in several fans that meet only at the vertex (a bow-tie: a
// non-manifold vertex). Each fan but one gets its own copy of the vertex, which is what actually
// separates the cloth. Rest coordinates stay as they are in every triangle: both sides of the
// seam keep their material positions.
#include <vector>

#include "mesh/cloth_mesh.h"
#include "mesh/topology_change.h"

namespace weft {

// Opens an interior edge; returns the id of the appended copy. Both are tagged torn.
int openEdge(ClothMesh& mesh, int edge, TopologyChange& change);

// Gives every fan of `vertex` but the first (the one holding the lowest triangle id) a copy of
// the vertex: same position, velocity and pinned flag, and the lumped mass of that fan's
// triangles (`areaDensity` kg/m^2), taken from the original's, so mass and momentum are kept.
// `incidentTriangles` must list every triangle at the vertex. Returns the copies, in the order
// made (nothing for a vertex with one fan).
std::vector<int> separateFans(ClothMesh& mesh, int vertex, std::vector<int> incidentTriangles, double areaDensity,
                              TopologyChange& change);

}  // namespace weft
