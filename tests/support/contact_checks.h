#pragma once
// Exact checks that contact left no penetration, for the contact tests: every candidate triangle
// pair (from a BVH over the current positions) goes through the exact intersection predicate of
// collision/triangle_intersection.h.
#include <array>
#include <vector>

#include "collision/bvh.h"
#include "collision/triangle_intersection.h"
#include "mesh/cloth_mesh.h"

namespace weft::test {

inline std::vector<Aabb> triangleBoxes(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Aabb> boxes(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) boxes[t].grow(x[triangles[t][k]]);
  }
  return boxes;
}

inline std::vector<std::array<int, 3>> clothTriangles(const ClothMesh& mesh) {
  std::vector<std::array<int, 3>> triangles;
  for (const Triangle& t : mesh.tris) triangles.push_back(t.v);
  return triangles;
}

// Pairs of intersecting triangles between two meshes.
inline int countIntersections(const std::vector<Vec3>& xa, const std::vector<std::array<int, 3>>& ta,
                              const std::vector<Vec3>& xb, const std::vector<std::array<int, 3>>& tb) {
  Bvh a, b;
  a.build(triangleBoxes(xa, ta));
  b.build(triangleBoxes(xb, tb));
  int count = 0;
  a.overlappingPairs(b, [&](int i, int j) {
    const auto& p = ta[i];
    const auto& q = tb[j];
    if (trianglesIntersect(xa[p[0]], xa[p[1]], xa[p[2]], xb[q[0]], xb[q[1]], xb[q[2]])) ++count;
  });
  return count;
}

// Pairs of triangles of one cloth that intersect other than along what they share.
inline int countSelfIntersections(const ClothMesh& mesh) {
  const auto triangles = clothTriangles(mesh);
  Bvh bvh;
  bvh.build(triangleBoxes(mesh.x, triangles));
  int count = 0;
  bvh.selfOverlappingPairs([&](int i, int j) {
    const Vec3 a[3] = {mesh.x[triangles[i][0]], mesh.x[triangles[i][1]], mesh.x[triangles[i][2]]};
    const Vec3 b[3] = {mesh.x[triangles[j][0]], mesh.x[triangles[j][1]], mesh.x[triangles[j][2]]};
    if (meshTrianglesIntersect(a, triangles[i].data(), b, triangles[j].data())) ++count;
  });
  return count;
}

inline int countBelow(const std::vector<Vec3>& x, double height) {
  int count = 0;
  for (const Vec3& p : x) count += p.y() < height ? 1 : 0;
  return count;
}

}  // namespace weft::test
