#include "rigid/rigid_body.h"

#include <cassert>
#include <cmath>

namespace weft {

namespace {

Mat3 cross(const Vec3& r) {
  Mat3 m;
  m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return m;
}

// The rotation by |v| radians about v (the exponential map).
Eigen::Quaterniond rotationBy(const Vec3& rotationVector) {
  const double angle = rotationVector.norm();
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotationVector / angle));
}

}  // namespace

double RigidBody::inverseMass() const { return isKinematic() ? 0.0 : 1.0 / mass; }

Mat3 RigidBody::inverseInertiaBody() const { return isKinematic() ? Mat3::Zero() : Mat3(inertiaBody.inverse()); }

Mat3 RigidBody::inverseInertiaWorld() const {
  if (isKinematic()) return Mat3::Zero();
  const Mat3 rotation = state.orientation.toRotationMatrix();
  return rotation * inverseInertiaBody() * rotation.transpose();
}

Vec3 RigidBody::velocityAt(const Vec3& worldPoint) const {
  return state.linearVelocity + state.angularVelocity.cross(worldPoint - state.position);
}

Mat3 RigidBody::inverseMassMatrixAt(const Vec3& worldPoint) const {
  const Mat3 r = cross(worldPoint - state.position);
  return inverseMass() * Mat3::Identity() - r * inverseInertiaWorld() * r;
}

double RigidBody::effectiveInverseMass(const Vec3& direction, const Vec3& worldPoint) const {
  const Vec3 rn = (worldPoint - state.position).cross(direction);
  return inverseMass() * direction.squaredNorm() + rn.dot(inverseInertiaWorld() * rn);
}

void RigidBody::applyImpulse(const Vec3& impulse, const Vec3& worldPoint) {
  if (isKinematic()) return;
  state.linearVelocity += impulse / mass;
  state.angularVelocity += inverseInertiaWorld() * (worldPoint - state.position).cross(impulse);
}

void RigidBody::applyGravity(const Vec3& gravity, double dt) {
  if (isKinematic()) return;
  state.linearVelocity += gravity * dt;
}

void RigidBody::advancePose(double dt) {
  state.position += state.linearVelocity * dt;
  if (state.angularVelocity.isZero(0.0)) return;
  if (isKinematic()) {
    state.orientation = (rotationBy(state.angularVelocity * dt) * state.orientation).normalized();
    return;
  }
  // Explicit midpoint on the rotation group: predict the orientation at mid-step, take the angular
  // velocity there from the conserved momentum, and turn the whole step by it. Second order in dt
  // (the first-order "turn by the current ω" drifts ~100x more in energy on a tumbling box), and
  // exact for a spin about a principal axis, where ω is the same at every instant.
  const Vec3 momentum = angularMomentum();
  const Eigen::Quaterniond start = state.orientation;
  state.orientation = (rotationBy(state.angularVelocity * (0.5 * dt)) * start).normalized();
  const Vec3 midStep = inverseInertiaWorld() * momentum;
  state.orientation = (rotationBy(midStep * dt) * start).normalized();
  state.angularVelocity = inverseInertiaWorld() * momentum;
}

double RigidBody::kineticEnergy() const {
  assert(!isKinematic());
  return 0.5 * mass * state.linearVelocity.squaredNorm() + 0.5 * state.angularVelocity.dot(angularMomentum());
}

Vec3 RigidBody::linearMomentum() const {
  assert(!isKinematic());
  return mass * state.linearVelocity;
}

Vec3 RigidBody::angularMomentum() const {
  assert(!isKinematic());
  const Mat3 rotation = state.orientation.toRotationMatrix();
  return rotation * inertiaBody * rotation.transpose() * state.angularVelocity;
}

RigidBody makeDynamicBody(const MassProperties& properties, const RigidState& state) {
  assert(properties.mass > 0.0);
  assert(properties.centreOfMass.norm() <= 1e-9 * (1.0 + std::cbrt(properties.volume)));
  RigidBody body;
  body.mass = properties.mass;
  body.inertiaBody = properties.inertia;
  body.state = state;
  return body;
}

RigidBody makeKinematicBody(const RigidState& state) {
  RigidBody body;
  body.mass = kInfiniteMass;
  body.inertiaBody = Mat3::Zero();
  body.state = state;
  return body;
}

}  // namespace weft
