#pragma once
#include <string>
#include <vector>

#include "mesh/cloth_mesh.h"

namespace weft {

// Checks that the mesh is a consistent oriented 2-manifold with boundary: every index in range,
// no duplicated or dangling elements, each edge used by one or two triangles with opposite
// orientation, Triangle::edge consistent with Edge::tri, positive rest area, finite positions.
// Returns one human-readable line per problem (empty when valid).
std::vector<std::string> checkMesh(const ClothMesh& mesh);

}  // namespace weft
