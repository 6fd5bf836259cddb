#include "collision/material_patches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "collision/candidate_pairs.h"
#include "collision/ccd.h"
#include "collision/closest_points.h"
#include "contact/cloth_collision_mesh.h"
#include "tearing/tear_mesh.h"
#include "support/candidate_pair_reference.h"
#include "support/collision_meshes.h"

#include <Eigen/SVD>

namespace weft {
namespace {

// A grid cloth as the contact stage sees it: collision topology, rest corners, positions.
struct ClothGrid {
  CollisionMesh mesh;
  RestCorners rest;
  std::vector<Vec3> x;
};

ClothGrid clothGrid(int n) {
  const ClothMesh cloth = test::gridCloth(n, 1.0);
  ClothGrid grid;
  std::vector<std::array<int, 3>> triangles;
  for (const Triangle& t : cloth.tris) {
    triangles.push_back(t.v);
    grid.rest.push_back(t.rest);
  }
  grid.mesh = makeCollisionMesh(cloth.vertexCount(), triangles);
  grid.x = cloth.x;
  return grid;
}

SweptMesh sweptCloth(const CollisionMesh& mesh, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                     const RestCorners* rest, double margin) {
  SweptMesh swept;
  swept.mesh = &mesh;
  swept.x0 = &x0;
  swept.x1 = &x1;
  swept.rest = rest;
  updateSweptMesh(swept, margin);
  return swept;
}

TEST(MaterialPatches, AGridTreeSplitsAlongGridLinesSoEveryNodeTilesARectangle) {
  for (int n : {9, 10, 33}) {  // even and odd cell counts
    const ClothGrid grid = clothGrid(n);
    const SweptMesh swept = sweptCloth(grid.mesh, grid.x, grid.x, &grid.rest, 0.0);
    const MaterialPatches& patches = swept.features.patches;
    ASSERT_EQ(static_cast<int>(patches.tilesConvexRegion.size()), swept.bvh.nodeCount());
    for (int node = 0; node < swept.bvh.nodeCount(); ++node) {
      EXPECT_TRUE(patches.tilesConvexRegion[node]) << "grid " << n << ", node " << node;
      EXPECT_NEAR(patches.smallestAltitude[node], (1.0 / (n - 1)) / std::sqrt(2.0), 1e-12);
    }
  }
  // An obstacle (no rest corners) has no patches.
  const ClothGrid grid = clothGrid(9);
  EXPECT_TRUE(sweptCloth(grid.mesh, grid.x, grid.x, nullptr, 0.0).features.patches.empty());
}

TEST(MaterialPatches, ASlitInsideANodeBreaksItsTilingButNotTheNodesAwayFromIt) {
  // A 9 x 9 grid (8 x 8 cells) cut along the middle row between columns 2 and 6: the triangles
  // above the cut take copies of its inner vertices, at the same material positions.
  ClothGrid grid = clothGrid(9);
  const int n = 9, row = 4;
  std::vector<int> copyOf(static_cast<std::size_t>(n * n), -1);
  int vertexCount = grid.mesh.vertexCount;
  std::vector<std::array<int, 3>> triangles = grid.mesh.triangles;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    double centreY = 0.0;
    for (const Vec2& r : grid.rest[t]) centreY += r.y() / 3.0;
    if (centreY < row / double(n - 1)) continue;
    for (int& v : triangles[t]) {
      const int i = v % n, j = v / n;
      if (j != row || i < 3 || i > 5) continue;  // the slit's inner vertices (its ends stay joined)
      if (copyOf[v] < 0) {
        copyOf[v] = vertexCount++;
        grid.x.push_back(grid.x[v]);
      }
      v = copyOf[v];
    }
  }
  ASSERT_EQ(vertexCount, n * n + 3);
  grid.mesh = makeCollisionMesh(vertexCount, triangles);
  const SweptMesh swept = sweptCloth(grid.mesh, grid.x, grid.x, &grid.rest, 0.0);
  const MaterialPatches& patches = swept.features.patches;
  EXPECT_FALSE(patches.tilesConvexRegion[0]) << "the whole cloth holds the slit";
  int tiling = 0;
  for (char tiles : patches.tilesConvexRegion) tiling += tiles;
  EXPECT_GT(tiling, swept.bvh.nodeCount() / 2) << "nodes away from the slit still tile";

