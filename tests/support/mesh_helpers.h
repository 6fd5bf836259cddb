#pragma once
// Small mesh helpers shared by the tests.
#include <array>

#include <gtest/gtest.h>

#include "mesh/cloth_mesh.h"

namespace weft::test {

// Splits the vertices of an n x n patch (vertex id = row * n + column, already added) into
// 2 (n-1)^2 counter-clockwise triangles, taking each corner's rest coordinates from the
// vertex's x and y.
inline void triangulatePatch(ClothMesh& mesh, int n) {
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const int a = n * j + i, b = a + 1, c = a + n + 1, d = a + n;
      for (const std::array<int, 3>& corners : {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, d}}) {
        Triangle t;
        t.v = corners;
        for (int k = 0; k < 3; ++k) t.rest[k] = mesh.x[corners[k]].head<2>();
        mesh.tris.push_back(t);
      }
    }
  }
}

// Every array of the two meshes is equal, element by element (determinism checks).
inline void expectSameMesh(const ClothMesh& a, const ClothMesh& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.v, b.v);
  EXPECT_EQ(a.mass, b.mass);
  EXPECT_EQ(a.pinned, b.pinned);
  ASSERT_EQ(a.triangleCount(), b.triangleCount());
  for (int t = 0; t < a.triangleCount(); ++t) {
    EXPECT_EQ(a.tris[t].v, b.tris[t].v);
    EXPECT_EQ(a.tris[t].rest, b.tris[t].rest);
    EXPECT_EQ(a.tris[t].edge, b.tris[t].edge);
  }
  ASSERT_EQ(a.edgeCount(), b.edgeCount());
  for (int e = 0; e < a.edgeCount(); ++e) {
    EXPECT_EQ(a.edges[e].v, b.edges[e].v);
    EXPECT_EQ(a.edges[e].tri, b.edges[e].tri);
  }
}

}  // namespace weft::test
