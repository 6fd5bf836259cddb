#include "collision/candidate_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "collision/ccd.h"
#include "collision/closest_points.h"
#include "support/candidate_pair_reference.h"
#include "support/collision_meshes.h"

namespace weft {
namespace {

using test::bruteForceEdgeEdge;
using test::bruteForceVertexFace;
using test::Motion;
using test::PairList;
using test::sweep;
using test::toList;
using test::isCorner;

// Sorted, strictly: no pair twice.
void expectStrictlyIncreasing(const PairList& pairs) {
  for (size_t k = 1; k < pairs.size(); ++k) ASSERT_LT(pairs[k - 1], pairs[k]) << "at " << k;
}

// A cloth grid with noisy height, crossing a sphere, both moving randomly over the step.
std::pair<Motion, Motion> clothThroughSphere(std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, 0.02);
  const test::PositionedMesh grid = test::gridMesh(7, 1.0);
  const test::PositionedMesh sphere = test::icosphere(1, Vec3(0.5, 0.45, 0.05), 0.3);
  Motion cloth{grid.mesh, grid.x, grid.x};
  Motion obstacle{sphere.mesh, sphere.x, sphere.x};
  for (size_t v = 0; v < cloth.x0.size(); ++v) {
    cloth.x0[v].z() += noise(rng);
    cloth.x1[v] = cloth.x0[v] + Vec3(noise(rng), noise(rng), noise(rng) - 0.05);
  }
  for (size_t v = 0; v < obstacle.x0.size(); ++v) obstacle.x1[v] = obstacle.x0[v] + Vec3(0.01, 0.0, noise(rng));
  return {cloth, obstacle};
}

// A grid folded over itself along x = 0.5 with a small gap between the layers, moving noisily.
Motion foldedCloth(std::mt19937& rng, int n) {
  std::normal_distribution<double> noise(0.0, 0.01);
  const test::PositionedMesh grid = test::gridMesh(n, 1.0);
  Motion cloth{grid.mesh, grid.x, grid.x};
  for (size_t v = 0; v < cloth.x0.size(); ++v) {
    Vec3& p = cloth.x0[v];
    if (p.x() > 0.5) p = Vec3(1.0 - p.x(), p.y(), 0.04 * (p.x() - 0.5) / 0.5);
    p += Vec3(noise(rng), noise(rng), noise(rng));
    cloth.x1[v] = p + Vec3(noise(rng), noise(rng), noise(rng));
  }
  return cloth;
}

TEST(CandidatePairs, MeshAgainstMeshEqualsTheBruteForceEnumeration) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 4; ++trial) {
    const double margin = trial == 0 ? 0.0 : 0.01 * trial;
    const auto [cloth, sphere] = clothThroughSphere(rng);
    const SweptMesh a = sweep(cloth, margin), b = sweep(sphere, margin);
    CandidatePairs pairs;
    findCandidatePairs(a, b, margin, pairs);
    const PairList vfAB = toList(pairs.vfAB), vfBA = toList(pairs.vfBA), ee = toList(pairs.ee);
    expectStrictlyIncreasing(vfAB);
    expectStrictlyIncreasing(vfBA);
    expectStrictlyIncreasing(ee);
    EXPECT_EQ(vfAB, bruteForceVertexFace(cloth, sphere, margin, false)) << "trial " << trial;
    EXPECT_EQ(vfBA, bruteForceVertexFace(sphere, cloth, margin, false)) << "trial " << trial;
    EXPECT_EQ(ee, bruteForceEdgeEdge(cloth, sphere, margin, false)) << "trial " << trial;
    EXPECT_GT(pairs.size(), 50u) << "the meshes should be in contact";
    EXPECT_EQ(pairs.size(), vfAB.size() + vfBA.size() + ee.size());
  }
}