  // Folded shut over the slit (the two lips pressed within a millimetre of each other), no node
  // may be certified that holds both lips: the lips' pairs stay in the search.
  std::vector<Vec3> x = grid.x;
  for (std::size_t v = static_cast<std::size_t>(n * n); v < x.size(); ++v) x[v].z() += 0.0005;
  std::vector<char> certified;
  certifyPatches(patches, swept.bvh, grid.mesh, x, x, 0.001, certified);
  EXPECT_FALSE(certified[0]);
}

// A sheet creased along x = 0.5, its left half turned up by 60 degrees and stretched by 0.9
// across the crease: two deformation gradients, F on the left and the identity on the right.
// The ball around them is too wide to certify the whole sheet, the bound in C's column space
// (C their mean) is not: the sheet is certified just below that bound and not just above it, and
// the bound holds for sampled material point pairs.
TEST(MaterialPatches, ACreasedSheetIsCertifiedUpToTheBoundInItsMeanGradientsPlane) {
  const ClothGrid grid = clothGrid(9);
  const double angle = kPi / 3.0, stretch = 0.9;
  const Vec3 turned(std::cos(angle), 0.0, std::sin(angle));
  auto place = [&](const Vec2& m) {
    return m.x() >= 0.5 ? Vec3(m.x(), m.y(), 0.0) : Vec3(0.5, m.y(), 0.0) + stretch * (0.5 - m.x()) * -turned;
  };
  std::vector<Vec3> x(grid.x.size());
  for (std::size_t v = 0; v < x.size(); ++v) x[v] = place(Vec2(grid.x[v].x(), grid.x[v].y()));
  // The expected bound, from the two gradients (Jacobi SVD for sigma_min).
  Eigen::Matrix<double, 3, 2> left, right, mean;
  left << stretch * turned, Vec3::UnitY();
  right << Vec3::UnitX(), Vec3::UnitY();
  mean = 0.5 * (left + right);
  Eigen::Matrix<double, 3, 2> basis;
  basis.col(0) = mean.col(0).normalized();
  basis.col(1) = (mean.col(1) - basis.col(0).dot(mean.col(1)) * basis.col(0)).normalized();
  const double deviation =
      std::max((basis.transpose() * (left - mean)).norm(), (basis.transpose() * (right - mean)).norm());
  const double sigma = Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>>(mean).singularValues()(1);
  const double bound = sigma - deviation;
  ASSERT_GT(bound, 0.5);
  ASSERT_LT(sigma - 0.5 * (left - right).norm(), 0.5 * bound) << "the ball alone would certify it";

  const SweptMesh swept = sweptCloth(grid.mesh, x, x, &grid.rest, 0.0);
  const double altitude = swept.features.patches.smallestAltitude[0];
  std::vector<char> certified;
  certifyPatches(swept.features.patches, swept.bvh, grid.mesh, x, x, 0.98 * bound * altitude, certified);
  EXPECT_TRUE(certified[0]);
  certifyPatches(swept.features.patches, swept.bvh, grid.mesh, x, x, 1.02 * bound * altitude, certified);
  EXPECT_FALSE(certified[0]);
  EXPECT_TRUE(certified[1] && certified[swept.bvh.rightChild(0)]) << "each flat half on its own";

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const Vec2 p(unit(rng), unit(rng)), q(unit(rng), unit(rng));
    EXPECT_GE((place(p) - place(q)).norm(), bound * (p - q).norm() - 1e-12);
  }
}

using Pair = std::pair<int, int>;
std::set<Pair> asSet(const test::PairList& list) { return {list.begin(), list.end()}; }

RestCorners restOf(const ClothMesh& cloth) {
  RestCorners rest;
  for (const Triangle& t : cloth.tris) rest.push_back(t.rest);
  return rest;
}

