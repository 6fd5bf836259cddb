#include "integrate/newton.h"

#include <cmath>

#include "integrate/implicit_step.h"
#include "sim/cloth.h"
#include "sim/world.h"

namespace weft {

double NewtonIntegrator::potential(const Cloth& cloth, const std::vector<Vec3>& x, const StepInputs& in,
                                   StageProfile& profile) {
  ElasticOptions options;
  options.bending = in.bending;
  options.threads = in.threads;
  const ElasticSummary elastic =
      evaluateElasticForces(cloth, x, options, system_.elastic, system_.internalForce, nullptr, profile);
  const double h = in.form != nullptr ? in.form->h : in.dt;  // h^ of a BDF2 form (implicit_step.h)
  double inertia = 0.0, external = 0.0, damping = 0.0;
  const double grab = in.grab != nullptr ? grabEnergy(*in.grab, x[in.grab->vertex]) : 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    const Vec3 d = x[i] - inertialTarget_[i];
    inertia += cloth.mesh.mass[i] * d.squaredNorm();
    external += system_.externalForce[i].dot(x[i]);
    damping += in.damping.mass * cloth.mesh.mass[i] * (x[i] - x0_[i]).squaredNorm();
  }
  if (in.damping.stiffness > 0.0) {
    displacement_ = flat(x) - flat(x0_);
    dampedDisplacement_.noalias() = dampingHessian_ * displacement_;
    damping += displacement_.dot(dampedDisplacement_);
  }
  return inertia / (2.0 * h * h) + elastic.membraneEnergy + elastic.bendingEnergy + grab - external + damping / (2.0 * h) +
         heldEnergy(x, in, h);
}

double NewtonIntegrator::heldEnergy(const std::vector<Vec3>& x, const StepInputs& in, double h) const {
  if (in.heldVertices == nullptr) return 0.0;
  double energy = 0.0;
  for (std::size_t k = 0; k < in.heldVertices->size(); ++k) {
    const HeldVertex& held = (*in.heldVertices)[k];
    const Vec3 d = x[held.vertex] - x0_[held.vertex] - h * held.velocity;
    energy += d.dot(heldWeights_[k] * d);
  }
  return energy / (2.0 * h * h);
}

