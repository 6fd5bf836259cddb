#pragma once
// The implicit step both integrator families solve. Backward Euler and BDF2 are the same equations
//     M (v+ - v^) = h^ f(x+, v+),    x+ = x^ + h^ v+
// from a base state (x^, v^) with an effective step h^:
//   backward Euler   x^ = x_n,                   v^ = v_n,                   h^ = h
//   BDF2             x^ = (4 x_n - x_{n-1}) / 3,  v^ = (4 v_n - v_{n-1}) / 3,  h^ = 2h / 3
// (BDF2 for cloth: Choi & Ko 2002, their implicit step; the formula: Hairer & Wanner, Solving
// ODEs II, §III.1, BDF of order 2 on x' = v, v' = M^-1 f). So a BDF2 step is a backward Euler step
// of 2h/3 from the extrapolated state, and LinearizedBackwardEuler and NewtonIntegrator solve
// either form when StepInputs::form points at one.
//
// The linearized solve linearizes the forces at x^, as Baraff & Witkin do at x_n. Linearizing at
// the prediction x^ + h^ v^ instead (within O(h^2) of x+, so the definite, not exact, Hessian would
// cost no order) was tried: 8x less energy lost by the swinging test sheet at 1/60 s, but on the
// stiffest preset at 1/30 s the prediction overshoots and the sheet blew up (strain 3); at x^ it
// settles like backward Euler. The Newton variant starts from the prediction and iterates, so it
// has both.
#include <vector>

#include "util/types.h"

namespace weft {

struct ImplicitStep {
  double h = 0.0;          // h^: the effective step (s)
  std::vector<Vec3> x;     // x^ (m)
  std::vector<Vec3> v;     // v^ (m/s)
};

// The BDF2 form from the previous state (x_{n-1}, v_{n-1}) and the current one (x_n, v_n) for a
// step h (both steps of length h).
void setBdf2Step(const std::vector<Vec3>& previousX, const std::vector<Vec3>& previousV, const std::vector<Vec3>& x,
                 const std::vector<Vec3>& v, double h, ImplicitStep& step);

}  // namespace weft
