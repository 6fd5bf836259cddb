#include "mesh/mesh_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "mesh/grid.h"

namespace weft {
namespace {

// Each test breaks one thing in a small valid mesh and expects checkMesh to say so.

ClothMesh smallGrid() {
  GridSpec spec;
  spec.resolutionX = 4;
  spec.resolutionY = 3;
  ClothMesh mesh = makeGrid(spec);
  assignLumpedMasses(mesh, 0.2);
  return mesh;
}

// True when some problem line contains `phrase`; prints the lines otherwise.
::testing::AssertionResult reports(const ClothMesh& mesh, const std::string& phrase) {
  const std::vector<std::string> problems = checkMesh(mesh);
  for (const std::string& line : problems) {
    if (line.find(phrase) != std::string::npos) return ::testing::AssertionSuccess();
  }
  auto failure = ::testing::AssertionFailure() << "no problem mentions \"" << phrase << "\"; got " << problems.size()
                                               << " line(s):";
  for (const std::string& line : problems) failure << "\n  " << line;
  return failure;
}

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

TEST(MeshCheck, AValidMeshHasNoProblems) {
  const std::vector<std::string> problems = checkMesh(smallGrid());
  EXPECT_TRUE(problems.empty()) << problems.front();
}

TEST(MeshCheck, AnEmptyMeshHasNoProblems) { EXPECT_TRUE(checkMesh(ClothMesh{}).empty()); }

TEST(MeshCheck, ReportsAVertexIndexOutOfRange) {
  ClothMesh mesh = smallGrid();
  mesh.tris[3].v[1] = 99;
  EXPECT_TRUE(reports(mesh, "triangle 3: vertex index 99 out of range"));
  mesh.tris[3].v[1] = -5;
  EXPECT_TRUE(reports(mesh, "triangle 3: vertex index -5 out of range"));
}

TEST(MeshCheck, ReportsARepeatedVertexWithinATriangle) {
  ClothMesh mesh = smallGrid();
  mesh.tris[2].v[2] = mesh.tris[2].v[0];
  EXPECT_TRUE(reports(mesh, "triangle 2: repeated vertex"));
}

TEST(MeshCheck, ReportsADuplicatedTriangle) {
  ClothMesh mesh = smallGrid();
  Triangle copy = mesh.tris[0];
  std::rotate(copy.v.begin(), copy.v.begin() + 1, copy.v.end());  // same vertex set, other start
  std::rotate(copy.rest.begin(), copy.rest.begin() + 1, copy.rest.end());
  mesh.tris.push_back(copy);
  buildEdges(mesh);
  EXPECT_TRUE(reports(mesh, "duplicated triangle"));
}

TEST(MeshCheck, ReportsATriangleEdgeThatDoesNotJoinItsCorners) {
  ClothMesh mesh = smallGrid();
  std::swap(mesh.tris[4].edge[0], mesh.tris[4].edge[1]);
  EXPECT_TRUE(reports(mesh, "triangle 4: edge[0]"));
}

TEST(MeshCheck, ReportsATriangleEdgeOutOfRange) {
  ClothMesh mesh = smallGrid();
  mesh.tris[1].edge[2] = kNone;
  EXPECT_TRUE(reports(mesh, "triangle 1: edge[2] = -1 out of range"));
}

TEST(MeshCheck, ReportsAnEdgeWhoseTriangleListDisagreesWithTheTriangles) {
  ClothMesh mesh = smallGrid();
  // Find an interior edge and drop its second triangle from the list.
  int interior = kNone;
  for (int e = 0; e < mesh.edgeCount() && interior == kNone; ++e) {
    if (!mesh.edges[e].isBoundary()) interior = e;
  }
  ASSERT_NE(interior, kNone);
  const int dropped = mesh.edges[interior].tri[1];
  mesh.edges[interior].tri[1] = kNone;
  EXPECT_TRUE(reports(mesh, "edge " + std::to_string(interior) + ": used by triangle " + std::to_string(dropped)));
}

TEST(MeshCheck, ReportsAnEdgeListingATriangleThatDoesNotUseIt) {
  ClothMesh mesh = smallGrid();
  int boundary = kNone;
  for (int e = 0; e < mesh.edgeCount() && boundary == kNone; ++e) {
    if (mesh.edges[e].isBoundary()) boundary = e;
  }
  ASSERT_NE(boundary, kNone);
  const int stranger = mesh.edges[boundary].tri[0] == 0 ? 1 : 0;
  ASSERT_NE(mesh.tris[stranger].edge[0], boundary);
  ASSERT_NE(mesh.tris[stranger].edge[1], boundary);
  ASSERT_NE(mesh.tris[stranger].edge[2], boundary);
  mesh.edges[boundary].tri[1] = stranger;
  EXPECT_TRUE(reports(mesh, "lists triangle " + std::to_string(stranger) + ", which does not use it"));
}

TEST(MeshCheck, ReportsAnEdgeUsedByThreeTriangles) {
  ClothMesh mesh = smallGrid();
  // A flap hanging off the interior edge shared by triangles 0 and 1 (the first cell's diagonal).
  const int a = mesh.tris[0].v[0];
  const int c = mesh.tris[0].v[2];
  const int flap = mesh.addVertex(Vec3(0.2, 0.2, -0.3));
  Triangle t;
  t.v = {a, c, flap};
  t.rest = {mesh.tris[0].rest[0], mesh.tris[0].rest[2], Vec2(-1, 1)};
  mesh.tris.push_back(t);
  buildEdges(mesh);
  EXPECT_TRUE(reports(mesh, "used by 3 triangles (non-manifold)"));
}

TEST(MeshCheck, ReportsNeighboursWithInconsistentOrientation) {
  // Two triangles on the edge 0-1, both running 0 -> 1. Each is counter-clockwise in its own rest
  // coordinates (the second mirrored), so only the orientation check can object.
  ClothMesh mesh;
  for (int i = 0; i < 4; ++i) mesh.addVertex(Vec3(i, 0, 0));
  Triangle first, second;
  first.v = {0, 1, 2};
  first.rest = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  second.v = {0, 1, 3};
  second.rest = {Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 1)};
  mesh.tris = {first, second};
  buildEdges(mesh);
  const std::vector<std::string> problems = checkMesh(mesh);
  ASSERT_EQ(problems.size(), 1u) << problems.front();
  EXPECT_TRUE(reports(mesh, "inconsistent orientation"));
}

TEST(MeshCheck, ReportsADanglingEdge) {
  ClothMesh mesh = smallGrid();
  Edge loose;
  loose.v = {0, mesh.vertexCount() - 1};
  mesh.edges.push_back(loose);
  EXPECT_TRUE(reports(mesh, "dangling edge"));
}

TEST(MeshCheck, ReportsADuplicatedEdge) {
  ClothMesh mesh = smallGrid();
  mesh.edges.push_back(mesh.edges[0]);
  EXPECT_TRUE(reports(mesh, "duplicated edge"));
}

TEST(MeshCheck, ReportsADanglingVertex) {
  ClothMesh mesh = smallGrid();
  const int loose = mesh.addVertex(Vec3(5, 5, 5));
  EXPECT_TRUE(reports(mesh, "vertex " + std::to_string(loose) + ": dangling vertex"));
}

TEST(MeshCheck, ReportsANonPositiveRestArea) {
  ClothMesh mesh = smallGrid();
  std::swap(mesh.tris[5].rest[1], mesh.tris[5].rest[2]);  // clockwise in material space
  EXPECT_TRUE(reports(mesh, "triangle 5: non-positive rest area"));

  mesh = smallGrid();
  mesh.tris[6].rest[2] = mesh.tris[6].rest[1];  // collapsed
  EXPECT_TRUE(reports(mesh, "triangle 6: non-positive rest area"));

  mesh = smallGrid();
  mesh.tris[7].rest[0].x() = kNan;
  EXPECT_TRUE(reports(mesh, "triangle 7: non-positive rest area"));
}

TEST(MeshCheck, ReportsANonFinitePosition) {
  ClothMesh mesh = smallGrid();
  mesh.x[3].y() = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(reports(mesh, "vertex 3: non-finite position"));
}

TEST(MeshCheck, ReportsANonFiniteVelocity) {
  ClothMesh mesh = smallGrid();
  mesh.v[2].z() = kNan;
  EXPECT_TRUE(reports(mesh, "vertex 2: non-finite velocity"));
}

TEST(MeshCheck, ReportsANonFiniteMass) {
  ClothMesh mesh = smallGrid();
  mesh.mass[4] = kNan;
  EXPECT_TRUE(reports(mesh, "vertex 4: non-finite mass"));
}

TEST(MeshCheck, ReportsANegativeMass) {
  ClothMesh mesh = smallGrid();
  mesh.mass[1] = -0.01;
  EXPECT_TRUE(reports(mesh, "vertex 1: negative mass"));
}

TEST(MeshCheck, ReportsInconsistentArraySizes) {
  ClothMesh mesh = smallGrid();
  mesh.v.pop_back();
  EXPECT_TRUE(reports(mesh, "velocities for 12 positions"));

  mesh = smallGrid();
  mesh.mass.push_back(0.0);
  EXPECT_TRUE(reports(mesh, "masses for 12 positions"));

  mesh = smallGrid();
  mesh.pinned.clear();
  EXPECT_TRUE(reports(mesh, "pinned flags for 12 positions"));
}

TEST(MeshCheck, SurvivesAnEdgeWithEndpointsAndTrianglesOutOfRange) {
  ClothMesh mesh = smallGrid();
  mesh.edges[0].v = {-2, 1000};
  mesh.edges[0].tri = {500, -7};
  EXPECT_TRUE(reports(mesh, "edge 0: vertex index -2-1000 out of range"));
  EXPECT_TRUE(reports(mesh, "edge 0: tri[0] = 500 out of range"));
  EXPECT_TRUE(reports(mesh, "edge 0: tri[1] = -7 out of range"));
}

// Two triangles that share only vertex 0: each edge is fine, but the vertex has two fans.
TEST(MeshCheck, ReportsABowTieVertex) {
  ClothMesh mesh;
  for (int i = 0; i < 5; ++i) mesh.addVertex(Vec3(i, 0, 0));
  Triangle right, left;
  right.v = {0, 1, 2};
  right.rest = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1)};
  left.v = {0, 3, 4};
  left.rest = {Vec2(0, 0), Vec2(-1, 0), Vec2(-1, -1)};
  mesh.tris = {right, left};
  buildEdges(mesh);
  const std::vector<std::string> problems = checkMesh(mesh);
  ASSERT_EQ(problems.size(), 1u) << problems.front();
  EXPECT_TRUE(reports(mesh, "vertex 0: non-manifold vertex (its triangles form 2 fans"));
}

