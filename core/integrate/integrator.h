#pragma once
// Time integrators: each advances one cloth by one (sub)step.
//
//  - LinearizedBackwardEuler: the thesis' Eq. 2.47, (M - h^2 K) v+ = M v + h f(x), one linear
//    solve per step (Baraff & Witkin 1998). The default.
//  - Newton: backward Euler solved to a tolerance by Newton's method on the incremental potential,
//    with a backtracking line search. The accurate option.
//  - SymplecticEuler: v += h M^-1 f(x), x += h v. The explicit baseline (needs small steps).
//  - Bdf2Integrator (bdf2.h): the second-order BDF2 step, solved by either of the first two (both
//    solve the general implicit step of implicit_step.h), with one backward Euler step wherever
//    its two-step history is invalid.
#include <memory>
#include <optional>
#include <vector>

#include "forces/grab_spring.h"
#include "forces/membrane_ahead.h"
#include "mesh/topology_change.h"
#include "scene/scene.h"
#include "sim/stage_profile.h"

namespace weft {

struct Cloth;
struct ImplicitStep;
struct SolverStats;

// A cloth vertex resting on an obstacle or the ground (contact/held_contacts.h), held in this
// step's implicit solve so that contact and the cloth's stiffness meet inside it:
//  - ShareMass (a dynamic obstacle): the vertex carries `massShare` kg of the obstacle moving at
//    its velocity there; its row gains massShare (v - velocity).
//  - NormalSupport (a static or kinematic obstacle, the ground): along `normal` only, the vertex is
//    made much heavier than anything around it (a penalty of kNormalSupportWeight times its
//    diagonal entry) moving at the support's velocity; it slides freely along the surface.
// The impulse the vertex received that way is reported back as the reaction (the obstacle takes
// its opposite when it is dynamic).
struct HeldVertex {
  enum class Kind { ShareMass, NormalSupport };
  static constexpr double kNormalSupportWeight = 100.0;
  Kind kind = Kind::ShareMass;
  int vertex = 0;
  Vec3 velocity = Vec3::Zero();  // the obstacle's velocity at the vertex (m/s)
  Vec3 normal = Vec3::UnitY();   // out of the obstacle (NormalSupport)
  double massShare = 0.0;        // kg (ShareMass; set by the integrator for NormalSupport)
  Vec3 reaction = Vec3::Zero();  // out: impulse the vertex received from the obstacle (N s)
};

// The 3x3 weight (kg) a held vertex adds to its row of the step's momentum balance: massShare for
// ShareMass; for NormalSupport, kNormalSupportWeight times `diagonal()` (the vertex's largest
// diagonal entry of that balance, in kg) along the normal, read on its first use in the step.
template <typename Diagonal>
Mat3 holdWeight(HeldVertex& held, const Diagonal& diagonal) {
  if (held.kind == HeldVertex::Kind::ShareMass) return held.massShare * Mat3::Identity();
  if (held.massShare == 0.0) held.massShare = HeldVertex::kNormalSupportWeight * diagonal();
  return held.massShare * held.normal * held.normal.transpose();
}

struct StepInputs {
  double time = 0.0;  // time at the start of the step (s)
  double dt = 0.0;    // step length (s)
  Vec3 gravity = Vec3::Zero();
  const WindSpec* wind = nullptr;  // null: no wind stage
  DampingSpec damping;
  bool bending = true;
  int threads = 1;
  // The implicit integrators (linearized backward Euler, Newton, and BDF2 of either, which then
  // takes a backward Euler step: bdf2.h); symplectic Euler leaves contact to the impulses.
  std::vector<HeldVertex>* heldVertices = nullptr;
  // The editor's grab on this cloth (forces/grab_spring.h); null: nothing grabbed. Part of the
  // implicit solve (force and Jacobian) in the implicit integrators.
  const GrabSpring* grab = nullptr;
  // The implicit integrators' step form (implicit_step.h); null: backward Euler from the cloth's
  // state. Set by Bdf2Integrator.
  const ImplicitStep* form = nullptr;
  // This cloth's membrane contributions evaluated at the end of the last step
  // (forces/membrane_ahead.h), or null.
  const MembraneAhead* membraneAhead = nullptr;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual void advance(Cloth& cloth, const StepInputs& inputs, StageProfile& profile, SolverStats& stats) = 0;
  // Called after a topology change nobody described: the next step rebuilds the matrix pattern.
  virtual void topologyChanged() {}
  // Called after a local topology change (a tear) of `cloth`, described by `change`: the matrix
  // pattern grows by what the change couples (SystemMatrix::growPattern) instead of being rebuilt.
  virtual void topologyChanged(const Cloth& cloth, const TopologyChange& change) {
    (void)cloth;
    (void)change;
    topologyChanged();
  }
  // A new integrator of the kind `spec` makes, holding what the coming steps' physics read from
  // this one (BDF2's two-step history) and none of its caches (the matrix pattern, a lagged
  // factorization: the copy builds them at its first step, as after a solver edit). For
  // World::clone: a copy of the world steps on from the same state without the memory of a
  // factorization per copy.
  virtual std::unique_ptr<Integrator> copyWithoutCaches(const SolverSpec& spec) const;
  // The Hessian mode in which the next advance evaluates the membrane at the cloth's positions as
  // they stand, if it does (a cache of that evaluation made at the end of a step then serves it,
  // forces/membrane_ahead.h); none when it evaluates elsewhere first.
  virtual std::optional<HessianMode> membraneModeAtStart() const { return std::nullopt; }
};

std::unique_ptr<Integrator> makeIntegrator(const SolverSpec& spec);

// Gravity and wind on every vertex (the external forces, constant over a step).
void externalForces(const Cloth& cloth, const StepInputs& inputs, std::vector<Vec3>& forces, StageProfile& profile);

}  // namespace weft
