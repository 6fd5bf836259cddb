#pragma once
// Loads an obstacle or tool surface from an OBJ file (tinyobjloader).
#include <filesystem>

#include "rigid/triangle_mesh.h"

namespace weft {

// Reads the `v` positions and `f` faces of an OBJ as a closed triangle mesh in its body frame.
// Vertex i is the file's i-th `v` line (counting from 0, across groups and objects), so ids in a
// sharp-tag file stay valid; nothing is welded, reordered or dropped. Polygons are split into a
// fan from their first corner. Texture coordinates, normals and materials are ignored.
// Throws an InputError naming the file for: a missing or unreadable file, a coordinate that is not
// a finite number, a face with fewer than 3 corners or an index out of range, no faces, a surface
// that is not closed, consistently oriented and 2-manifold (closedSurfaceProblems), or one that
// encloses a negative volume (triangles turned inward).
TriangleMesh loadClosedObj(const std::filesystem::path& path);

}  // namespace weft