// Half a tear: an edge opened (two border copies) but its vertices not separated. The triangles
// still share the side, so it is the duplicated edge that gives it away.
TEST(MeshCheck, ReportsAnOpenedEdgeWhoseVerticesWereNotSeparated) {
  ClothMesh mesh = smallGrid();
  int opened = kNone;
  for (int e = 0; e < mesh.edgeCount(); ++e) {
    if (mesh.edges[e].v == std::array<int, 2>{1, 5}) opened = e;
  }
  ASSERT_NE(opened, kNone);
  Edge copy = mesh.edges[opened];
  copy.tri = {copy.tri[1], kNone};
  mesh.edges[opened].tri[1] = kNone;
  for (int& e : mesh.tris[copy.tri[0]].edge) {
    if (e == opened) e = mesh.edgeCount();
  }
  mesh.edges.push_back(copy);
  EXPECT_TRUE(reports(mesh, "duplicated edge"));
}

TEST(MeshCheck, ReportsABorderEdgeWithItsTriangleInTheSecondSlot) {
  ClothMesh mesh = smallGrid();
  int boundary = kNone;
  for (int e = 0; e < mesh.edgeCount() && boundary == kNone; ++e) {
    if (mesh.edges[e].isBoundary()) boundary = e;
  }
  ASSERT_NE(boundary, kNone);
  std::swap(mesh.edges[boundary].tri[0], mesh.edges[boundary].tri[1]);
  EXPECT_TRUE(reports(mesh, "edge " + std::to_string(boundary) + ": tri[0] is empty"));
}

TEST(MeshCheck, ReportsTrianglesThatDisagreeOnAnEdgesRestLength) {
  ClothMesh mesh = smallGrid();
  // Triangles 0 and 1 share the first cell's diagonal, corners 0 and 2 of triangle 0 (a-b-c, a-c-d).
  // Moving corner 0 along its other side keeps triangle 0 valid but lengthens the diagonal there.
  mesh.tris[0].rest[0] += 0.1 * (mesh.tris[0].rest[0] - mesh.tris[0].rest[1]);
  EXPECT_TRUE(reports(mesh, "triangles 0 and 1 disagree on the rest length"));
}

}  // namespace
}  // namespace weft