TEST(CandidatePairs, BoxesLetThroughPairsWithinTheMarginAndNotThoseTwiceAsFar) {
  // Two parallel unit triangles `gap` apart along z, both sliding along x over the step (so no
  // fixed plane culls anything): as two meshes, and as two pieces of one mesh (self collision).
  const double margin = 0.004;
  const std::vector<std::array<int, 3>> one{{0, 1, 2}}, two{{0, 1, 2}, {3, 4, 5}};
  auto corners = [](double z) {
    return std::vector<Vec3>{Vec3(0, 0, z), Vec3(1, 0, z), Vec3(0, 1, z)};
  };
  auto slid = [](std::vector<Vec3> x) {
    for (Vec3& p : x) p.x() += 0.01;
    return x;
  };
  for (const double gap : {0.99 * margin, 1.5 * margin}) {
    const bool within = gap < margin;
    const Motion lower{makeCollisionMesh(3, one), corners(0.0), slid(corners(0.0))};
    const Motion upper{makeCollisionMesh(3, one), corners(gap), slid(corners(gap))};
    const SweptMesh a = sweep(lower, margin), b = sweep(upper, margin);
    CandidatePairs pairs;
    findCandidatePairs(a, b, margin, pairs);
    EXPECT_EQ(pairs.vfAB.size(), within ? 3u : 0u) << "gap " << gap;
    EXPECT_EQ(pairs.vfBA.size(), within ? 3u : 0u) << "gap " << gap;
    EXPECT_EQ(pairs.ee.size(), within ? 9u : 0u) << "gap " << gap;

    std::vector<Vec3> both = corners(0.0);
    const std::vector<Vec3> top = corners(gap);
    both.insert(both.end(), top.begin(), top.end());
    const Motion stacked{makeCollisionMesh(6, two), both, slid(both)};
    findSelfCandidatePairs(sweep(stacked, margin), margin, pairs);
    EXPECT_EQ(pairs.vfAB.size(), within ? 6u : 0u) << "gap " << gap;
    EXPECT_EQ(pairs.ee.size(), within ? 9u : 0u) << "gap " << gap;
  }
}

TEST(CandidatePairs, UpdatingAroundMovedVerticesEqualsAFullUpdate) {
  // A folded cloth whose lower half holds still over the step (its triangles have fixed planes).
  // Then a few vertices move, as impulses move them between two iterations of pass 2: refreshing
  // around them must leave every box, plane and pair as a full refresh does.
  std::mt19937 rng(31);
  Motion cloth = foldedCloth(rng, 16);
  for (size_t v = 0; v < cloth.x0.size(); ++v) {
    if (cloth.x0[v].y() < 0.5) cloth.x1[v] = cloth.x0[v];
  }
  const double margin = 0.004;
  SweptMesh around = sweep(cloth, margin);
  ASSERT_TRUE(around.hasFixedPlanes);
  std::vector<char> moved(cloth.x0.size(), 0);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(cloth.x0.size()) - 1);
  std::normal_distribution<double> kick(0.0, 0.01);
  for (int round = 0; round < 3; ++round) {
    std::fill(moved.begin(), moved.end(), char{0});
    for (int k = 0; k < 12; ++k) {
      const int v = pick(rng);
      moved[v] = 1;
      cloth.x1[v] += Vec3(kick(rng), kick(rng), kick(rng));
    }
    updateSweptMeshAround(around, margin, moved);
    const SweptMesh full = sweep(cloth, margin);
    for (size_t t = 0; t < cloth.mesh.triangles.size(); ++t) {
      EXPECT_EQ(around.triangleBoxes[t].lo, full.triangleBoxes[t].lo) << "triangle " << t;
      EXPECT_EQ(around.triangleBoxes[t].hi, full.triangleBoxes[t].hi) << "triangle " << t;
      EXPECT_EQ(around.planes[t].normal, full.planes[t].normal) << "triangle " << t;
    }
    EXPECT_EQ(around.hasFixedPlanes, full.hasFixedPlanes);
    EXPECT_EQ(around.bvh.bounds().lo, full.bvh.bounds().lo);
    EXPECT_EQ(around.bvh.bounds().hi, full.bvh.bounds().hi);
    CandidatePairs fromAround, fromFull;
    findSelfCandidatePairs(around, margin, fromAround);
    findSelfCandidatePairs(full, margin, fromFull);
    EXPECT_EQ(toList(fromAround.vfAB), toList(fromFull.vfAB)) << "round " << round;
    EXPECT_EQ(toList(fromAround.ee), toList(fromFull.ee)) << "round " << round;
    EXPECT_GT(fromFull.size(), 100u) << "the layers should be in contact";
  }
  // Boxes last refreshed for another margin: a full refresh whatever the flags say.
  std::fill(moved.begin(), moved.end(), char{0});
  updateSweptMeshAround(around, 2.0 * margin, moved);
  const SweptMesh wider = sweep(cloth, 2.0 * margin);
  EXPECT_EQ(around.bvh.bounds().lo, wider.bvh.bounds().lo);
  EXPECT_EQ(around.triangleBoxes.front().lo, wider.triangleBoxes.front().lo);
}

