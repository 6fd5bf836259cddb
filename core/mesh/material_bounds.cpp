#include "mesh/material_bounds.h"

#include <limits>

namespace weft {

MaterialBounds materialBounds(const ClothMesh& mesh) {
  MaterialBounds bounds;
  bounds.lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  bounds.hi = -bounds.lo;
  for (const Triangle& t : mesh.tris) {
    for (const Vec2& p : t.rest) {
      bounds.lo = bounds.lo.cwiseMin(p);
      bounds.hi = bounds.hi.cwiseMax(p);
    }
  }
  return bounds;
}

}  // namespace weft
