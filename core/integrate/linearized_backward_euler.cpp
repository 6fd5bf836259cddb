#include "integrate/linearized_backward_euler.h"

#include <algorithm>

#include "integrate/implicit_step.h"
#include "sim/cloth.h"
#include "sim/world.h"

namespace weft {

void LinearizedBackwardEuler::advance(Cloth& cloth, const StepInputs& in, StageProfile& profile, SolverStats& stats) {
  ClothMesh& mesh = cloth.mesh;
  const int n = mesh.vertexCount();
  // The step's form (implicit_step.h): backward Euler from the cloth's state unless BDF2 hands
  // one; then h is h^ = 2dt/3 and (x, v) the extrapolated base state (x^, v^), where the forces
  // are linearized as Baraff & Witkin linearize at x_n.
  const ImplicitStep* form = in.form;
  const double h = form != nullptr ? form->h : in.dt;
  const std::vector<Vec3>& baseX = form != nullptr ? form->x : mesh.x;
  const std::vector<Vec3>& baseV = form != nullptr ? form->v : mesh.v;
  system_.beginStep(cloth, in, profile);

  system_.matrix.setZero();
  ElasticOptions options;
  options.bending = in.bending;
  options.hessian = HessianMode::Definite;
  options.threads = in.threads;
  options.ahead = in.membraneAhead;  // HessianMode::Definite: as membraneModeAtStart says
  evaluateElasticForces(cloth, baseX, options, system_.elastic, system_.internalForce, &system_.matrix, profile);
  if (in.grab != nullptr) addGrabForce(*in.grab, baseX, system_.internalForce, profile);

  {
    StageTimer timer(profile, "assemble");
    // Eq. 2.47 with damping: [(1 + h c_m) M + (h^2 + h beta) H] v+ = M v + h (f_int(x) + f_ext),
    // where H = -K is the (definite) Hessian of the elastic energy, c_m the mass damping and beta
    // the stiffness (Rayleigh) damping, both taken implicitly. In a BDF2 form x, v and h are
    // x^, v^ and h^.
    SystemMatrix::Sparse& A = system_.matrix.matrix();
    A *= h * h + h * in.damping.stiffness;
    for (int i = 0; i < n; ++i) system_.matrix.addDiagonal(i, (1.0 + h * in.damping.mass) * mesh.mass[i]);
    // The grab spring's Jacobian, implicit like the elastic one (so a stiff grab stays stable)
    // but outside the stiffness damping: the spring is the user's hand, not the cloth.
    if (in.grab != nullptr) system_.matrix.addBlock(in.grab->vertex, in.grab->vertex, -(h * h) * grabForceJacobian(*in.grab));
    system_.rhs.resize(3 * n);
    const auto v = flat(baseV);
    const auto fInt = flat(system_.internalForce);
    const auto fExt = flat(system_.externalForce);
    for (int i = 0; i < n; ++i)
      system_.rhs.segment<3>(3 * i) = mesh.mass[i] * v.segment<3>(3 * i) + h * (fInt.segment<3>(3 * i) + fExt.segment<3>(3 * i));
    // Vertices resting on obstacles are held (integrator.h HeldVertex).
    if (in.heldVertices != nullptr) {
      for (HeldVertex& held : *in.heldVertices) {
        const Mat3 weight = holdWeight(held);
        system_.matrix.addBlock(held.vertex, held.vertex, weight);
        system_.rhs.segment<3>(3 * held.vertex) += weight * held.velocity;
      }
    }
    // Pinned vertices move at the velocity that takes them to their scripted target.
    system_.known.setZero(3 * n);
    for (size_t k = 0; k < system_.pinnedVertices.size(); ++k) {
      const int p = system_.pinnedVertices[k];
      system_.known.segment<3>(3 * p) = (system_.pinnedTargets[k] - baseX[p]) / h;
    }
    system_.matrix.constrainVertices(system_.pinnedVertices, system_.known, system_.rhs);
  }

  system_.solution = flat(baseV);  // warm start
  // The right-hand side is a momentum; near rest it shrinks towards 0, while the accuracy that
  // matters stays that of one step's external impulse.
  const double impulseScale = h * flat(system_.externalForce).norm();
  system_.solve(system_.rhs, impulseScale, system_.solution, profile, stats);

  StageTimer timer(profile, "update");
  reportReactions(in);
  flat(mesh.v) = system_.solution;
  for (int i = 0; i < n; ++i) mesh.x[i] = baseX[i] + h * mesh.v[i];
  for (size_t k = 0; k < system_.pinnedVertices.size(); ++k) mesh.x[system_.pinnedVertices[k]] = system_.pinnedTargets[k];
}

Mat3 LinearizedBackwardEuler::holdWeight(HeldVertex& held) const {
  // The balance is the velocity system itself (kg): its assembled diagonal.
  return weft::holdWeight(held, [&] { return system_.matrix.largestDiagonal(held.vertex); });
}

void LinearizedBackwardEuler::reportReactions(const StepInputs& in) {
  if (in.heldVertices == nullptr) return;
  for (HeldVertex& held : *in.heldVertices) {
    held.reaction = holdWeight(held) * (held.velocity - system_.solution.segment<3>(3 * held.vertex));
  }
}

}  // namespace weft