TEST(CandidatePairs, SelfPairsEqualTheBruteForceEnumerationWithoutAdjacentFeatures) {
  std::mt19937 rng(22);
  for (int trial = 0; trial < 4; ++trial) {
    const double margin = 0.005 * trial;
    const Motion cloth = foldedCloth(rng, 9);
    const SweptMesh swept = sweep(cloth, margin);
    CandidatePairs pairs;
    findSelfCandidatePairs(swept, margin, pairs);
    EXPECT_TRUE(pairs.vfBA.empty());
    const PairList vf = toList(pairs.vfAB), ee = toList(pairs.ee);
    expectStrictlyIncreasing(vf);
    expectStrictlyIncreasing(ee);
    EXPECT_EQ(vf, bruteForceVertexFace(cloth, cloth, margin, true)) << "trial " << trial;
    EXPECT_EQ(ee, bruteForceEdgeEdge(cloth, cloth, margin, true)) << "trial " << trial;
    EXPECT_GT(vf.size(), 100u) << "the layers should be in contact";
  }
}

TEST(CandidatePairs, SelfPairsOfALargerClothEqualTheBruteForceEnumeration) {
  // 40 x 40 vertices: pair keys need more than 22 bits, so every digit pass of the sort is used.
  std::mt19937 rng(25);
  const Motion cloth = foldedCloth(rng, 40);
  const double margin = 0.004;
  const SweptMesh swept = sweep(cloth, margin);
  CandidatePairs pairs;
  findSelfCandidatePairs(swept, margin, pairs);
  EXPECT_EQ(toList(pairs.vfAB), bruteForceVertexFace(cloth, cloth, margin, true));
  EXPECT_EQ(toList(pairs.ee), bruteForceEdgeEdge(cloth, cloth, margin, true));
}

TEST(CandidatePairs, SelfPairsNeverJoinAFaceToItsCornersOrEdgesThatShareAVertex) {
  // A flat grid with a margin wider than a cell: every neighbour's box overlaps, so only the
  // exclusion keeps adjacent features out.
  const test::PositionedMesh grid = test::gridMesh(6, 1.0);
  const Motion cloth{grid.mesh, grid.x, grid.x};
  const double margin = 0.3;
  const SweptMesh swept = sweep(cloth, margin);
  CandidatePairs pairs;
  findSelfCandidatePairs(swept, margin, pairs);
  for (const VertexFacePair& p : pairs.vfAB) EXPECT_FALSE(isCorner(cloth.mesh.triangles[p.face], p.vertex));
  for (const EdgeEdgePair& p : pairs.ee) {
    const auto& a = cloth.mesh.edges[p.edgeA];
    const auto& b = cloth.mesh.edges[p.edgeB];
    EXPECT_LT(p.edgeA, p.edgeB);
    EXPECT_TRUE(a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1]);
  }
  EXPECT_EQ(toList(pairs.vfAB), bruteForceVertexFace(cloth, cloth, margin, true));
  EXPECT_EQ(toList(pairs.ee), bruteForceEdgeEdge(cloth, cloth, margin, true));
}