// A flat sheet torn again and again, its broad phase patched after each tear as the contact stage
// does it: the two lips of every tear lie on each other, so a node holding a tear must never be
// certified again (until a fresh build finds it no longer tiles). Every pair within the margin
// stays in the search; the rest of the sheet is still certified.
TEST(MaterialPatches, NodesHoldingATearAreNeverCertifiedAfterThePatch) {
  std::mt19937 rng(11);
  ClothMesh cloth = test::gridCloth(13, 1.0);
  for (int v = 0; v < cloth.vertexCount(); ++v) cloth.mass[v] = 1.0;
  CollisionMesh mesh = makeClothCollisionMesh(cloth);
  RestCorners rest = restOf(cloth);
  std::vector<Vec3> x = cloth.x;
  const double margin = 0.004;
  SweptMesh swept = sweptCloth(mesh, x, x, &rest, margin);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  std::normal_distribution<double> noise(0.0, 0.0001);
  int tears = 0;
  for (int attempt = 0; attempt < 200 && tears < 40; ++attempt) {
    const int vertex = std::uniform_int_distribution<int>(0, cloth.vertexCount() - 1)(rng);
    const double a = angle(rng);
    TopologyChange change;
    if (!tearThroughVertex(cloth, vertex, Vec2(std::cos(a), std::sin(a)), TearGuards{}, 0.2, change)) continue;
    ++tears;
    patchSweptMesh(swept, updateClothCollisionMesh(mesh, cloth, change));
    rest = restOf(cloth);
    x = cloth.x;
    for (Vec3& p : x) p.z() += noise(rng);
    updateSweptMesh(swept, margin);
    CandidatePairs kept;
    findSelfCandidatePairs(swept, margin, kept);
    const std::set<Pair> keptVf = asSet(test::toList(kept.vfAB)), keptEe = asSet(test::toList(kept.ee));
    const test::Motion motion{mesh, x, x};
    int near = 0;
    for (const auto& [v, f] : test::bruteForceVertexFace(motion, motion, margin, true)) {
      const auto& c = mesh.triangles[f];
      if (!(closestPointOnTriangle(x[v], x[c[0]], x[c[1]], x[c[2]]).distance < margin)) continue;
      ++near;
      EXPECT_TRUE(keptVf.count({v, f})) << "tear " << tears << ": vertex " << v << ", face " << f;
    }
    for (const auto& [e, g] : test::bruteForceEdgeEdge(motion, motion, margin, true)) {
      const auto& p = mesh.edges[e];
      const auto& q = mesh.edges[g];
      if (!(closestSegmentSegment(x[p[0]], x[p[1]], x[q[0]], x[q[1]]).distance < margin)) continue;
      ++near;
      EXPECT_TRUE(keptEe.count({e, g})) << "tear " << tears << ": edges " << e << ", " << g;
    }
    EXPECT_GT(near, 0) << "the lips of the tears touch";
    if (HasFailure()) FAIL() << "after tear " << tears;
  }
  EXPECT_GE(tears, 30);
  std::vector<char> certified;
  certifyPatches(swept.features.patches, swept.bvh, mesh, x, x, margin, certified);
  int certifiedNodes = 0;
  for (char c : certified) certifiedNodes += c;
  EXPECT_GT(certifiedNodes, 0) << "the sheet away from the tears is still certified";
}

// A 33 x 33 grid bent into part of a cylinder of radius 0.3 m (a gentle curve), folded over
// itself along x = 0.5 with the layers 3 mm apart, or squashed to an eighth of its width (its
// features a few millimetres apart, about the margin), with noise, moving over the step.
enum class Shape { Bent, Folded, Squashed };
test::Motion deformedGrid(const ClothGrid& grid, Shape shape, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, shape == Shape::Squashed ? 0.0001 : 0.001);
  test::Motion motion{grid.mesh, grid.x, grid.x};
  for (std::size_t v = 0; v < grid.x.size(); ++v) {
    const double u = grid.x[v].x(), w = grid.x[v].y();
    Vec3 p;
    if (shape == Shape::Folded) {
      p = u <= 0.5 ? Vec3(u, w, 0.0) : Vec3(1.0 - u, w, 0.003);
    } else if (shape == Shape::Squashed) {
      p = Vec3(u / 8.0, w, 0.0);
    } else {
      const double r = 0.3;
      p = Vec3(r * std::sin(u / r), w, r * (1.0 - std::cos(u / r)));
    }
    motion.x0[v] = p + Vec3(noise(rng), noise(rng), noise(rng));
    motion.x1[v] = motion.x0[v] + Vec3(0.004, 0.0, -0.002) + Vec3(noise(rng), noise(rng), noise(rng));
  }
  return motion;
}

