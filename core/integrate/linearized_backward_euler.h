#pragma once
#include "integrate/implicit_system.h"
#include "integrate/integrator.h"

namespace weft {

// The thesis' linearized backward Euler step (Eq. 2.47): one linear solve per step.
class LinearizedBackwardEuler final : public Integrator {
 public:
  explicit LinearizedBackwardEuler(const SolverSpec& spec) : system_(spec) {}
  void advance(Cloth& cloth, const StepInputs& inputs, StageProfile& profile, SolverStats& stats) override;
  void topologyChanged() override { system_.patternStale = true; }
  void topologyChanged(const Cloth& cloth, const TopologyChange& change) override {
    system_.topologyChanged(cloth, change);
  }
  // Unless BDF2 hands it a form (then it evaluates at the extrapolated state).
  std::optional<HessianMode> membraneModeAtStart() const override { return HessianMode::Definite; }

 private:
  // The impulse each held vertex (integrator.h) received from its obstacle in the solve.
  void reportReactions(const StepInputs& inputs);
  // The 3x3 weight a held vertex adds to its diagonal block (integrator.h HeldVertex).
  Mat3 holdWeight(HeldVertex& held) const;

  ImplicitSystem system_;
};

}  // namespace weft
