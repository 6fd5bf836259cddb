#pragma once
// Is a triangle mesh the boundary of a solid? Mass properties (divergence theorem) and contact
// (inside/outside, outward normals) both rely on it, so loaded and generated meshes are checked.
#include <string>
#include <vector>

#include "rigid/triangle_mesh.h"

namespace weft {

// Checks that the mesh is a closed, consistently oriented 2-manifold: at least one triangle, every
// id in range, finite positions, no triangle repeating a vertex or of zero area, every edge shared
// by exactly two triangles that traverse it in opposite directions, every vertex used, and the
// triangles around each vertex forming a single fan (two cubes touching at a corner are rejected).
// Says nothing about which way the surface faces: a closed mesh turned inside out passes, and
// shows up as a negative volume (signedVolume in mass_properties.h). Returns one human-readable
// line per problem (empty when valid).
std::vector<std::string> closedSurfaceProblems(const TriangleMesh& mesh);

}  // namespace weft
