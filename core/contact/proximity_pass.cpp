// Pass 1 of Bridson, Fedkiw & Anderson 2002 (§7.1): repulsion between pairs that start the step
// closer than the cloth thickness.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "contact/contact_impulse.h"
#include "contact/contact_passes.h"

namespace weft {
namespace {

// Bridson 2002 restores a tenth of the overlap per step: enough to keep resting contact at the
// thickness, gentle enough not to make stacked layers jitter.
constexpr double kRepulsionFraction = 0.1;

// A touching pair's stand-in normal, turned against the relative velocity so the impulse
// separates them.
Vec3 orientAgainstApproach(Vec3 normal, const Vec3& relativeVelocity) {
  if (normal.dot(relativeVelocity) > 0.0) normal = -normal;
  return normal;
}

// Cloth vertices against the ground plane y = height.
void groundProximity(std::vector<ContactBody>& bodies, const ContactStepSettings& settings, PassCounts& counts) {
  const GroundSpec& ground = *settings.ground;
  for (ContactBody& body : bodies) {
    if (!body.isCloth()) continue;
    for (std::size_t i = 0; i < body.x0->size(); ++i) {
      if ((*body.inverseMass)[i] == 0.0) continue;
      const double distance = (*body.x0)[i].y() - ground.height;
      if (!(distance < settings.thickness)) continue;
      Vec3& v = (*body.v)[i];
      const double target = kRepulsionFraction * (settings.thickness - distance) / settings.h;
      if (!(v.y() < target)) continue;
      applyGroundImpulse(v, target, ground.friction);
      (*body.x1)[i] = (*body.x0)[i] + settings.h * v;
      ++counts.groundContacts;
    }
  }
}

bool isClothPair(const std::vector<ContactBody>& bodies, const PrimitivePair& pair) {
  return bodies[pair.bodyA].isCloth() && bodies[pair.bodyB].isCloth();
}

// The repulsion of one near pair: its normal (a touching pair's turned against the approach) and
// the normal velocity that restores a tenth of the overlap.
struct Repulsion {
  Vec3 normal;
  double target;
};

Repulsion repulsion(const std::vector<ContactBody>& bodies, const NearPair& near, const ContactStepSettings& settings) {
  Vec3 normal = near.normal;
  if (near.touching) {
    normal = orientAgainstApproach(normal, sideVelocity(bodies, near.a, settings.h) - sideVelocity(bodies, near.b, settings.h));
  }
  return {normal, kRepulsionFraction * (settings.thickness - near.distance) / settings.h};
}

// Cloth against cloth. Applied one after another in a fixed order, the impulses of the many
// overlapping pairs of a compressed drape each start from what the earlier ones left, and their
// errors add up in one direction: a 64 x 64 sheet draped on a ball, at rest without
// self-collision, crept off the ball within 15 s with it. So the pairs are swept as a Jacobi
// iteration: in each sweep, every pair's impulse is computed from the velocities the sweep starts
// from, then scaled by how shared its vertices are, by 2 / (n_a + n_b), n_a the number of pairs
// pushing side a's vertices (averaged with side a's weights), so that a vertex pushed by many
// pairs takes about their mean rather than their sum. The result does not depend on the pairs'
// order, and each pair pushes its two sides equally and oppositely, so momentum is kept. One sweep
// stops too little (a folding sheet then needed impact zones in 291 of its 360 steps); the sweeps
// go on until no pair asks for more, at most kRepulsionSweeps (16: 6 CCD collisions a step and
// no impact zone for that sheet, 7 with the sequential pass; 8 sweeps still left 177 zones).
constexpr int kRepulsionSweeps = 16;

void repelClothPairs(std::vector<ContactBody>& bodies, const std::vector<NearPair>& nearPairs,
                     const ContactStepSettings& settings, PassCounts& counts) {
  struct Push {
    const NearPair* near;
    Vec3 impulse;  // on side a; side b takes its opposite
  };
  std::vector<const NearPair*> active;
  for (const NearPair& near : nearPairs) {
    if (near.distance < settings.thickness && isClothPair(bodies, near.pair)) active.push_back(&near);
  }
  std::vector<char> pushedOnce(active.size(), 0);
  std::vector<Push> pushes;
  std::vector<std::vector<int>> pushesOf(bodies.size());  // per body and vertex: the pairs pushing it
  for (int sweep = 0; sweep < kRepulsionSweeps; ++sweep) {
    pushes.clear();
    for (auto& perVertex : pushesOf) std::fill(perVertex.begin(), perVertex.end(), 0);
    auto countSide = [&](const ContactSide& side) {
      std::vector<int>& vertexPushes = pushesOf[side.body];
      if (vertexPushes.empty()) vertexPushes.assign(bodies[side.body].v->size(), 0);
      for (int k = 0; k < side.count; ++k) ++vertexPushes[side.vertex[k]];
    };
    for (std::size_t p = 0; p < active.size(); ++p) {
      const NearPair& near = *active[p];
      const Repulsion r = repulsion(bodies, near, settings);
      const PairImpulse impulse =
          contactImpulse(bodies, near.a, near.b, r.normal, r.target, pairFriction(bodies, near.pair), settings.h);
      if (!impulse.result.applied) continue;
      if (!pushedOnce[p]) ++counts.proximityImpulses;
      pushedOnce[p] = 1;
      pushes.push_back({&near, impulse.normal + impulse.friction});
      countSide(near.a);
      countSide(near.b);
    }
    if (pushes.empty()) break;
    auto sharedBy = [&](const ContactSide& side) {
      double n = 0.0;
      for (int k = 0; k < side.count; ++k) n += side.weight[k] * pushesOf[side.body][side.vertex[k]];
      return n;
    };
    for (const Push& push : pushes) {
      const double share = 2.0 / (sharedBy(push.near->a) + sharedBy(push.near->b));
      applySideImpulse(bodies, push.near->a, share * push.impulse, settings.h);
      applySideImpulse(bodies, push.near->b, -share * push.impulse, settings.h);
    }
  }
}

}  // namespace

void runProximityPass(std::vector<ContactBody>& bodies, const std::vector<NearPair>& nearPairs,
                      const ContactStepSettings& settings, PassCounts& counts) {
  if (settings.ground != nullptr) groundProximity(bodies, settings, counts);
  // Against obstacles, one impulse after another: a vertex has few such pairs, and the obstacles'
  // side of each is fixed or one rigid body.
  for (const NearPair& near : nearPairs) {
    if (!(near.distance < settings.thickness) || isClothPair(bodies, near.pair)) continue;
    const Repulsion r = repulsion(bodies, near, settings);
    const ImpulseResult result =
        applyContactImpulse(bodies, near.a, near.b, r.normal, r.target, pairFriction(bodies, near.pair), settings.h);
    if (result.applied) ++counts.proximityImpulses;
  }
  repelClothPairs(bodies, nearPairs, settings, counts);
}

}  // namespace weft
