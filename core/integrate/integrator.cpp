#include "integrate/integrator.h"

#include "integrate/bdf2.h"
#include "integrate/linearized_backward_euler.h"
#include "integrate/newton.h"
#include "integrate/symplectic_euler.h"

namespace weft {

std::unique_ptr<Integrator> makeIntegrator(const SolverSpec& spec) {
  switch (spec.integrator) {
    case IntegratorKind::Newton: return std::make_unique<NewtonIntegrator>(spec);
    case IntegratorKind::SymplecticEuler: return std::make_unique<SymplecticEuler>();
    case IntegratorKind::Bdf2: return std::make_unique<Bdf2Integrator>(std::make_unique<LinearizedBackwardEuler>(spec));
    case IntegratorKind::Bdf2Newton: return std::make_unique<Bdf2Integrator>(std::make_unique<NewtonIntegrator>(spec));
    case IntegratorKind::LinearizedBackwardEuler: break;
  }
  return std::make_unique<LinearizedBackwardEuler>(spec);
}

std::unique_ptr<Integrator> Integrator::copyWithoutCaches(const SolverSpec& spec) const { return makeIntegrator(spec); }

}  // namespace weft
