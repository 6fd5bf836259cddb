#pragma once
#include <string>
#include <vector>

#include "mesh/cloth_mesh.h"

namespace weft {

// Checks that the mesh is a consistent oriented 2-manifold with boundary: every index in range,
// no duplicated or dangling elements, each edge used by one or two triangles with opposite
// orientation (a border edge's triangle in tri[0]), each vertex's triangles forming a single fan
// (no bow-tie), the two triangles of an edge agreeing on its rest length, Triangle::edge
// consistent with Edge::tri, positive rest area, finite positions, velocities and masses.
// Returns one human-readable line per problem (empty when valid).
std::vector<std::string> checkMesh(const ClothMesh& mesh);

// checkMesh's lines grouped by kind (the same words with other numbers), in order of first
// appearance, at most `maxKinds` kinds: a kind seen once is its line, a repeated one its first
// line followed by "(and 1922 more like it)". A sheet of huge coordinates breaks every triangle
// alike; one line says so, where one line per triangle would flood the terminal.
std::vector<std::string> groupProblems(const std::vector<std::string>& problems, std::size_t maxKinds = 10);

}  // namespace weft
