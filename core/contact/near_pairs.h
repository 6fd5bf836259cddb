#pragma once
// Pairs that are near each other at the start of the step, measured once: their closest points,
// distance and normal. The held vertices (held_contacts.h) and the proximity pass
// (contact_passes.h) both read them, so each pair's closest points are computed once per step.
#include <vector>

#include "contact/contact_body.h"
#include "contact/contact_pairs.h"

namespace weft {

struct NearPair {
  PrimitivePair pair;
  ContactSide a, b;        // the closest points, as weighted vertices of each body
  double distance = 0.0;   // m, at the start of the step
  Vec3 normal = Vec3::UnitY();  // unit, from b towards a; when `touching`, a geometric stand-in
  bool touching = false;   // closer than a thousandth of the reach: the closest points give no
                           // reliable direction, `normal` is the face normal or the edges' cross
                           // product with an arbitrary sign (orient it against the approach)
};

// Measures `pairs` at the start positions and keeps those closer than `reach`, in pair order.
void measureNearPairs(const std::vector<ContactBody>& bodies, const std::vector<PrimitivePair>& pairs, double reach,
                      std::vector<NearPair>& out);

}  // namespace weft
