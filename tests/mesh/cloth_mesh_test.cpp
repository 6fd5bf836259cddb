#include "mesh/cloth_mesh.h"

#include <gtest/gtest.h>

#include "mesh/mesh_check.h"

namespace weft {
namespace {

Triangle makeTriangle(std::array<int, 3> ids, std::array<Vec2, 3> rest) {
  Triangle t;
  t.v = ids;
  t.rest = rest;
  return t;
}

// The unit square split along 0-2:  3---2
//                                   | / |
//                                   0---1
ClothMesh unitSquare() {
  ClothMesh mesh;
  mesh.addVertex(Vec3(0, 0, 0));
  mesh.addVertex(Vec3(1, 0, 0));
  mesh.addVertex(Vec3(1, 1, 0));
  mesh.addVertex(Vec3(0, 1, 0));
  const Vec2 p0(0, 0), p1(1, 0), p2(1, 1), p3(0, 1);
  mesh.tris.push_back(makeTriangle({0, 1, 2}, {p0, p1, p2}));
  mesh.tris.push_back(makeTriangle({0, 2, 3}, {p0, p2, p3}));
  return mesh;
}

TEST(ClothMesh, AddVertexAppendsAVertexAtRest) {
  ClothMesh mesh;
  EXPECT_EQ(mesh.addVertex(Vec3(1, 2, 3)), 0);
  EXPECT_EQ(mesh.addVertex(Vec3(4, 5, 6)), 1);
  ASSERT_EQ(mesh.vertexCount(), 2);
  ASSERT_EQ(mesh.v.size(), 2u);
  ASSERT_EQ(mesh.mass.size(), 2u);
  ASSERT_EQ(mesh.pinned.size(), 2u);
  EXPECT_EQ(mesh.x[1], Vec3(4, 5, 6));
  EXPECT_EQ(mesh.v[1], Vec3::Zero());
  EXPECT_EQ(mesh.mass[1], 0.0);
  EXPECT_EQ(mesh.pinned[1], 0);
}

TEST(ClothMesh, RestAreaIsPositiveCounterClockwiseAndNegativeClockwise) {
  const Vec2 a(0, 0), b(2, 0), c(0, 3);
  EXPECT_DOUBLE_EQ(restArea(makeTriangle({0, 1, 2}, {a, b, c})), 3.0);
  EXPECT_DOUBLE_EQ(restArea(makeTriangle({0, 2, 1}, {a, c, b})), -3.0);
  // Translation does not change the area.
  const Vec2 shift(5, -7);
  EXPECT_DOUBLE_EQ(restArea(makeTriangle({0, 1, 2}, {a + shift, b + shift, c + shift})), 3.0);
}

TEST(ClothMesh, BuildEdgesSharesTheDiagonalAndSortsByEndpoints) {
  ClothMesh mesh = unitSquare();
  buildEdges(mesh);
  ASSERT_EQ(mesh.edgeCount(), 5);
  // Sorted by (lower endpoint, higher endpoint).
  const std::array<std::array<int, 2>, 5> expected{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {2, 3}}};
  for (int e = 0; e < 5; ++e) EXPECT_EQ(mesh.edges[e].v, expected[e]) << "edge " << e;

  const Edge& diagonal = mesh.edges[1];
  EXPECT_EQ(diagonal.tri[0], 0);  // lowest triangle id first
  EXPECT_EQ(diagonal.tri[1], 1);
  EXPECT_FALSE(diagonal.isBoundary());
  EXPECT_TRUE(mesh.edges[0].isBoundary());
  EXPECT_EQ(mesh.edges[0].tri[0], 0);
  EXPECT_EQ(mesh.edges[2].tri[0], 1);

  // Triangle::edge[k] joins v[k] and v[k+1].
  EXPECT_EQ(mesh.tris[0].edge, (std::array<int, 3>{0, 3, 1}));
  EXPECT_EQ(mesh.tris[1].edge, (std::array<int, 3>{1, 4, 2}));
  EXPECT_TRUE(checkMesh(mesh).empty());
}

TEST(ClothMesh, BuildEdgesReplacesAStaleEdgeList) {
  ClothMesh mesh = unitSquare();
  buildEdges(mesh);
  buildEdges(mesh);
  EXPECT_EQ(mesh.edgeCount(), 5);
  EXPECT_TRUE(checkMesh(mesh).empty());
}

TEST(ClothMesh, BuildEdgesKeepsTheFirstTwoTrianglesOfANonManifoldEdge) {
  ClothMesh mesh = unitSquare();
  // A third triangle on the diagonal 0-2, a flap below the sheet.
  const int flap = mesh.addVertex(Vec3(0.5, 0.5, -1));
  mesh.tris.push_back(makeTriangle({0, 2, flap}, {Vec2(0, 0), Vec2(1, 1), Vec2(-1, 2)}));
  buildEdges(mesh);

  const Edge& diagonal = mesh.edges[1];
  ASSERT_EQ(diagonal.v, (std::array<int, 2>{0, 2}));
  EXPECT_EQ(diagonal.tri[0], 0);
  EXPECT_EQ(diagonal.tri[1], 1);
  EXPECT_EQ(mesh.tris[2].edge[0], 1);  // the flap still points at the shared edge
  EXPECT_FALSE(checkMesh(mesh).empty());
}

TEST(ClothMesh, LumpedMassesGiveEachVertexAThirdOfItsTriangles) {
  ClothMesh mesh = unitSquare();
  assignLumpedMasses(mesh, 0.3);
  // Each triangle is 0.5 m^2: 0.05 kg per corner. Vertices 0 and 2 touch both triangles.
  ASSERT_EQ(mesh.mass.size(), 4u);
  EXPECT_DOUBLE_EQ(mesh.mass[0], 0.1);
  EXPECT_DOUBLE_EQ(mesh.mass[1], 0.05);
  EXPECT_DOUBLE_EQ(mesh.mass[2], 0.1);
  EXPECT_DOUBLE_EQ(mesh.mass[3], 0.05);
  EXPECT_DOUBLE_EQ(mesh.mass[0] + mesh.mass[1] + mesh.mass[2] + mesh.mass[3], 0.3 * 1.0);
}

TEST(ClothMesh, LumpedMassesReplaceEarlierMasses) {
  ClothMesh mesh = unitSquare();
  mesh.mass.assign(4, 7.0);
  assignLumpedMasses(mesh, 1.0);
  EXPECT_DOUBLE_EQ(mesh.mass[1], 0.5 / 3.0);
}

TEST(ClothMesh, VertexTrianglesListsIncidentTrianglesInIdOrder) {
  const ClothMesh mesh = unitSquare();
  const std::vector<std::vector<int>> around = vertexTriangles(mesh);
  ASSERT_EQ(around.size(), 4u);
  EXPECT_EQ(around[0], (std::vector<int>{0, 1}));
  EXPECT_EQ(around[1], (std::vector<int>{0}));
  EXPECT_EQ(around[2], (std::vector<int>{0, 1}));
  EXPECT_EQ(around[3], (std::vector<int>{1}));
}

}  // namespace
}  // namespace weft
