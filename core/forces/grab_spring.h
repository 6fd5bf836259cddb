#pragma once
// The editor's grab: a zero-rest-length spring from one cloth vertex x to a target point p the user
// drags, with energy E = 1/2 k |x - p|^2. Its force -k (x - p) and constant Jacobian -k I (on the
// vertex's diagonal block only) go into the implicit solve like any elastic force, so a stiff grab
// stays stable at the step sizes the cloth uses.
#include <vector>

#include "sim/stage_profile.h"
#include "util/types.h"

namespace weft {

struct GrabSpring {
  int vertex = 0;                // cloth vertex id (ids are stable: tears only append)
  Vec3 target = Vec3::Zero();    // where the vertex is pulled to (m)
  double stiffness = 0.0;        // k (N/m)
};

double grabEnergy(const GrabSpring& spring, const Vec3& x);  // J
Vec3 grabForce(const GrabSpring& spring, const Vec3& x);     // -dE/dx (N)
Mat3 grabForceJacobian(const GrabSpring& spring);            // d(force)/dx = -k I (N/m)

// Adds the spring's force at positions x to forces[vertex]. Timed as the "grab" stage. The
// integrators add the Jacobian themselves, with the scaling of their own system (h^2 for
// linearized backward Euler, 1 for Newton's Hessian), and without stiffness damping: the spring is
// the user's hand, not part of the cloth.
void addGrabForce(const GrabSpring& spring, const std::vector<Vec3>& x, std::vector<Vec3>& forces,
                  StageProfile& profile);

}  // namespace weft
