// Pass 1 of Bridson, Fedkiw & Anderson 2002 (§7.1): repulsion between pairs that start the step
// closer than the cloth thickness.
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "collision/closest_points.h"
#include "contact/contact_impulse.h"
#include "contact/contact_passes.h"

namespace weft {
namespace {

// Bridson 2002 restores a tenth of the overlap per step: enough to keep resting contact at the
// thickness, gentle enough not to make stacked layers jitter.
constexpr double kRepulsionFraction = 0.1;

// A unit normal for a pair that touches (distance ~ 0), where the closest points give no direction:
// the given geometric normal, turned against the relative velocity so the impulse separates them.
Vec3 orientAgainstApproach(Vec3 normal, const Vec3& relativeVelocity) {
  if (normal.dot(relativeVelocity) > 0.0) normal = -normal;
  return normal;
}

Vec3 anyPerpendicular(const Vec3& d) {
  const Vec3 axis = std::abs(d.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 n = d.cross(axis);
  return n.squaredNorm() > 0.0 ? n.normalized() : Vec3::UnitY();
}

// The contact of a pair at the start of the step when it is closer than the thickness.
bool proximityContact(const std::vector<ContactBody>& bodies, const PrimitivePair& pair, double thickness, double h,
                      ContactSide& a, ContactSide& b, Vec3& normal, double& distance) {
  const std::vector<Vec3>& xa = *bodies[pair.bodyA].x0;
  const std::vector<Vec3>& xb = *bodies[pair.bodyB].x0;
  Vec3 fallback;
  if (pair.kind == PairKind::VertexFace) {
    const auto& face = bodies[pair.bodyB].topology->triangles[pair.featureB];
    const Vec3& p = xa[pair.featureA];
    const PointTriangleClosest c = closestPointOnTriangle(p, xb[face[0]], xb[face[1]], xb[face[2]]);
    if (!(c.distance < thickness)) return false;
    a = vertexSide(pair.bodyA, pair.featureA);
    b = faceSide(bodies, pair.bodyB, pair.featureB, c.weights);
    distance = c.distance;
    normal = p - c.point;
    fallback = (xb[face[1]] - xb[face[0]]).cross(xb[face[2]] - xb[face[0]]);
  } else {
    const auto& ea = bodies[pair.bodyA].topology->edges[pair.featureA];
    const auto& eb = bodies[pair.bodyB].topology->edges[pair.featureB];
    const SegmentSegmentClosest c = closestSegmentSegment(xa[ea[0]], xa[ea[1]], xb[eb[0]], xb[eb[1]]);
    if (!(c.distance < thickness)) return false;
    a = edgeSide(bodies, pair.bodyA, pair.featureA, c.s);
    b = edgeSide(bodies, pair.bodyB, pair.featureB, c.t);
    distance = c.distance;
    normal = sidePosition(bodies, a, false) - sidePosition(bodies, b, false);
    fallback = (xa[ea[1]] - xa[ea[0]]).cross(xb[eb[1]] - xb[eb[0]]);
  }
  // Below a thousandth of the thickness the closest-point direction is mostly rounding.
  if (distance > 1e-3 * thickness) {
    normal /= distance;
  } else {
    const Vec3 relative = sideVelocity(bodies, a, h) - sideVelocity(bodies, b, h);
    normal = fallback.squaredNorm() > 0.0 ? fallback.normalized() : anyPerpendicular(relative);
    normal = orientAgainstApproach(normal, relative);
  }
  return true;
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
      const double normalChange = target - v.y();
      v.y() = target;
      // Coulomb friction against a static plane (Bridson 2002 §7.2).
      Vec3 tangential(v.x(), 0.0, v.z());
      const double speed = tangential.norm();
      if (speed > 0.0) tangential *= std::max(0.0, 1.0 - ground.friction * normalChange / speed);
      v.x() = tangential.x();
      v.z() = tangential.z();
      (*body.x1)[i] = (*body.x0)[i] + settings.h * v;
      ++counts.groundContacts;
    }
  }
}

}  // namespace

void runProximityPass(std::vector<ContactBody>& bodies, const std::vector<PrimitivePair>& pairs,
                      const ContactStepSettings& settings, PassCounts& counts) {
  if (settings.ground != nullptr) groundProximity(bodies, settings, counts);
  for (const PrimitivePair& pair : pairs) {
    ContactSide a, b;
    Vec3 normal;
    double distance = 0.0;
    if (!proximityContact(bodies, pair, settings.thickness, settings.h, a, b, normal, distance)) continue;
    const double target = kRepulsionFraction * (settings.thickness - distance) / settings.h;
    const ImpulseResult result =
        applyContactImpulse(bodies, a, b, normal, target, pairFriction(bodies, pair), settings.h);
    if (result.applied) ++counts.proximityImpulses;
  }
}

}  // namespace weft
