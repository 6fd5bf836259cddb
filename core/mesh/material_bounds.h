#pragma once
// The bounding box of a cloth's material space: every rest corner of its triangles (tears keep
// them all, so a torn cloth has the bounds it was built with). Where a strength map spans by
// default (tearing/strength_map.h).
#include "mesh/cloth_mesh.h"
#include "util/types.h"

namespace weft {

struct MaterialBounds {
  Vec2 lo = Vec2::Zero();
  Vec2 hi = Vec2::Zero();
};

// Of a mesh with at least one triangle (none: lo = +inf, hi = -inf).
MaterialBounds materialBounds(const ClothMesh& mesh);

}  // namespace weft