TEST(CandidatePairs, UpdateRebuildsOnATopologyChangeThatKeepsTheTriangleCount) {
  std::mt19937 rng(23);
  Motion cloth = foldedCloth(rng, 8);
  const double margin = 0.01;
  SweptMesh swept;
  swept.mesh = &cloth.mesh;
  swept.x0 = &cloth.x0;
  swept.x1 = &cloth.x1;
  updateSweptMesh(swept, margin);
  EXPECT_EQ(swept.features.triangles, cloth.mesh.triangles);

  // Flip the diagonal of every cell (makeGrid stores a cell's two triangles one after the other):
  // same vertices, same triangle count, other triangles.
  std::vector<std::array<int, 3>> flipped;
  for (size_t t = 0; t < cloth.mesh.triangles.size(); t += 2) {
    const auto& first = cloth.mesh.triangles[t];
    const auto& second = cloth.mesh.triangles[t + 1];
    std::vector<int> diagonal;
    int loneFirst = -1, loneSecond = -1;
    for (int v : first) {
      if (isCorner(second, v)) {
        diagonal.push_back(v);
      } else {
        loneFirst = v;
      }
    }
    for (int v : second) {
      if (!isCorner(first, v)) loneSecond = v;
    }
    ASSERT_EQ(diagonal.size(), 2u);
    flipped.push_back({loneFirst, diagonal[0], loneSecond});
    flipped.push_back({loneFirst, loneSecond, diagonal[1]});
  }
  const CollisionMesh before = cloth.mesh;
  cloth.mesh = makeCollisionMesh(before.vertexCount, flipped);
  ASSERT_EQ(cloth.mesh.triangles.size(), before.triangles.size());
  updateSweptMesh(swept, margin);
  EXPECT_EQ(swept.features.triangles, cloth.mesh.triangles);

  CandidatePairs pairs;
  findSelfCandidatePairs(swept, margin, pairs);
  EXPECT_EQ(toList(pairs.vfAB), bruteForceVertexFace(cloth, cloth, margin, true));
  EXPECT_EQ(toList(pairs.ee), bruteForceEdgeEdge(cloth, cloth, margin, true));

  // Moving the vertices without changing the topology refits; the pairs follow the motion.
  for (Vec3& p : cloth.x1) p.z() *= -1.0;
  updateSweptMesh(swept, margin);
  findSelfCandidatePairs(swept, margin, pairs);
  EXPECT_EQ(toList(pairs.vfAB), bruteForceVertexFace(cloth, cloth, margin, true));
  EXPECT_EQ(toList(pairs.ee), bruteForceEdgeEdge(cloth, cloth, margin, true));
}

// A cloth grid draped in a dome over a static sphere, resting about a contact thickness (4 mm)
// above it as in the sheet-on-sphere scene (the held and proximity passes' case), optionally
// moving down into it over the step (pass 2's case): the sphere's triangles do not move, so their
// planes cull.
std::pair<Motion, Motion> clothOverStaticSphere(std::mt19937& rng, double drop) {
  std::normal_distribution<double> noise(0.0, 0.0005);
  const Vec3 centre(0.5, 0.5, -0.2);
  const double radius = 0.25;
  const test::PositionedMesh grid = test::gridMesh(40, 1.0);
  const test::PositionedMesh sphere = test::icosphere(3, centre, radius);
  Motion cloth{grid.mesh, grid.x, grid.x};
  Motion obstacle{sphere.mesh, sphere.x, sphere.x};
  for (size_t v = 0; v < cloth.x0.size(); ++v) {
    Vec3& p = cloth.x0[v];
    const double r2 = (p - centre).head<2>().squaredNorm();
    p.z() = r2 < radius * radius ? centre.z() + std::sqrt(radius * radius - r2) + 0.004 + noise(rng) : 0.0;
    cloth.x1[v] = p + Vec3(noise(rng), noise(rng), -drop + 4.0 * noise(rng));
  }
  if (drop == 0.0) cloth.x1 = cloth.x0;
  return {cloth, obstacle};
}

