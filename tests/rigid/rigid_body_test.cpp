// Rigid-body dynamics: impulses, free flight, rotation updates, effective mass, kinematic bodies.
#include "rigid/rigid_body.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "rigid/mass_properties.h"
#include "rigid/shape_meshes.h"

namespace weft {
namespace {

// A 0.2 x 0.4 x 0.6 m box of density 1000 (48 kg): three different principal moments.
RigidBody tiltedBox() {
  const MassProperties properties = computeMassProperties(makeBoxMesh({Vec3(0.1, 0.2, 0.3), 0.0}), 1000.0, "box");
  RigidState state;
  state.position = Vec3(0.5, 1.0, -0.3);
  state.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.8, Vec3(1.0, -2.0, 0.5).normalized()));
  state.linearVelocity = Vec3(0.3, -0.1, 0.2);
  state.angularVelocity = Vec3(0.4, 1.5, -0.7);
  return makeDynamicBody(properties, state);
}

void expectVecNear(const Vec3& actual, const Vec3& expected, double tolerance) {
  EXPECT_LE((actual - expected).norm(), tolerance)
      << "actual " << actual.transpose() << ", expected " << expected.transpose();
}

TEST(RigidBody, ImpulseChangesMomentaByTheImpulseAndItsMoment) {
  RigidBody body = tiltedBox();
  const Vec3 p0 = body.linearMomentum(), l0 = body.angularMomentum();
  const Vec3 impulse(2.0, -1.0, 0.5), point = body.state.position + Vec3(0.1, 0.25, -0.2);
  body.applyImpulse(impulse, point);
  expectVecNear(body.linearMomentum() - p0, impulse, 1e-14);
  expectVecNear(body.angularMomentum() - l0, (point - body.state.position).cross(impulse), 1e-14);
}

TEST(RigidBody, VelocityOfAPoint) {
  const RigidBody body = tiltedBox();
  const Vec3 r(0.1, -0.2, 0.3);
  expectVecNear(body.velocityAt(body.state.position + r),
                body.state.linearVelocity + body.state.angularVelocity.cross(r), 1e-15);
  expectVecNear(body.velocityAt(body.state.position), body.state.linearVelocity, 0.0);
}

