// The size of a generated obstacle shape, known from its spec before it is built: the counts that
// validation bounds must be the counts the World builds.
#include "scene/shape_size.h"

#include <gtest/gtest.h>

#include <vector>

#include "contact/obstacle.h"

namespace weft {
namespace {

std::int64_t builtTriangles(const ShapeSpec& shape) {
  ObstacleSpec spec;
  spec.shape = shape;
  return static_cast<std::int64_t>(buildObstacle(spec, "shapes.json", 0).topology.triangles.size());
}

TEST(ShapeSize, CountsTheTrianglesTheWorldBuilds) {
  std::vector<ShapeSpec> shapes;
  for (int s = 0; s <= 3; ++s) {
    ShapeSpec sphere;
    sphere.kind = ShapeKind::Sphere;
    sphere.subdivisions = s;
    shapes.push_back(sphere);
  }
  for (const Vec3 halfExtents : {Vec3(0.1, 0.1, 0.1), Vec3(1.0, 0.01, 0.3), Vec3(0.2, 0.7, 0.05)}) {
    for (const int resolution : {1, 3, 16}) {
      ShapeSpec box;
      box.kind = ShapeKind::Box;
      box.halfExtents = halfExtents;
      box.resolution = resolution;
      shapes.push_back(box);
    }
  }
  for (const ShapeKind kind : {ShapeKind::Capsule, ShapeKind::Cylinder}) {
    for (const int segments : {3, 4, 7, 32}) {
      for (const double halfLength : {0.0, 0.05, 1.0}) {
        if (kind == ShapeKind::Cylinder && halfLength == 0.0) continue;  // validation needs > 0
        ShapeSpec shape;
        shape.kind = kind;
        shape.radius = 0.05;
        shape.halfLength = halfLength;
        shape.segments = segments;
        shapes.push_back(shape);
      }
    }
  }
  for (const ShapeSpec& shape : shapes) {
    EXPECT_EQ(shapeTriangleCount(shape), builtTriangles(shape))
        << "kind " << static_cast<int>(shape.kind) << ", segments " << shape.segments << ", resolution "
        << shape.resolution << ", half length " << shape.halfLength;
  }
}

TEST(ShapeSize, AThinLongCylinderHasMillionsOfBands) {
  ShapeSpec cylinder;
  cylinder.kind = ShapeKind::Cylinder;
  cylinder.radius = 0.001;
  cylinder.halfLength = 100.0;
  cylinder.segments = 1024;
  EXPECT_EQ(cylinderBands(cylinder), 32594932);  // 200 m / (2 pi 1 mm / 1024)
  EXPECT_GT(shapeTriangleCount(cylinder), std::int64_t{60'000'000'000});
  cylinder.radius = 0.1;
  cylinder.halfLength = 1.0;
  cylinder.segments = 32;
  EXPECT_EQ(cylinderBands(cylinder), 101);  // the shipped columns' proportions: 2 m / 19.6 mm
}

}  // namespace
}  // namespace weft
