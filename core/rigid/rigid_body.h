#pragma once
// A rigid body for obstacles and tools: its mass distribution and its state. The body frame has
// its origin at the centre of mass (recentre a mesh with recentreAtCentreOfMass first), so the
// state's position is the centre of mass.
//
// A kinematic body (mass = infinity) follows a script: impulses and gravity leave it unmoved, its
// inverse mass and inverse inertia are zero, so contact formulas need no special case for it.
//
// Free flight conserves linear and angular momentum exactly: advancePose moves the centre of mass
// with its velocity, turns the body, and recomputes the angular velocity from the (unchanged)
// angular momentum in the new orientation, which is how a thrown sword tumbles. A spin about a
// principal axis keeps its angular velocity; any other spin precesses.
#include <limits>

#include <Eigen/Geometry>

#include "rigid/mass_properties.h"
#include "rigid/rigid_pose.h"
#include "util/types.h"

namespace weft {

inline constexpr double kInfiniteMass = std::numeric_limits<double>::infinity();

struct RigidState {
  Vec3 position = Vec3::Zero();                                     // m, world position of the centre of mass
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // unit; body frame -> world
  Vec3 linearVelocity = Vec3::Zero();                               // m/s, of the centre of mass
  Vec3 angularVelocity = Vec3::Zero();                              // rad/s, world frame

  RigidPose pose() const { return {position, orientation}; }
};

struct RigidBody {
  double mass = 1.0;                    // kg, > 0; kInfiniteMass for a kinematic body
  Mat3 inertiaBody = Mat3::Identity();  // kg m^2, about the centre of mass, body axes; ignored when kinematic
  RigidState state;

  bool isKinematic() const { return mass == kInfiniteMass; }
  double inverseMass() const;        // 1/kg; 0 when kinematic
  Mat3 inverseInertiaBody() const;   // 1/(kg m^2), body axes; 0 when kinematic
  Mat3 inverseInertiaWorld() const;  // R I⁻¹ Rᵀ for the current orientation; 0 when kinematic

  // Velocity of the body point now at `worldPoint`: v + ω × (worldPoint - position).
  Vec3 velocityAt(const Vec3& worldPoint) const;
  // K, the velocity change at `worldPoint` per unit impulse applied there:
  // Δv(point) = K J with K = I/m - [r]ₓ I⁻¹ [r]ₓ, r = worldPoint - position (symmetric, PSD).
  Mat3 inverseMassMatrixAt(const Vec3& worldPoint) const;
  // nᵀ K n = 1/m + (r × n)ᵀ I⁻¹ (r × n): for a unit `direction` n, the change of the point's
  // velocity along n caused by a unit impulse along n (the inverse of the "effective mass").
  double effectiveInverseMass(const Vec3& direction, const Vec3& worldPoint) const;

  // An instantaneous impulse J (N s) at `worldPoint`: v += J/m, ω += I⁻¹ (r × J). No effect when kinematic.
  void applyImpulse(const Vec3& impulse, const Vec3& worldPoint);
  // Gravity (m/s^2) over dt seconds, as a velocity change. No effect when kinematic.
  void applyGravity(const Vec3& gravity, double dt);
  // Moves the pose by dt: the centre of mass by v dt; the orientation by the exact rotation of angle
  // |ω| dt about ω (then normalised), where for a dynamic body ω is its value at mid-step, predicted
  // from the conserved angular momentum (explicit midpoint: second order; equal to the current ω
  // for a spin about a principal axis, and always for a kinematic body). A dynamic body's ω is then
  // recomputed so that its angular momentum is unchanged. Deterministic: no state besides `state`.
  void advancePose(double dt);

  // Dynamic bodies only (the values are infinite for a kinematic one).
  double kineticEnergy() const;  // J
  Vec3 linearMomentum() const;   // kg m/s
  Vec3 angularMomentum() const;  // kg m^2/s, about the centre of mass, world frame
};

// A dynamic body with the mass and inertia of `properties`; the mesh they came from must already
// be centred at its centre of mass (their centreOfMass ≈ 0).
RigidBody makeDynamicBody(const MassProperties& properties, const RigidState& state);
RigidBody makeKinematicBody(const RigidState& state);

}  // namespace weft
