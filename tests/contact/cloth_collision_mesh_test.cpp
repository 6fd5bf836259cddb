// A torn cloth's collision topology and broad phase, patched tear by tear, against the same
// structures built from scratch and against the brute-force enumeration of candidate pairs.
#include "contact/cloth_collision_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "collision/candidate_pairs.h"
#include "mesh/grid.h"
#include "support/candidate_pair_reference.h"
#include "support/collision_meshes.h"
#include "tearing/tear_mesh.h"

namespace weft {
namespace {

using test::Motion;
using test::PairList;
using test::toList;

constexpr double kAreaDensity = 0.2;

// Every vertex and edge in a triangle has exactly one owner, the lowest triangle using it.
void expectLowestOwners(const CollisionMesh& mesh) {
  std::vector<int> lowestOfVertex(mesh.vertexCount, -1), lowestOfEdge(mesh.edges.size(), -1);
  for (int t = static_cast<int>(mesh.triangles.size()) - 1; t >= 0; --t) {
    for (int v : mesh.triangles[t]) lowestOfVertex[v] = t;
    for (int e : mesh.triangleEdges[t]) lowestOfEdge[e] = t;
  }
  EXPECT_EQ(mesh.vertexOwner, lowestOfVertex);
  EXPECT_EQ(mesh.edgeOwner, lowestOfEdge);
  for (int e : lowestOfEdge) EXPECT_GE(e, 0) << "an edge in no triangle";
}

void expectSameCollisionMesh(const CollisionMesh& a, const CollisionMesh& b) {
  EXPECT_EQ(a.vertexCount, b.vertexCount);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.triangleEdges, b.triangleEdges);
  EXPECT_EQ(a.vertexOwner, b.vertexOwner);
  EXPECT_EQ(a.edgeOwner, b.edgeOwner);
  EXPECT_EQ(a.trianglesAround, b.trianglesAround);
}

void expectSamePairs(const CandidatePairs& a, const CandidatePairs& b, const char* what) {
  EXPECT_EQ(toList(a.vfAB), toList(b.vfAB)) << what;
  EXPECT_EQ(toList(a.vfBA), toList(b.vfBA)) << what;
  EXPECT_EQ(toList(a.ee), toList(b.ee)) << what;
}

// The cloth crumpled (folded over itself along x = 0.5 with a small gap, plus noise) and moving
// over the step: a copy made by a tear moves with its original, as vertex ids are the noise seed
// of neither, so pairs across the tear come and go as the test runs.
void placeCloth(const ClothMesh& mesh, std::mt19937& rng, std::vector<Vec3>& x0, std::vector<Vec3>& x1) {
  std::normal_distribution<double> noise(0.0, 0.01);
  x0.resize(mesh.vertexCount());
  x1.resize(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    Vec3 p = mesh.x[v];
    if (p.x() > 0.5) p = Vec3(1.0 - p.x(), p.y(), 0.04 * (p.x() - 0.5) / 0.5);
    x0[v] = p + Vec3(noise(rng), noise(rng), noise(rng));
    x1[v] = x0[v] + Vec3(noise(rng), noise(rng), noise(rng));
  }
}

TEST(ClothCollisionMesh, FromScratchMirrorsTheClothIdsWithLowestTriangleOwners) {
  const ClothMesh cloth = makeGrid(GridSpec{1.0, 1.0, 5, 4});
  const CollisionMesh mesh = makeClothCollisionMesh(cloth);
  ASSERT_EQ(mesh.edges.size(), cloth.edges.size());
  for (int e = 0; e < cloth.edgeCount(); ++e) {
    EXPECT_EQ(mesh.edges[e][0], std::min(cloth.edges[e].v[0], cloth.edges[e].v[1]));
    EXPECT_EQ(mesh.edges[e][1], std::max(cloth.edges[e].v[0], cloth.edges[e].v[1]));
  }
  for (int t = 0; t < cloth.triangleCount(); ++t) {
    EXPECT_EQ(mesh.triangles[t], cloth.tris[t].v);
    EXPECT_EQ(mesh.triangleEdges[t], cloth.tris[t].edge);
  }
  expectLowestOwners(mesh);
}

// Tears a grid many times at random. After each tear, the patched collision mesh equals a fresh
// one, and the patched broad phase (BVH grown by insertion, feature runs and neighbour lists
// patched) finds exactly the candidates of a fresh one and of the brute-force enumeration, within
// the cloth and against a sphere.
TEST(ClothCollisionMesh, PatchedAfterEveryTearEqualsAFreshBuildAndTheBruteForcePairs) {
  std::mt19937 rng(41);
  ClothMesh cloth = makeGrid(GridSpec{1.0, 1.0, 13, 13});
  for (int v = 0; v < cloth.vertexCount(); ++v) cloth.mass[v] = 1.0;
  const test::PositionedMesh sphere = test::icosphere(1, Vec3(0.3, 0.5, 0.02), 0.15);
  Motion obstacle{sphere.mesh, sphere.x, sphere.x};
  for (Vec3& p : obstacle.x1) p += Vec3(0.01, 0.0, -0.01);
  const double margin = 0.01;

  Motion patched{makeClothCollisionMesh(cloth), {}, {}};
  placeCloth(cloth, rng, patched.x0, patched.x1);
  SweptMesh swept = test::sweep(patched, margin);
  const SweptMesh obstacleSwept = test::sweep(obstacle, margin);

  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  TearGuards guards;
  int tears = 0, rebuilds = 0;
  for (int attempt = 0; attempt < 400 && tears < 120; ++attempt) {
    const int vertex = std::uniform_int_distribution<int>(0, cloth.vertexCount() - 1)(rng);
    const double a = angle(rng);
    TopologyChange change;
    if (!tearThroughVertex(cloth, vertex, Vec2(std::cos(a), std::sin(a)), guards, kAreaDensity, change)) continue;
    ++tears;
    const CollisionMeshChange edit = updateClothCollisionMesh(patched.mesh, cloth, change);
    patchSweptMesh(swept, edit);
    if (swept.features.triangles.empty()) ++rebuilds;  // the policy chose a fresh build

    const Motion fresh{makeClothCollisionMesh(cloth), {}, {}};
    expectSameCollisionMesh(patched.mesh, fresh.mesh);
    expectLowestOwners(patched.mesh);

    placeCloth(cloth, rng, patched.x0, patched.x1);
    updateSweptMesh(swept, margin);
    Motion freshMotion = fresh;
    freshMotion.x0 = patched.x0;
    freshMotion.x1 = patched.x1;
    const SweptMesh freshSwept = test::sweep(freshMotion, margin);

    CandidatePairs self, freshSelf, between, freshBetween;
    findSelfCandidatePairs(swept, margin, self);
    findSelfCandidatePairs(freshSwept, margin, freshSelf);
    expectSamePairs(self, freshSelf, "self, patched vs fresh");
    EXPECT_EQ(toList(self.vfAB), test::bruteForceVertexFace(patched, patched, margin, true)) << "tear " << tears;
    EXPECT_EQ(toList(self.ee), test::bruteForceEdgeEdge(patched, patched, margin, true)) << "tear " << tears;

    findCandidatePairs(swept, obstacleSwept, margin, between);
    findCandidatePairs(freshSwept, obstacleSwept, margin, freshBetween);
    expectSamePairs(between, freshBetween, "cloth-sphere, patched vs fresh");
    EXPECT_EQ(toList(between.vfAB), test::bruteForceVertexFace(patched, obstacle, margin, false));
    EXPECT_EQ(toList(between.vfBA), test::bruteForceVertexFace(obstacle, patched, margin, false));
    EXPECT_EQ(toList(between.ee), test::bruteForceEdgeEdge(patched, obstacle, margin, false));
    if (HasFailure()) FAIL() << "after tear " << tears;
  }
  EXPECT_GE(tears, 100) << "too few tears went through";
  EXPECT_GE(rebuilds, 1) << "the rebuild policy was never exercised";
  EXPECT_GT(cloth.triangleCount(), 2 * 12 * 12 + 100) << "the tears should have split triangles";
}

}  // namespace
}  // namespace weft
