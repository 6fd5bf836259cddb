#include "scene/shape_size.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "util/types.h"

namespace weft {

int cylinderBands(const ShapeSpec& shape) {
  const double segmentWidth = 2.0 * kPi * shape.radius / shape.segments;
  const double bands = 2.0 * shape.halfLength / segmentWidth;
  // Compared as a double: the cast of a value past INT32_MAX would be undefined.
  if (!(bands < double(std::numeric_limits<int>::max()))) return std::numeric_limits<int>::max();
  return std::max(1, static_cast<int>(bands));
}

std::int64_t shapeTriangleCount(const ShapeSpec& shape) {
  switch (shape.kind) {
    case ShapeKind::Sphere: return std::int64_t{20} << (2 * std::clamp(shape.subdivisions, 0, 30));  // 20 * 4^s
    case ShapeKind::Box: {
      // Cells no larger than the longest side over `resolution` (rigid/shape_meshes.h makeBoxMesh).
      const double maxCellSize = 2.0 * shape.halfExtents.maxCoeff() / shape.resolution;
      std::array<std::int64_t, 3> cells{};
      for (int a = 0; a < 3; ++a) {
        cells[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(2.0 * shape.halfExtents[a] / maxCellSize - 1e-9)));
      }
      return 4 * (cells[0] * cells[1] + cells[1] * cells[2] + cells[2] * cells[0]);
    }
    case ShapeKind::Capsule: {
      // Two fans at the poles and 2 triangles a segment between consecutive rings of latitude.
      const std::int64_t perHemisphere = std::max(1, shape.segments / 4);
      const std::int64_t rings = 2 * perHemisphere - (shape.halfLength > 0.0 ? 0 : 1);
      return 2 * std::int64_t{shape.segments} * rings;
    }
    case ShapeKind::Cylinder:
      // Two cap fans and 2 triangles a segment in each band.
      return 2 * std::int64_t{shape.segments} * (std::int64_t{cylinderBands(shape)} + 1);
    case ShapeKind::Mesh: return 0;
  }
  return 0;
}

}  // namespace weft
