// findPrimitivePairsTouching (contact_pairs.h), which pass 2's later iterations use, against the
// full search: every pair findPrimitivePairs lists with a flagged vertex must come out, in the same
// order, whichever side of the pair the flag is on, for two bodies and for a cloth against itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>

#include "contact/contact_pairs.h"
#include "support/collision_meshes.h"
#include "support/contact_bodies.h"

namespace weft {
namespace {

struct Scene {
  test::PositionedMesh cloth = test::gridMesh(12, 1.0);
  test::PositionedMesh ball = test::icosphere(2, Vec3(0.3, 0.45, 0.5), 0.3);
  std::vector<Vec3> clothX0, clothX1, ballX0, ballX1;
  std::vector<ContactBody> bodies;
  ContactPairing pairing;

  // A cloth folded over itself (layers 6 mm apart) falling onto a ball that rises into it: both
  // bodies move, so flags on either side of a pair matter.
  explicit Scene(std::mt19937& rng) {
    std::normal_distribution<double> noise(0.0, 0.002);
    for (Vec3& p : cloth.x) {
      const double u = p.x(), w = p.y();
      p = u < 0.5 ? Vec3(u, 0.75, w) : Vec3(1.0 - u, 0.756, w);
    }
    clothX0 = cloth.x;
    clothX1 = cloth.x;
    for (Vec3& p : clothX1) p += Vec3(noise(rng), -0.01 + noise(rng), noise(rng));
    ballX0 = ball.x;
    ballX1 = ball.x;
    for (Vec3& p : ballX1) p += Vec3(0.0, 0.01, 0.0);
    bodies = {test::contactBody(cloth.mesh, clothX0, clothX1), test::contactBody(ball.mesh, ballX0, ballX1)};
    pairing.between.emplace_back(0, 1);
    pairing.self.push_back(0);
  }
};

using PairId = std::tuple<int, int, int, int, int>;

PairId id(const PrimitivePair& p) { return {static_cast<int>(p.kind), p.bodyA, p.featureA, p.bodyB, p.featureB}; }

bool touches(const std::vector<ContactBody>& bodies, const PrimitivePair& p, const VertexFlags& flags) {
  auto flagged = [&](int body, bool isVertex, bool isFace, int feature) {
    const CollisionMesh& mesh = *bodies[body].topology;
    if (isVertex) return flags[body][feature] != 0;
    if (isFace) return std::ranges::any_of(mesh.triangles[feature], [&](int v) { return flags[body][v] != 0; });
    return std::ranges::any_of(mesh.edges[feature], [&](int v) { return flags[body][v] != 0; });
  };
  const bool vertexFace = p.kind == PairKind::VertexFace;
  return flagged(p.bodyA, vertexFace, false, p.featureA) || flagged(p.bodyB, false, vertexFace, p.featureB);
}

TEST(TouchingPairs, ListEveryPairOfTheFullSearchWithAFlaggedVertexInItsOrder) {
  std::mt19937 rng(11);
  for (double margin : {0.0, 0.004}) {
    for (double share : {0.02, 0.2}) {
      Scene scene(rng);
      VertexFlags flags(2);
      std::bernoulli_distribution flip(share);
      for (int b = 0; b < 2; ++b) {
        flags[b].resize(scene.bodies[b].x0->size());
        for (char& f : flags[b]) f = flip(rng) ? 1 : 0;
      }
      std::vector<PrimitivePair> full, touching;
      CandidatePairs scratch;
      findPrimitivePairs(scene.bodies, scene.pairing, margin, scratch, full);
      findPrimitivePairsTouching(scene.bodies, scene.pairing, margin, flags, touching);

      std::vector<PairId> expected, got;
      for (const PrimitivePair& p : full) {
        if (touches(scene.bodies, p, flags)) expected.push_back(id(p));
      }
      for (const PrimitivePair& p : touching) {
        EXPECT_TRUE(touches(scene.bodies, p, flags)) << "a pair without a flagged vertex";
        got.push_back(id(p));
      }
      // Every expected pair, each kind and body pair represented (the scene is built for it).
      ASSERT_GT(expected.size(), 50u) << "margin " << margin << ", share " << share;
      int selfEdgePairs = 0, betweenVertexFace[2] = {0, 0};
      for (const PrimitivePair& p : full) {
        if (!touches(scene.bodies, p, flags)) continue;
        selfEdgePairs += p.kind == PairKind::EdgeEdge && p.bodyA == p.bodyB;
        if (p.kind == PairKind::VertexFace && p.bodyA != p.bodyB) ++betweenVertexFace[p.bodyA];
      }
      EXPECT_GT(selfEdgePairs, 0);
      EXPECT_GT(betweenVertexFace[0], 0);
      EXPECT_GT(betweenVertexFace[1], 0);
      // The expected pairs appear in `got` in the same order (got may hold a few more: it tests
      // boxes only, without the full search's plane culling).
      std::size_t next = 0;
      for (const PairId& pair : got) {
        if (next < expected.size() && pair == expected[next]) ++next;
      }
      EXPECT_EQ(next, expected.size()) << "missing or out of order from pair " << next << " of " << expected.size()
                                       << " (margin " << margin << ", share " << share << ")";
      // No repeats, and in one order: by body pair as listed, then kind group, then features.
      std::vector<PairId> unique = got;
      std::sort(unique.begin(), unique.end());
      EXPECT_EQ(std::unique(unique.begin(), unique.end()), unique.end());
    }
  }
}

}  // namespace
}  // namespace weft
