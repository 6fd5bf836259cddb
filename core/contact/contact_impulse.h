#pragma once
// The impulse every pass applies to a pair of contact sides (Bridson, Fedkiw & Anderson 2002,
// §7.1-7.2): raise the relative normal velocity to a target, then reduce the relative tangential
// velocity by Coulomb friction, |dv_T| <= mu |dv_N|.
#include <vector>

#include "contact/contact_body.h"

namespace weft {

struct ImpulseResult {
  bool applied = false;
  double normalVelocityBefore = 0.0;  // relative normal velocity before (m/s), < 0 when approaching
  double inverseMass = 0.0;           // effective inverse mass of the pair along the normal (1/kg)
};

// The impulses applyContactImpulse applies to side a (side b takes their opposites), computed
// from the bodies' current velocities without applying them.
struct PairImpulse {
  ImpulseResult result;
  Vec3 normal = Vec3::Zero();    // N s, along n
  Vec3 friction = Vec3::Zero();  // N s, against the relative tangential velocity
};
PairImpulse contactImpulse(const std::vector<ContactBody>& bodies, const ContactSide& a, const ContactSide& b,
                           const Vec3& n, double targetNormalVelocity, double mu, double h);

// Side a against side b, n the unit normal pointing from b towards a. When the relative normal
// velocity n.(v_a - v_b) is below targetNormalVelocity, applies equal and opposite impulses that
// bring it to the target (inelastic: no bounce beyond it), then friction with coefficient mu.
// Does nothing when both sides are infinitely heavy.
ImpulseResult applyContactImpulse(std::vector<ContactBody>& bodies, const ContactSide& a, const ContactSide& b,
                                  const Vec3& n, double targetNormalVelocity, double mu, double h);

// A cloth vertex against the ground plane (normal +y, infinitely heavy): raises v.y to the target,
// then Coulomb friction on the horizontal velocity (Bridson 2002 §7.2), as applyContactImpulse
// does for a pair.
void applyGroundImpulse(Vec3& v, double targetNormalVelocity, double mu);

}  // namespace weft
