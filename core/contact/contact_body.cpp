#include "contact/contact_body.h"

#include "contact/obstacle.h"

namespace weft {

Vec3 sidePosition(const std::vector<ContactBody>& bodies, const ContactSide& side, bool atEnd) {
  const std::vector<Vec3>& x = atEnd ? *bodies[side.body].x1 : *bodies[side.body].x0;
  Vec3 p = Vec3::Zero();
  for (int k = 0; k < side.count; ++k) p += side.weight[k] * x[side.vertex[k]];
  return p;
}

Vec3 sideVelocity(const std::vector<ContactBody>& bodies, const ContactSide& side, double h) {
  const ContactBody& body = bodies[side.body];
  Vec3 velocity = Vec3::Zero();
  if (body.v != nullptr) {
    for (int k = 0; k < side.count; ++k) velocity += side.weight[k] * (*body.v)[side.vertex[k]];
    return velocity;
  }
  for (int k = 0; k < side.count; ++k) {
    const int i = side.vertex[k];
    velocity += side.weight[k] * ((*body.x1)[i] - (*body.x0)[i]);
  }
  return velocity / h;
}

double sideInverseMass(const std::vector<ContactBody>& bodies, const ContactSide& side, const Vec3& n) {
  const ContactBody& body = bodies[side.body];
  if (body.obstacle != nullptr) return obstacleInverseMass(*body.obstacle, sidePosition(bodies, side, false), n);
  // A point w_k-weighted over vertices moves by sum w_k dv_k; an impulse J split as w_k J over
  // them gives dv = sum w_k^2 / m_k J (the generalisation of Bridson 2002's 2I / (1 + sum w^2)).
  double inverse = 0.0;
  for (int k = 0; k < side.count; ++k) {
    inverse += side.weight[k] * side.weight[k] * (*body.inverseMass)[side.vertex[k]];
  }
  return inverse;
}

void applySideImpulse(std::vector<ContactBody>& bodies, const ContactSide& side, const Vec3& impulse, double h) {
  ContactBody& body = bodies[side.body];
  if (body.obstacle != nullptr) {
    applyObstacleImpulse(*body.obstacle, impulse, sidePosition(bodies, side, false), h);
    return;
  }
  for (int k = 0; k < side.count; ++k) {
    const int i = side.vertex[k];
    const double inverseMass = (*body.inverseMass)[i];
    if (inverseMass == 0.0) continue;
    (*body.v)[i] += side.weight[k] * inverseMass * impulse;
    (*body.x1)[i] = (*body.x0)[i] + h * (*body.v)[i];
  }
}

}  // namespace weft
