#pragma once
#include <string>

#include "mesh/cloth_mesh.h"
#include "scene/scene.h"

namespace weft {

// Loads a triangle (or polygon, fan-triangulated) OBJ with tinyobjloader. Positions become world
// positions; texture coordinates times uvScale become each corner's rest coordinates (m). Vertices
// that share a position but carry different UVs (a UV seam) are split into separate cloth vertices.
// Throws InputError naming the file for a missing file, no UVs, or a degenerate (zero-area in UV)
// triangle.
ClothMesh loadObjMesh(const ObjSpec& spec, const std::string& referencingFile);

}  // namespace weft
