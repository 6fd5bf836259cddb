#pragma once
// BDF2, the second-order backward differentiation formula, for cloth (Choi & Ko 2002 chose it for
// its small numerical damping at large steps): each step solves the implicit step of
// implicit_step.h in BDF2 form, either linearized (one linear solve, as LinearizedBackwardEuler;
// scene value `bdf2`) or by Newton's method (as NewtonIntegrator; `bdf2_newton`). The forces,
// damping, pins and grab are backward Euler's, taken implicitly at the end of the step.
//
// BDF2 builds on the previous step. Where that history is invalid the step is one backward Euler
// step instead (of the same solver; counted in SolverStats::bdf2Restarts), and BDF2 resumes from
// the next one:
//  - there is none: the first step, or a fresh integrator after World::setSolver;
//  - the topology changed: a tear (vertices were added), a material or weft edit (topologyChanged);
//  - the cloth is not in the state this integrator left it in: something between two steps moved a
//    vertex or changed a velocity (a contact impulse or impact zone, a tear's vertex move, an
//    edit). Extrapolating across such a jump would carry 4/3 of it into the next step;
//  - the step length changed (a live edit of dt or substeps). A variable-step BDF2 could go on, but
//    the edit is rare and the one backward Euler step costs the same;
//  - the contact stage holds vertices of this cloth in the solve (contact/held_contacts.h): the
//    hold keeps the momentum exchanged with obstacles exact in backward Euler's form. A cloth that
//    rests on something therefore steps with backward Euler while it rests.
// Pinned vertices need no restart: the solve takes them to their script's target, at the velocity
// (target - x^) / h^ that BDF2 gives a pin.
#include <memory>
#include <vector>

#include "integrate/implicit_step.h"
#include "integrate/integrator.h"

namespace weft {

class Bdf2Integrator final : public Integrator {
 public:
  // `solver`: LinearizedBackwardEuler or NewtonIntegrator, which solve either form of the step.
  explicit Bdf2Integrator(std::unique_ptr<Integrator> solver) : solver_(std::move(solver)) {}
  void advance(Cloth& cloth, const StepInputs& inputs, StageProfile& profile, SolverStats& stats) override;
  void topologyChanged() override {
    hasHistory_ = false;
    solver_->topologyChanged();
  }
  void topologyChanged(const Cloth& cloth, const TopologyChange& change) override {
    hasHistory_ = false;
    solver_->topologyChanged(cloth, change);
  }
  std::unique_ptr<Integrator> copyWithoutCaches(const SolverSpec& spec) const override;

 private:
  // The previous step is still valid history for a BDF2 step from the cloth's state (bdf2.h).
  bool historyHolds(const Cloth& cloth, const StepInputs& inputs) const;

  std::unique_ptr<Integrator> solver_;
  bool hasHistory_ = false;
  double stepLength_ = 0.0;                   // h of the step that left (x_n, v_n) (s)
  std::vector<Vec3> previousX_, previousV_;   // x_{n-1}, v_{n-1}
  std::vector<Vec3> currentX_, currentV_;     // x_n, v_n as this integrator left them
  ImplicitStep step_;
};

}  // namespace weft
