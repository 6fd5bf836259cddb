#include "contact/contact_impulse.h"

#include <algorithm>

namespace weft {

PairImpulse contactImpulse(const std::vector<ContactBody>& bodies, const ContactSide& a, const ContactSide& b,
                           const Vec3& n, double targetNormalVelocity, double mu, double h) {
  PairImpulse out;
  ImpulseResult& result = out.result;
  const Vec3 relative = sideVelocity(bodies, a, h) - sideVelocity(bodies, b, h);
  const double normalVelocity = n.dot(relative);
  result.normalVelocityBefore = normalVelocity;
  if (!(normalVelocity < targetNormalVelocity)) return out;
  const double inverseMass = sideInverseMass(bodies, a, n) + sideInverseMass(bodies, b, n);
  result.inverseMass = inverseMass;
  if (!(inverseMass > 0.0)) return out;

  // Normal: the impulse that changes the relative normal velocity by exactly the shortfall.
  const double normalChange = targetNormalVelocity - normalVelocity;
  out.normal = (normalChange / inverseMass) * n;
  result.applied = true;

  // Friction (Bridson 2002, §7.2): v_T <- max(1 - mu dv_N / |v_T|, 0) v_T, so sliding slows by at
  // most mu times the normal velocity change and never reverses.
  const Vec3 tangential = relative - normalVelocity * n;
  const double speed = tangential.norm();
  if (mu > 0.0 && speed > 0.0) {
    const Vec3 direction = tangential / speed;
    const double tangentInverseMass = sideInverseMass(bodies, a, direction) + sideInverseMass(bodies, b, direction);
    if (tangentInverseMass > 0.0) {
      const double slowDown = std::min(mu * normalChange, speed);
      out.friction = (-slowDown / tangentInverseMass) * direction;
    }
  }
  return out;
}

ImpulseResult applyContactImpulse(std::vector<ContactBody>& bodies, const ContactSide& a, const ContactSide& b,
                                  const Vec3& n, double targetNormalVelocity, double mu, double h) {
  const PairImpulse impulse = contactImpulse(bodies, a, b, n, targetNormalVelocity, mu, h);
  if (!impulse.result.applied) return impulse.result;
  applySideImpulse(bodies, a, impulse.normal, h);
  applySideImpulse(bodies, b, -impulse.normal, h);
  if (impulse.friction != Vec3::Zero()) {
    applySideImpulse(bodies, a, impulse.friction, h);
    applySideImpulse(bodies, b, -impulse.friction, h);
  }
  return impulse.result;
}

void applyGroundImpulse(Vec3& v, double targetNormalVelocity, double mu) {
  const double normalChange = targetNormalVelocity - v.y();
  v.y() = targetNormalVelocity;
  Vec3 tangential(v.x(), 0.0, v.z());
  const double speed = tangential.norm();
  if (speed > 0.0) tangential *= std::max(0.0, 1.0 - mu * normalChange / speed);
  v.x() = tangential.x();
  v.z() = tangential.z();
}

}  // namespace weft
