// The closed-surface check: each kind of defect is found and named.
#include "rigid/closed_surface_check.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "rigid/mass_properties.h"
#include "rigid/shape_meshes.h"
#include "rigid_test_support.h"

namespace weft {
namespace {

// The check finds exactly one problem, and its text contains `phrase`.
void expectOneProblem(const TriangleMesh& mesh, const std::string& phrase) {
  const std::vector<std::string> problems = closedSurfaceProblems(mesh);
  ASSERT_FALSE(problems.empty()) << "expected: " << phrase;
  EXPECT_NE(problems.front().find(phrase), std::string::npos) << problems.front();
}

TriangleMesh tetrahedron(const Vec3& offset = Vec3::Zero()) {
  TriangleMesh mesh;
  mesh.vertices = {offset, offset + Vec3(1, 0, 0), offset + Vec3(0, 1, 0), offset + Vec3(0, 0, 1)};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

TEST(RigidClosedSurface, ValidMeshesPass) {
  EXPECT_TRUE(closedSurfaceProblems(tetrahedron()).empty());
  EXPECT_NEAR(signedVolume(tetrahedron()), 1.0 / 6.0, 1e-15);
  EXPECT_TRUE(closedSurfaceProblems(makeBoxMesh({Vec3(1, 2, 3), 0.5})).empty());
}

TEST(RigidClosedSurface, InsideOutIsClosedButHasNegativeVolume) {
  const TriangleMesh inward = test::reversed(tetrahedron());
  EXPECT_TRUE(closedSurfaceProblems(inward).empty());
  EXPECT_NEAR(signedVolume(inward), -1.0 / 6.0, 1e-15);
}

TEST(RigidClosedSurface, EachDefectIsNamed) {
  TriangleMesh mesh = tetrahedron();
  mesh.triangles.pop_back();
  expectOneProblem(mesh, "has a hole");

  mesh = tetrahedron();
  std::swap(mesh.triangles[3][1], mesh.triangles[3][2]);
  expectOneProblem(mesh, "inconsistent orientation");

  mesh = tetrahedron();
  mesh.triangles.push_back({1, 2, 3});
  expectOneProblem(mesh, "not a 2-manifold");

  mesh = tetrahedron();
  mesh.vertices.push_back(Vec3(5, 5, 5));
  expectOneProblem(mesh, "vertex 4 is in no triangle");

  mesh = tetrahedron();
  mesh.triangles[0][1] = 7;
  expectOneProblem(mesh, "out of range");

  mesh = tetrahedron();
  mesh.triangles[0] = {0, 0, 1};
  expectOneProblem(mesh, "repeats a vertex");

  mesh = tetrahedron();
  mesh.vertices[3] = Vec3(0.5, 0.0, 0.0);  // on the edge 0-1: triangle (0, 1, 3) collapses to a segment
  expectOneProblem(mesh, "triangle 1 has zero area");

  mesh = tetrahedron();
  mesh.vertices[1].x() = NAN;
  expectOneProblem(mesh, "non-finite");

  expectOneProblem(TriangleMesh{}, "no triangles");
}

// Two tetrahedra sharing only a corner: every edge is fine, but the corner joins two separate fans.
TEST(RigidClosedSurface, SurfacesTouchingAtAVertexAreRejected) {
  TriangleMesh mesh = tetrahedron();
  const TriangleMesh other = tetrahedron(Vec3(1, 0, 0));                   // its vertex 0 is our vertex 1
  for (int v = 1; v < 4; ++v) mesh.vertices.push_back(other.vertices[v]);  // ids 4, 5, 6
  auto id = [](int v) { return v == 0 ? 1 : v + 3; };
  for (const auto& t : other.triangles) mesh.triangles.push_back({id(t[0]), id(t[1]), id(t[2])});
  expectOneProblem(mesh, "vertex 1 joins separate fans");
  EXPECT_EQ(closedSurfaceProblems(mesh).size(), 1u);
}

}  // namespace
}  // namespace weft
