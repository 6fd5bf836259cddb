#pragma once
// How large the mesh of a generated obstacle shape (sphere, box, capsule, cylinder) will be, known
// from its ShapeSpec before it is built. Validation refuses shapes too fine to build
// (scene_limits.h, kMaxShapeTriangles): each field of a cylinder can be in range while together
// they ask for billions of triangles (bands are as tall as a segment is wide, so a thin, long
// cylinder has millions of them). contact/obstacle.cpp builds the shapes with the same counts.
#include <cstdint>

#include "scene/contact_spec.h"

namespace weft {

// A cylinder's bands along its axis: about as tall as its segments are wide, so its sides are not
// slivers; at least 1. Saturates at INT32_MAX for shapes no validated scene holds.
int cylinderBands(const ShapeSpec& shape);

// Triangles of the generated mesh; 0 for a mesh shape (its size is its file's).
std::int64_t shapeTriangleCount(const ShapeSpec& shape);

}  // namespace weft
