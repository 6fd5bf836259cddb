#pragma once
#include <string>
#include <vector>

#include "mesh/cloth_mesh.h"
#include "scene/scene.h"

namespace weft {

// Which cloth vertices each `v` line of the file became. Cloth vertices are numbered in `v` order
// (a position used with several UVs, on a UV seam, gives consecutive ids, in order of first use),
// so without seams and unused `v` lines cloth vertex k is the file's (k+1)-th `v` line. Pins by
// vertex id on an OBJ cloth name `v` lines (from 0) and go through this map.
struct ObjVertexMap {
  std::vector<std::vector<int>> clothVertices;  // [v line, from 0]: its cloth vertex ids; empty when no face uses it

  int objVertexCount() const { return static_cast<int>(clothVertices.size()); }
  bool isIdentity() const;  // cloth vertex k is exactly v line k, for every k
};

// Loads a triangle (or polygon, fan-triangulated) OBJ with tinyobjloader. Positions become world
// positions; texture coordinates times uvScale become each corner's rest coordinates (m). Vertices
// that share a position but carry different UVs (a UV seam) are split into separate cloth vertices.
// Throws InputError naming the file for a missing file, no UVs, or a degenerate (zero-area in UV)
// triangle.
// outVertexMap, when given, receives the map above.
ClothMesh loadObjMesh(const ObjSpec& spec, const std::string& referencingFile, ObjVertexMap* outVertexMap = nullptr);

}  // namespace weft
