// Pass 1 (contact_passes.h) between cloth layers: the repulsion of many overlapping pairs must not
// depend on the order they are listed in (a sequential pass drifted a draped sheet off a ball),
// and must keep the cloth's momentum (each pair pushes both sides equally and oppositely).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "contact/contact_pairs.h"
#include "contact/contact_passes.h"
#include "contact/near_pairs.h"
#include "support/collision_meshes.h"
#include "support/contact_bodies.h"

namespace weft {
namespace {

// Two 12 x 12 layers of one cloth, 1.5 mm apart (the thickness is 4 mm), the upper one falling
// onto the lower one and both sliding a little, with uneven vertex masses.
struct TwoLayers {
  CollisionMesh mesh;
  std::vector<Vec3> x0, x1, v;
  std::vector<double> inverseMass;
  std::vector<ContactBody> bodies;
  static constexpr double kThickness = 0.004, kStep = 1.0 / 60.0;

  explicit TwoLayers(std::mt19937& rng) {
    const test::PositionedMesh layer = test::gridMesh(12, 0.2);
    std::vector<std::array<int, 3>> triangles = layer.mesh.triangles;
    const int n = layer.mesh.vertexCount;
    for (const auto& t : layer.mesh.triangles) triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
    mesh = makeCollisionMesh(2 * n, triangles);
    std::uniform_real_distribution<double> jitter(-0.0003, 0.0003), mass(0.5e-3, 1.5e-3), slide(-0.02, 0.02);
    for (int copy = 0; copy < 2; ++copy) {
      for (const Vec3& p : layer.x) {
        x0.push_back(Vec3(p.x(), p.y(), 0.0015 * copy) + Vec3(jitter(rng), jitter(rng), jitter(rng)));
        v.push_back(Vec3(slide(rng), slide(rng), copy == 1 ? -0.1 : 0.0));
        inverseMass.push_back(1.0 / mass(rng));
      }
    }
    x1 = x0;
    for (std::size_t i = 0; i < x0.size(); ++i) x1[i] = x0[i] + kStep * v[i];
    ContactBody body = test::contactBody(mesh, x0, x1, &v);
    body.inverseMass = &inverseMass;
    body.friction = 0.3;
    bodies.push_back(body);
  }

  std::vector<NearPair> nearPairs() {
    ContactPairing pairing;
    pairing.self.push_back(0);
    CandidatePairs scratch;
    std::vector<PrimitivePair> pairs;
    findPrimitivePairs(bodies, pairing, kThickness, scratch, pairs);
    std::vector<Vec3> end = x1;
    x1 = x0;  // the pairs are measured at the start, as the contact stage does
    std::vector<NearPair> near;
    measureNearPairs(bodies, pairs, kThickness, near);
    x1 = end;
    return near;
  }

  PassCounts repel(const std::vector<NearPair>& near) {
    ContactStepSettings settings;
    settings.h = kStep;
    settings.thickness = kThickness;
    PassCounts counts;
    runProximityPass(bodies, near, settings, counts);
    return counts;
  }

  Vec3 momentum() const {
    Vec3 sum = Vec3::Zero();
    for (std::size_t i = 0; i < v.size(); ++i) sum += v[i] / inverseMass[i];
    return sum;
  }
};

TEST(ProximityPass, ClothLayersAreRepelledAlikeWhateverTheOrderOfTheirPairsAndKeepTheirMomentum) {
  std::mt19937 rng(5);
  TwoLayers forward(rng);
  TwoLayers backward = forward;
  backward.bodies[0] = test::contactBody(backward.mesh, backward.x0, backward.x1, &backward.v);
  backward.bodies[0].inverseMass = &backward.inverseMass;
  backward.bodies[0].friction = forward.bodies[0].friction;

  const std::vector<NearPair> near = forward.nearPairs();
  ASSERT_GT(near.size(), 500u) << "the layers should overlap within the thickness";
  std::vector<NearPair> reversed = backward.nearPairs();
  std::reverse(reversed.begin(), reversed.end());

  const Vec3 before = forward.momentum();
  double upperBefore = 0.0, upperAfter = 0.0;
  const std::size_t half = forward.v.size() / 2;
  for (std::size_t i = half; i < forward.v.size(); ++i) upperBefore += forward.v[i].z();
  const PassCounts counts = forward.repel(near);
  backward.repel(reversed);
  EXPECT_GT(counts.proximityImpulses, 500);

  // Momentum: every pair's impulses are equal and opposite.
  EXPECT_LT((forward.momentum() - before).norm(), 1e-12 * (1.0 + before.norm()));
  // Order: the same velocities up to rounding (a pass applying each pair's impulse on what the
  // earlier ones left differs by a good fraction of the velocities here).
  double largest = 0.0;
  for (std::size_t i = 0; i < forward.v.size(); ++i) {
    largest = std::max(largest, (forward.v[i] - backward.v[i]).norm());
    EXPECT_EQ(forward.x1[i], forward.x0[i] + TwoLayers::kStep * forward.v[i]) << "x1 follows v";
  }
  EXPECT_LT(largest, 1e-12);
  // And the upper layer's fall is mostly stopped (a tenth of the overlap a step is restored; the
  // sweeps bring it from -0.1 to -0.045 m/s here, one sweep alone to -0.075).
  for (std::size_t i = half; i < forward.v.size(); ++i) upperAfter += forward.v[i].z();
  EXPECT_LT(upperBefore / half, -0.09);
  EXPECT_GT(upperAfter / half, -0.06);
}

}  // namespace
}  // namespace weft
