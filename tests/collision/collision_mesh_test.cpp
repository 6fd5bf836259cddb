#include "collision/collision_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "support/collision_meshes.h"

namespace weft {
namespace {

bool usesVertex(const std::array<int, 3>& triangle, int v) {
  return std::find(triangle.begin(), triangle.end(), v) != triangle.end();
}

// Every vertex and edge owned by exactly one triangle that contains it, the lowest such id.
void expectOwnershipHolds(const CollisionMesh& mesh) {
  const int triangleCount = static_cast<int>(mesh.triangles.size());
  ASSERT_EQ(mesh.vertexOwner.size(), static_cast<size_t>(mesh.vertexCount));
  ASSERT_EQ(mesh.edgeOwner.size(), mesh.edges.size());
  for (int v = 0; v < mesh.vertexCount; ++v) {
    int lowest = -1;
    for (int t = 0; t < triangleCount && lowest < 0; ++t) {
      if (usesVertex(mesh.triangles[t], v)) lowest = t;
    }
    EXPECT_EQ(mesh.vertexOwner[v], lowest) << "vertex " << v;
  }
  for (size_t e = 0; e < mesh.edges.size(); ++e) {
    int lowest = -1;
    for (int t = 0; t < triangleCount && lowest < 0; ++t) {
      if (usesVertex(mesh.triangles[t], mesh.edges[e][0]) && usesVertex(mesh.triangles[t], mesh.edges[e][1])) {
        lowest = t;
      }
    }
    EXPECT_EQ(mesh.edgeOwner[e], lowest) << "edge " << e;
  }
  // Counting features per owning triangle: each feature is counted once, so the totals match.
  int ownedVertices = 0, ownedEdges = 0;
  for (int t = 0; t < triangleCount; ++t) {
    for (int k = 0; k < 3; ++k) {
      ownedVertices += mesh.vertexOwner[mesh.triangles[t][k]] == t ? 1 : 0;
      ownedEdges += mesh.edgeOwner[mesh.triangleEdges[t][k]] == t ? 1 : 0;
    }
  }
  const int usedVertices = static_cast<int>(std::count_if(mesh.vertexOwner.begin(), mesh.vertexOwner.end(),
                                                          [](int owner) { return owner >= 0; }));
  EXPECT_EQ(ownedVertices, usedVertices);
  EXPECT_EQ(ownedEdges, static_cast<int>(mesh.edges.size()));
}

// Edges are unique, sorted within, and triangleEdges points at the edge joining each corner pair.
void expectEdgesMatchTriangles(const CollisionMesh& mesh) {
  std::set<std::array<int, 2>> unique(mesh.edges.begin(), mesh.edges.end());
  EXPECT_EQ(unique.size(), mesh.edges.size());
  for (const auto& e : mesh.edges) EXPECT_LT(e[0], e[1]);
  ASSERT_EQ(mesh.triangleEdges.size(), mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      const std::array<int, 2> expected{std::min(a, b), std::max(a, b)};
      EXPECT_EQ(mesh.edges[mesh.triangleEdges[t][k]], expected) << "triangle " << t << " edge " << k;
    }
  }
}

TEST(CollisionMesh, GridOfTwoByTwoQuadsHasTheExpectedCounts) {
  const CollisionMesh mesh = test::gridMesh(3, 1.0).mesh;  // 3 x 3 vertices, 2 x 2 quads
  EXPECT_EQ(mesh.vertexCount, 9);
  EXPECT_EQ(mesh.triangles.size(), 8u);
  // 6 horizontal + 6 vertical + 4 diagonals.
  EXPECT_EQ(mesh.edges.size(), 16u);
  expectEdgesMatchTriangles(mesh);
  expectOwnershipHolds(mesh);
}

TEST(CollisionMesh, EveryFeatureIsOwnedOnceByTheLowestTriangleContainingIt) {
  expectOwnershipHolds(test::gridMesh(7, 1.0).mesh);
  const CollisionMesh sphere = test::icosphere(1, Vec3::Zero(), 1.0).mesh;
  EXPECT_EQ(sphere.edges.size(), 120u);  // closed: E = 3F / 2
  expectEdgesMatchTriangles(sphere);
  expectOwnershipHolds(sphere);
}

TEST(CollisionMesh, EdgesAreNumberedInOrderOfFirstAppearance) {
  const CollisionMesh mesh = makeCollisionMesh(5, {{0, 1, 2}, {2, 1, 3}, {3, 1, 0}});
  // Triangle 0: (0,1) (1,2) (2,0); triangle 1: (2,1) again, then (1,3) (3,2); triangle 2: (3,1),
  // then (1,0) again, then (0,3).
  const std::vector<std::array<int, 2>> expected = {{0, 1}, {1, 2}, {0, 2}, {1, 3}, {2, 3}, {0, 3}};
  EXPECT_EQ(mesh.edges, expected);
  EXPECT_EQ(mesh.triangleEdges[1], (std::array<int, 3>{1, 3, 4}));
  EXPECT_EQ(mesh.triangleEdges[2], (std::array<int, 3>{3, 0, 5}));
  EXPECT_EQ(mesh.edgeOwner, (std::vector<int>{0, 0, 0, 1, 1, 2}));
  EXPECT_EQ(mesh.vertexOwner, (std::vector<int>{0, 0, 0, 1, -1}));  // vertex 4 is in no triangle
}

TEST(CollisionMesh, EmptyMeshHasNoFeatures) {
  const CollisionMesh mesh = makeCollisionMesh(2, {});
  EXPECT_TRUE(mesh.edges.empty());
  EXPECT_EQ(mesh.vertexOwner, (std::vector<int>{-1, -1}));
}

}  // namespace
}  // namespace weft