// The vertex-face and edge-edge pairs of two meshes (vertices of `a` on faces of `b`) whose
// distance at the start is below `reach`, by brute force.
PairList nearVertexFace(const Motion& a, const Motion& b, double reach) {
  PairList pairs;
  for (int v = 0; v < a.mesh.vertexCount; ++v) {
    if (a.mesh.vertexOwner[v] < 0) continue;
    for (int f = 0; f < static_cast<int>(b.mesh.triangles.size()); ++f) {
      const auto& t = b.mesh.triangles[f];
      if (closestPointOnTriangle(a.x0[v], b.x0[t[0]], b.x0[t[1]], b.x0[t[2]]).distance < reach) pairs.emplace_back(v, f);
    }
  }
  return pairs;
}

PairList nearEdgeEdge(const Motion& a, const Motion& b, double reach) {
  PairList pairs;
  for (int ea = 0; ea < static_cast<int>(a.mesh.edges.size()); ++ea) {
    for (int eb = 0; eb < static_cast<int>(b.mesh.edges.size()); ++eb) {
      const auto& p = a.mesh.edges[ea];
      const auto& q = b.mesh.edges[eb];
      if (closestSegmentSegment(a.x0[p[0]], a.x0[p[1]], b.x0[q[0]], b.x0[q[1]]).distance < reach) {
        pairs.emplace_back(ea, eb);
      }
    }
  }
  return pairs;
}

// Every element of `subset` is in `set` (both sorted).
bool includes(const PairList& set, const PairList& subset) {
  return std::includes(set.begin(), set.end(), subset.begin(), subset.end());
}

TEST(CandidatePairs, FixedPlanesCullPairsButKeepEveryPairWithinTheMargin) {
  std::mt19937 rng(26);
  const double margin = 0.005;
  const auto [cloth, sphere] = clothOverStaticSphere(rng, 0.0);
  const SweptMesh a = sweep(cloth, margin), b = sweep(sphere, margin);
  ASSERT_TRUE(a.hasFixedPlanes && b.hasFixedPlanes) << "nothing moves: every triangle has a plane";
  CandidatePairs pairs;
  findCandidatePairs(a, b, margin, pairs);
  const PairList vfAB = toList(pairs.vfAB), vfBA = toList(pairs.vfBA), ee = toList(pairs.ee);
  expectStrictlyIncreasing(vfAB);
  expectStrictlyIncreasing(vfBA);
  expectStrictlyIncreasing(ee);
  // Never more than the boxes allow, never fewer than the pairs really within the margin.
  const PairList boxVfAB = bruteForceVertexFace(cloth, sphere, margin, false);
  const PairList boxEe = bruteForceEdgeEdge(cloth, sphere, margin, false);
  EXPECT_TRUE(includes(boxVfAB, vfAB));
  EXPECT_TRUE(includes(bruteForceVertexFace(sphere, cloth, margin, false), vfBA));
  EXPECT_TRUE(includes(boxEe, ee));
  const PairList nearVf = nearVertexFace(cloth, sphere, margin), nearEe = nearEdgeEdge(cloth, sphere, margin);
  EXPECT_GT(nearVf.size(), 20u) << "the cloth should lie on the sphere";
  EXPECT_GT(nearEe.size(), 20u);
  EXPECT_TRUE(includes(vfAB, nearVf));
  EXPECT_TRUE(includes(vfBA, nearVertexFace(sphere, cloth, margin)));
  EXPECT_TRUE(includes(ee, nearEe));
  // And the planes do cull, though little of what the boxes (grown by half the margin) let
  // through: 4% here (when each box was grown by the whole margin, 10% of more).
  EXPECT_LT(vfAB.size() + ee.size(), (boxVfAB.size() + boxEe.size()) * 39 / 40);
}