void NewtonIntegrator::advance(Cloth& cloth, const StepInputs& in, StageProfile& profile, SolverStats& stats) {
  ClothMesh& mesh = cloth.mesh;
  const int n = mesh.vertexCount();
  // The step's form (implicit_step.h): backward Euler from the cloth's state unless BDF2 hands
  // one; then h is h^ = 2dt/3 and (x0, v0) the extrapolated base state (x^, v^).
  const ImplicitStep* form = in.form;
  const double h = form != nullptr ? form->h : in.dt;
  const std::vector<Vec3>& v0 = form != nullptr ? form->v : mesh.v;
  system_.beginStep(cloth, in, profile);

  x0_ = form != nullptr ? form->x : mesh.x;
  inertialTarget_.resize(n);
  for (int i = 0; i < n; ++i) inertialTarget_[i] = x0_[i] + h * v0[i];
  std::vector<Vec3>& x = current_;
  x = inertialTarget_;  // start from the inertial prediction
  for (size_t k = 0; k < system_.pinnedVertices.size(); ++k) x[system_.pinnedVertices[k]] = system_.pinnedTargets[k];

  ElasticOptions options;
  options.bending = in.bending;
  options.hessian = HessianMode::Definite;
  options.threads = in.threads;
  if (in.damping.stiffness > 0.0) {
    system_.matrix.setZero();
    evaluateElasticForces(cloth, x0_, options, system_.elastic, system_.internalForce, &system_.matrix, profile);
    dampingHessian_ = system_.matrix.matrix() * in.damping.stiffness;
  }

  const double externalForceScale = flat(system_.externalForce).norm();
  double lastChange = 0.0, firstChange = 0.0;
  int iteration = 0;
  for (; iteration < maxIterations_; ++iteration) {
    system_.matrix.setZero();
    const ElasticSummary elastic =
        evaluateElasticForces(cloth, x, options, system_.elastic, system_.internalForce, &system_.matrix, profile);
    if (in.grab != nullptr) addGrabForce(*in.grab, x, system_.internalForce, profile);
    double phi = 0.0;
    {
      StageTimer timer(profile, "assemble");
      // Gradient of Phi and its Hessian M/h^2 + H(x) + D/h.
      gradient_.resize(3 * n);
      double inertia = 0.0, external = 0.0, damping = 0.0;
      for (int i = 0; i < n; ++i) {
        const Vec3 d = x[i] - inertialTarget_[i];
        const Vec3 moved = x[i] - x0_[i];
        gradient_.segment<3>(3 * i) = mesh.mass[i] * d / (h * h) - system_.internalForce[i] - system_.externalForce[i] +
                                      in.damping.mass * mesh.mass[i] * moved / h;
        inertia += mesh.mass[i] * d.squaredNorm();
        external += system_.externalForce[i].dot(x[i]);
        damping += in.damping.mass * mesh.mass[i] * moved.squaredNorm();
      }
      if (in.damping.stiffness > 0.0) {
        displacement_ = flat(x) - flat(x0_);
        dampedDisplacement_.noalias() = dampingHessian_ * displacement_;
        gradient_ += dampedDisplacement_ / h;
        damping += displacement_.dot(dampedDisplacement_);
        system_.matrix.matrix() += dampingHessian_ / h;
      }
      const double grab = in.grab != nullptr ? grabEnergy(*in.grab, x[in.grab->vertex]) : 0.0;
      phi = inertia / (2.0 * h * h) + elastic.membraneEnergy + elastic.bendingEnergy + grab - external + damping / (2.0 * h);
      for (int i = 0; i < n; ++i) system_.matrix.addDiagonal(i, mesh.mass[i] * (1.0 / (h * h) + in.damping.mass / h));
      if (in.grab != nullptr) system_.matrix.addBlock(in.grab->vertex, in.grab->vertex, -grabForceJacobian(*in.grab));
      if (in.heldVertices != nullptr) {
        // The weights once per step, a NormalSupport's from the first assembly's diagonal times
        // h^2 (the linearized integrator's diagonal, in kg); gradient W (x - x0 - h u)/h^2,
        // Hessian W/h^2.
        if (iteration == 0) {
          heldWeights_.clear();
          for (HeldVertex& held : *in.heldVertices) {
            heldWeights_.push_back(weft::holdWeight(held, [&] { return h * h * system_.matrix.largestDiagonal(held.vertex); }));
          }
        }
        for (std::size_t k = 0; k < in.heldVertices->size(); ++k) {
          const HeldVertex& held = (*in.heldVertices)[k];
          const Vec3 d = x[held.vertex] - x0_[held.vertex] - h * held.velocity;
          gradient_.segment<3>(3 * held.vertex) += heldWeights_[k] * d / (h * h);
          system_.matrix.addBlock(held.vertex, held.vertex, heldWeights_[k] / (h * h));
        }
        phi += heldEnergy(x, in, h);
      }
      system_.rhs = -gradient_;
      system_.known.setZero(3 * n);  // pinned vertices already sit at their targets
      system_.matrix.constrainVertices(system_.pinnedVertices, system_.known, system_.rhs);
    }
    step_.setZero(3 * n);
    // The right-hand side is a force (the gradient of Phi), which vanishes as Newton converges:
    // measure the linear residual against the external force instead of demanding ever more
    // relative accuracy.
    if (!system_.solve(system_.rhs, externalForceScale, step_, profile, stats)) break;

    // Backtracking line search on Phi (Armijo condition).
    const double slope = -system_.rhs.dot(step_);  // gradient . step over the free unknowns
    double alpha = 1.0;
    trial_.resize(n);
    bool accepted = false;
    for (int halving = 0; halving < 12; ++halving, alpha *= 0.5) {
      for (int i = 0; i < n; ++i) trial_[i] = x[i] + alpha * step_.segment<3>(3 * i);
      const double trialPhi = potential(cloth, trial_, in, profile);
      if (std::isfinite(trialPhi) && trialPhi <= phi + 1e-4 * alpha * slope) {
        accepted = true;
        break;
      }
    }
    if (!accepted) break;  // no decrease along the step: x is as good as this Newton step gets
    x.swap(trial_);
    lastChange = alpha * step_.cwiseAbs().maxCoeff() / h;
    if (iteration == 0) firstChange = lastChange;
    if (lastChange < tolerance_) {
      ++iteration;
      break;
    }
  }
  stats.newtonIterations += iteration;
  stats.lastNewtonResidual = lastChange;
  stats.lastNewtonFirstChange = firstChange;

  StageTimer timer(profile, "update");
  for (int i = 0; i < n; ++i) {
    mesh.v[i] = (x[i] - x0_[i]) / h;
    mesh.x[i] = x[i];
  }
  // The impulse each held vertex received from its obstacle (the obstacle takes its opposite).
  if (in.heldVertices != nullptr && heldWeights_.size() == in.heldVertices->size()) {
    for (std::size_t k = 0; k < in.heldVertices->size(); ++k) {
      HeldVertex& held = (*in.heldVertices)[k];
      held.reaction = heldWeights_[k] * (held.velocity - mesh.v[held.vertex]);
    }
  }
}

}  // namespace weft
