#pragma once
// The surface of a rigid obstacle or tool: a closed triangle mesh in its body frame. The body
// frame is whatever the mesh was modelled in (a sword's grip centre, a ball's centre); a
// RigidBody needs it at the centre of mass (see recentreAtCentreOfMass in mass_properties.h).
#include <array>
#include <vector>

#include "util/types.h"

namespace weft {

struct TriangleMesh {
  std::vector<Vec3> vertices;                 // body frame (m); for a loaded OBJ, vertex i is the file's i-th `v` line
  std::vector<std::array<int, 3>> triangles;  // vertex ids, counter-clockwise seen from outside
};

// Each undirected edge once as {a, b} with a < b, sorted: the edges sharp tags may name.
std::vector<std::array<int, 2>> undirectedEdges(const TriangleMesh& mesh);

}  // namespace weft
