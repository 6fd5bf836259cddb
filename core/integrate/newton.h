#pragma once
#include "integrate/implicit_system.h"
#include "integrate/integrator.h"

namespace weft {

// Backward Euler solved by Newton's method: minimizes the incremental potential
//   Phi(x) = 1/(2h^2) |x - x0 - h v0|_M^2 + E(x) - f_ext.x + 1/(2h) |x - x0|_D^2,
// whose stationary point is M (v+ - v0)/h = f_int(x+) + f_ext - D v+ with v+ = (x - x0)/h and
// the damping matrix D = c_m M + beta H(x0). Each iteration solves with the definite Hessian and
// backtracks along the step until Phi decreases enough (Armijo), so it converges from any start.
// Given a BDF2 form (implicit_step.h), x0, v0 and h are its x^, v^ and h^: the same potential,
// minimized for the BDF2 step. Vertices held by obstacles (integrator.h HeldVertex) add their
// term (heldEnergy), so contact and the cloth's stiffness meet inside the solve as in the
// linearized integrator; left to the impulses, a ball's impact strained the cloth next to the
// vertices it moved so far in one step that Newton stopped at its iteration cap, run after run.
class NewtonIntegrator final : public Integrator {
 public:
  explicit NewtonIntegrator(const SolverSpec& spec)
      : system_(spec), maxIterations_(spec.newtonMaxIterations), tolerance_(spec.newtonTolerance) {}
  void advance(Cloth& cloth, const StepInputs& inputs, StageProfile& profile, SolverStats& stats) override;
  void topologyChanged() override { system_.patternStale = true; }
  void topologyChanged(const Cloth& cloth, const TopologyChange& change) override {
    system_.topologyChanged(cloth, change);
  }

 private:
  double potential(const Cloth& cloth, const std::vector<Vec3>& x, const StepInputs& in, StageProfile& profile);
  // The held vertices' share of Phi (integrator.h HeldVertex): each carries its weight W (kg)
  // moving at the obstacle's velocity u, 1/(2h^2) (x - x0 - h u)^T W (x - x0 - h u), whose
  // gradient W (v - u) / h is the linearized integrator's W (v - u) row, per unit of step.
  double heldEnergy(const std::vector<Vec3>& x, const StepInputs& in, double h) const;

  ImplicitSystem system_;
  int maxIterations_;
  double tolerance_;
  // Work arrays kept between steps so that a step allocates nothing once sized.
  std::vector<Vec3> x0_, inertialTarget_, current_, trial_;
  Eigen::VectorXd displacement_, dampedDisplacement_;
  SystemMatrix::Sparse dampingHessian_;  // beta * H(x0) when stiffness damping is on
  Eigen::VectorXd gradient_, step_;
  std::vector<Mat3> heldWeights_;  // per held vertex of this step, its weight W (kg), set by the first assembly
};

}  // namespace weft