// The velocity change of the point a unit impulse is applied at, along the impulse, is the
// effective inverse mass; for any impulse it is K J.
TEST(RigidBody, EffectiveInverseMassIsTheResponseToAUnitImpulse) {
  const RigidBody body = tiltedBox();
  const Vec3 point = body.state.position + Vec3(0.1, -0.2, 0.3);
  for (const Vec3& n : {Vec3(0, 0, 1), Vec3(1, -1, 2).normalized()}) {
    RigidBody pushed = body;
    pushed.applyImpulse(n, point);
    const double response = (pushed.velocityAt(point) - body.velocityAt(point)).dot(n);
    EXPECT_NEAR(body.effectiveInverseMass(n, point), response, 1e-15);
    EXPECT_GT(response, body.inverseMass());  // the lever arm adds to 1/m
  }
  const Vec3 impulse(0.3, 1.1, -0.4);
  RigidBody pushed = body;
  pushed.applyImpulse(impulse, point);
  expectVecNear(pushed.velocityAt(point) - body.velocityAt(point), body.inverseMassMatrixAt(point) * impulse, 1e-15);
  const Mat3 k = body.inverseMassMatrixAt(point);
  EXPECT_LE((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-17);
  // At the centre of mass only the mass resists.
  EXPECT_NEAR(body.effectiveInverseMass(Vec3(0, 1, 0), body.state.position), 1.0 / 48.0, 1e-16);
}

// Free flight: the centre of mass moves in a straight line, and both momenta stay as they were
// even for a tumbling (non-principal) spin.
TEST(RigidBody, FreeFlightKeepsMomentum) {
  RigidBody body = tiltedBox();
  const RigidState start = body.state;
  const Vec3 p0 = body.linearMomentum(), l0 = body.angularMomentum();
  const double e0 = body.kineticEnergy();
  const double dt = 1.0 / 240.0;
  const int steps = 2400;  // 10 s, about 2.6 turns
  double worstEnergyDrift = 0.0;
  for (int i = 0; i < steps; ++i) {
    body.advancePose(dt);
    worstEnergyDrift = std::max(worstEnergyDrift, std::abs(body.kineticEnergy() / e0 - 1.0));
  }
  expectVecNear(body.state.position, start.position + steps * dt * start.linearVelocity, 1e-12);
  expectVecNear(body.linearMomentum(), p0, 1e-13);
  expectVecNear(body.angularMomentum(), l0, 1e-12 * l0.norm());
  EXPECT_NEAR(body.state.orientation.norm(), 1.0, 1e-15);
  EXPECT_GT((body.state.angularVelocity - start.angularVelocity).norm(), 0.1);  // it does precess
  // The midpoint rotation update does not conserve energy exactly; measured drift, for the record.
  std::printf("[   info   ] tumbling box, dt = 1/240 s, 10 s: worst kinetic energy drift %.2e\n", worstEnergyDrift);
  EXPECT_LT(worstEnergyDrift, 1e-6);
}

// Spinning about a principal axis is a steady motion: ω stays as it is, whatever the orientation.
// The box's body x and z axes have the largest and smallest moments: stable spins, kept to rounding.
TEST(RigidBody, TorqueFreeSpinAboutAPrincipalAxisKeepsAngularVelocity) {
  for (const int axis : {0, 2}) {
    RigidBody body = tiltedBox();
    body.state.angularVelocity = body.state.orientation * (3.0 * Vec3::Unit(axis));
    const Vec3 omega = body.state.angularVelocity;
    for (int i = 0; i < 1000; ++i) body.advancePose(1.0 / 120.0);
    expectVecNear(body.state.angularVelocity, omega, 1e-12);
  }
}

// About the intermediate axis (body y) the spin is steady too, but unstable (the tennis-racket or
// Dzhanibekov effect): a small wobble grows like exp(λ t), λ = ω sqrt((I1-I2)(I2-I3)/(I1 I3)),
// until the body flips over, and flips back, while its angular momentum and energy stay.
TEST(RigidBody, SpinAboutTheIntermediateAxisFlipsOver) {
  RigidBody body = tiltedBox();
  body.state.angularVelocity = body.state.orientation * (3.0 * Vec3::UnitY());
  const Vec3 steady = body.state.angularVelocity;
  for (int i = 0; i < 120; ++i) body.advancePose(1.0 / 120.0);  // 1 s: rounding grows only by e^1.4
  expectVecNear(body.state.angularVelocity, steady, 1e-13);

  body = tiltedBox();
  body.state.angularVelocity = body.state.orientation * Vec3(0.003, 3.0, 0.0);
  const Vec3 l0 = body.angularMomentum();
  const double e0 = body.kineticEnergy() - 0.5 * body.mass * body.state.linearVelocity.squaredNorm();
  double lowest = 1.0;              // of the body y axis along the angular momentum
  for (int i = 0; i < 2400; ++i) {  // 10 s; the wobble reaches O(1) after ln(1000) / λ ≈ 5 s
    body.advancePose(1.0 / 240.0);
    lowest = std::min(lowest, (body.state.orientation * Vec3::UnitY()).dot(l0.normalized()));
  }
  EXPECT_LT(lowest, -0.99);  // turned upside down
  expectVecNear(body.angularMomentum(), l0, 1e-12 * l0.norm());
  const double e1 = body.kineticEnergy() - 0.5 * body.mass * body.state.linearVelocity.squaredNorm();
  EXPECT_NEAR(e1 / e0, 1.0, 1e-4);
}

// Stepping a constant ω by the exact rotation of angle |ω| dt composes to the closed form
// exp(ω T): the only error is rounding, measured here after 10^4 steps.
TEST(RigidBody, RotationStepsMatchTheClosedForm) {
  const MassProperties sphere = computeMassProperties(makeSphereMesh({0.1, 2}), 1000.0, "sphere");
  RigidBody body = makeDynamicBody(sphere, {});
  body.inertiaBody = sphere.inertia(0, 0) * Mat3::Identity();  // exactly isotropic: any axis is principal
  const Eigen::Quaterniond start(Eigen::AngleAxisd(0.3, Vec3(0, 1, 1).normalized()));
  body.state.orientation = start;
  body.state.angularVelocity = Vec3(0.7, -1.3, 2.1);
  const double dt = 1.0 / 1000.0;
  const int steps = 10000;
  for (int i = 0; i < steps; ++i) body.advancePose(dt);
  const Vec3 omega = body.state.angularVelocity;
  const Eigen::Quaterniond exact =
      Eigen::Quaterniond(Eigen::AngleAxisd(omega.norm() * steps * dt, omega.normalized())) * start;
  const double error = body.state.orientation.angularDistance(exact);
  std::printf("[   info   ] 10^4 rotation steps of |w| dt = %.4f rad: angle error %.2e rad\n", omega.norm() * dt,
              error);
  EXPECT_LT(error, 1e-11);
}

TEST(RigidBody, GravityIsAVelocityChange) {
  RigidBody body = tiltedBox();
  const Vec3 v0 = body.state.linearVelocity, w0 = body.state.angularVelocity;
  body.applyGravity(Vec3(0, -9.81, 0), 0.01);
  expectVecNear(body.state.linearVelocity, v0 + Vec3(0, -0.0981, 0), 1e-16);
  EXPECT_EQ(body.state.angularVelocity, w0);
}

TEST(RigidBody, KinematicBodyIsUnmovedByImpulsesAndGravity) {
  RigidState state;
  state.position = Vec3(1, 2, 3);
  state.linearVelocity = Vec3(0.5, 0, 0);
  state.angularVelocity = Vec3(0, 2.0, 0);
  RigidBody body = makeKinematicBody(state);
  EXPECT_TRUE(body.isKinematic());
  EXPECT_EQ(body.inverseMass(), 0.0);
  EXPECT_EQ(body.inverseInertiaWorld(), Mat3::Zero());
  EXPECT_EQ(body.effectiveInverseMass(Vec3(0, 0, 1), Vec3(1, 3, 3)), 0.0);
  EXPECT_EQ(body.inverseMassMatrixAt(Vec3(1, 3, 3)), Mat3::Zero());
  body.applyImpulse(Vec3(100, 100, 100), Vec3(1, 3, 3));
  body.applyGravity(Vec3(0, -9.81, 0), 1.0);
  EXPECT_EQ(body.state.linearVelocity, state.linearVelocity);
  EXPECT_EQ(body.state.angularVelocity, state.angularVelocity);
  // It still moves with its own velocities.
  body.advancePose(0.5);
  expectVecNear(body.state.position, Vec3(1.25, 2, 3), 1e-15);
  EXPECT_NEAR(body.state.orientation.angularDistance(Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Vec3::UnitY()))), 0.0,
              1e-15);
  EXPECT_EQ(body.state.angularVelocity, state.angularVelocity);
  EXPECT_FALSE(tiltedBox().isKinematic());
}

