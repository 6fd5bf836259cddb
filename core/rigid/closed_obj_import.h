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
// a finite number or lies beyond ±kMaxToolCoordinate, a mesh spanning less than kMinToolExtent, a
// face with fewer than 3 corners or an index out of range, no faces, a surface that is not closed,
// consistently oriented and 2-manifold (closedSurfaceProblems), or one that encloses a negative
// volume (triangles turned inward).
TriangleMesh loadClosedObj(const std::filesystem::path& path);

// The sizes a tool's OBJ may have, in its own units (a scene scales it by at most 1000). Beyond
// them no scene holds it, and the arithmetic a tool needs breaks first: its inertia sums fifth
// powers of the coordinates (infinite past about 1e61), its volume and areas underflow to 0 below
// about 1e-100 (a valid solid then read as "turned inward" or "of zero area"). Found by fuzzing
// the loader (fuzz/closed_obj_fuzz.cpp): a 1e70 tetrahedron loaded and had an infinite inertia.
inline constexpr double kMaxToolCoordinate = 1e9;
inline constexpr double kMinToolExtent = 1e-9;

}  // namespace weft