// Every pair the full search lists and the certified search leaves out never comes within the
// margin: at the start (x1 = x0) by its closest points, over a step by exact CCD.
TEST(MaterialPatches, TheCertifiedSearchLeavesOutOnlyPairsThatNeverComeWithinTheMargin) {
  std::mt19937 rng(5);
  const ClothGrid grid = clothGrid(33);
  for (Shape shape : {Shape::Bent, Shape::Folded, Shape::Squashed}) {
    const test::Motion motion = deformedGrid(grid, shape, rng);
    for (bool wholeStep : {false, true}) {
      const double margin = wholeStep ? 0.0 : 0.004;
      const std::vector<Vec3>& x1 = wholeStep ? motion.x1 : motion.x0;
      const SweptMesh full = sweptCloth(grid.mesh, motion.x0, x1, nullptr, margin);
      const SweptMesh culled = sweptCloth(grid.mesh, motion.x0, x1, &grid.rest, margin);
      CandidatePairs all, kept;
      findSelfCandidatePairs(full, margin, all);
      findSelfCandidatePairs(culled, margin, kept);
      const std::set<Pair> allVf = asSet(test::toList(all.vfAB)), keptVf = asSet(test::toList(kept.vfAB));
      const std::set<Pair> allEe = asSet(test::toList(all.ee)), keptEe = asSet(test::toList(kept.ee));
      const char* names[] = {"bent", "folded", "squashed"};
      const std::string where = std::string(names[static_cast<int>(shape)]) + (wholeStep ? ", step" : ", start");
      EXPECT_TRUE(std::includes(allVf.begin(), allVf.end(), keptVf.begin(), keptVf.end())) << where;
      EXPECT_TRUE(std::includes(allEe.begin(), allEe.end(), keptEe.begin(), keptEe.end())) << where;
      const std::vector<Vec3>& x0 = motion.x0;
      int nearOrCrossing = 0;
      for (const auto& [v, f] : allVf) {
        const auto& c = grid.mesh.triangles[f];
        const bool near = wholeStep ? vertexFaceCcd(x0[v], x0[c[0]], x0[c[1]], x0[c[2]], x1[v], x1[c[0]], x1[c[1]],
                                                    x1[c[2]])
                                          .has_value()
                                    : closestPointOnTriangle(x0[v], x0[c[0]], x0[c[1]], x0[c[2]]).distance < margin;
        nearOrCrossing += near;
        if (near) EXPECT_TRUE(keptVf.count({v, f})) << where << ": vertex " << v << ", face " << f;
      }
      for (const auto& [e, g] : allEe) {
        const auto& a = grid.mesh.edges[e];
        const auto& b = grid.mesh.edges[g];
        const bool near = wholeStep ? edgeEdgeCcd(x0[a[0]], x0[a[1]], x0[b[0]], x0[b[1]], x1[a[0]], x1[a[1]], x1[b[0]],
                                                  x1[b[1]])
                                          .has_value()
                                    : closestSegmentSegment(x0[a[0]], x0[a[1]], x0[b[0]], x0[b[1]]).distance < margin;
        nearOrCrossing += near;
        if (near) EXPECT_TRUE(keptEe.count({e, g})) << where << ": edges " << e << ", " << g;
      }
      // Most of the gentle curve is certified; the fold keeps its layers' pairs, and the squashed
      // sheet its near neighbours (nodes whose bound falls short of the margin stay searched).
      if (shape == Shape::Bent) EXPECT_LT(3 * (keptVf.size() + keptEe.size()), allVf.size() + allEe.size()) << where;
      if (shape != Shape::Bent && !wholeStep) EXPECT_GT(nearOrCrossing, 200) << where;
    }
  }
}

}  // namespace
}  // namespace weft