TEST(RigidBody, KineticEnergyAndMomenta) {
  const RigidBody body = tiltedBox();
  const Mat3 r = body.state.orientation.toRotationMatrix();
  const Vec3 w = body.state.angularVelocity, v = body.state.linearVelocity;
  const Mat3 worldInertia = r * body.inertiaBody * r.transpose();
  EXPECT_NEAR(body.kineticEnergy(), 0.5 * 48.0 * v.squaredNorm() + 0.5 * w.dot(worldInertia * w), 1e-13);
  expectVecNear(body.linearMomentum(), 48.0 * v, 1e-14);
  expectVecNear(body.angularMomentum(), worldInertia * w, 1e-14);
  EXPECT_LE((body.inverseInertiaWorld() * worldInertia - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-14);
}

// The same calls give the same bits (no hidden state, no threads).
TEST(RigidBody, StepsAreDeterministic) {
  RigidBody a = tiltedBox(), b = tiltedBox();
  for (RigidBody* body : {&a, &b}) {
    for (int i = 0; i < 500; ++i) {
      body->applyGravity(Vec3(0, -9.81, 0), 0.004);
      body->applyImpulse(Vec3(0.01 * i, 0.0, -0.02), body->state.position + Vec3(0.05, 0.1, 0.0));
      body->advancePose(0.004);
    }
  }
  EXPECT_EQ(a.state.position, b.state.position);
  EXPECT_EQ(a.state.orientation.coeffs(), b.state.orientation.coeffs());
  EXPECT_EQ(a.state.angularVelocity, b.state.angularVelocity);
}

}  // namespace
}  // namespace weft
