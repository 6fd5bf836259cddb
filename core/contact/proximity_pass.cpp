// Pass 1 of Bridson, Fedkiw & Anderson 2002 (§7.1): repulsion between pairs that start the step
// closer than the cloth thickness.
#include <algorithm>
#include <cmath>

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

}  // namespace

void runProximityPass(std::vector<ContactBody>& bodies, const std::vector<NearPair>& nearPairs,
                      const ContactStepSettings& settings, PassCounts& counts) {
  if (settings.ground != nullptr) groundProximity(bodies, settings, counts);
  for (const NearPair& near : nearPairs) {
    if (!(near.distance < settings.thickness)) continue;
    Vec3 normal = near.normal;
    if (near.touching) {
      normal = orientAgainstApproach(normal, sideVelocity(bodies, near.a, settings.h) - sideVelocity(bodies, near.b, settings.h));
    }
    const double target = kRepulsionFraction * (settings.thickness - near.distance) / settings.h;
    const ImpulseResult result =
        applyContactImpulse(bodies, near.a, near.b, normal, target, pairFriction(bodies, near.pair), settings.h);
    if (result.applied) ++counts.proximityImpulses;
  }
}

}  // namespace weft