TEST(CandidatePairs, AStaticObstaclesPlanesKeepEveryPairThatCollidesOverTheStep) {
  std::mt19937 rng(27);
  const auto [cloth, sphere] = clothOverStaticSphere(rng, 0.02);
  const SweptMesh a = sweep(cloth, 0.0), b = sweep(sphere, 0.0);
  ASSERT_FALSE(a.hasFixedPlanes) << "the cloth moves";
  ASSERT_TRUE(b.hasFixedPlanes) << "the sphere does not";
  CandidatePairs pairs;
  findCandidatePairs(a, b, 0.0, pairs);
  const PairList vfAB = toList(pairs.vfAB), vfBA = toList(pairs.vfBA), ee = toList(pairs.ee);
  EXPECT_TRUE(includes(bruteForceVertexFace(cloth, sphere, 0.0, false), vfAB));
  EXPECT_TRUE(includes(bruteForceEdgeEdge(cloth, sphere, 0.0, false), ee));
  int collisions = 0;
  for (int v = 0; v < cloth.mesh.vertexCount; ++v) {
    for (int f = 0; f < static_cast<int>(sphere.mesh.triangles.size()); ++f) {
      const auto& t = sphere.mesh.triangles[f];
      if (!vertexFaceCcd(cloth.x0[v], sphere.x0[t[0]], sphere.x0[t[1]], sphere.x0[t[2]], cloth.x1[v],
                         sphere.x1[t[0]], sphere.x1[t[1]], sphere.x1[t[2]])) {
        continue;
      }
      ++collisions;
      EXPECT_TRUE(std::binary_search(vfAB.begin(), vfAB.end(), std::pair(v, f))) << "vertex " << v << " face " << f;
    }
  }
  for (int ea = 0; ea < static_cast<int>(cloth.mesh.edges.size()); ++ea) {
    for (int eb = 0; eb < static_cast<int>(sphere.mesh.edges.size()); ++eb) {
      const auto& p = cloth.mesh.edges[ea];
      const auto& q = sphere.mesh.edges[eb];
      if (!edgeEdgeCcd(cloth.x0[p[0]], cloth.x0[p[1]], sphere.x0[q[0]], sphere.x0[q[1]], cloth.x1[p[0]],
                       cloth.x1[p[1]], sphere.x1[q[0]], sphere.x1[q[1]])) {
        continue;
      }
      ++collisions;
      EXPECT_TRUE(std::binary_search(ee.begin(), ee.end(), std::pair(ea, eb))) << "edges " << ea << ", " << eb;
    }
  }
  for (int w = 0; w < sphere.mesh.vertexCount; ++w) {
    for (int f = 0; f < static_cast<int>(cloth.mesh.triangles.size()); ++f) {
      const auto& t = cloth.mesh.triangles[f];
      if (!vertexFaceCcd(sphere.x0[w], cloth.x0[t[0]], cloth.x0[t[1]], cloth.x0[t[2]], sphere.x1[w], cloth.x1[t[0]],
                         cloth.x1[t[1]], cloth.x1[t[2]])) {
        continue;
      }
      ++collisions;
      EXPECT_TRUE(std::binary_search(vfBA.begin(), vfBA.end(), std::pair(w, f))) << "vertex " << w << " face " << f;
    }
  }
  EXPECT_GT(collisions, 20) << "the cloth should drop into the sphere";
  EXPECT_LT(pairs.size(), bruteForceVertexFace(cloth, sphere, 0.0, false).size() +
                              bruteForceVertexFace(sphere, cloth, 0.0, false).size() +
                              bruteForceEdgeEdge(cloth, sphere, 0.0, false).size())
      << "the sphere's planes should cull some box pairs";
}

TEST(CandidatePairs, ResultsDoNotDependOnEarlierCalls) {
  std::mt19937 rng(24);
  const auto [cloth, sphere] = clothThroughSphere(rng);
  const SweptMesh a = sweep(cloth, 0.01), b = sweep(sphere, 0.01);
  CandidatePairs first, reused;
  findCandidatePairs(a, b, 0.01, first);
  findSelfCandidatePairs(a, 0.01, reused);  // leaves other content behind in `reused`
  findCandidatePairs(a, b, 0.01, reused);
  EXPECT_EQ(toList(first.vfAB), toList(reused.vfAB));
  EXPECT_EQ(toList(first.vfBA), toList(reused.vfBA));
  EXPECT_EQ(toList(first.ee), toList(reused.ee));
}

}  // namespace
}  // namespace weft
