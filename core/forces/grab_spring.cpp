#include "forces/grab_spring.h"

namespace weft {

double grabEnergy(const GrabSpring& spring, const Vec3& x) {
  return 0.5 * spring.stiffness * (x - spring.target).squaredNorm();
}

Vec3 grabForce(const GrabSpring& spring, const Vec3& x) { return -spring.stiffness * (x - spring.target); }

Mat3 grabForceJacobian(const GrabSpring& spring) { return -spring.stiffness * Mat3::Identity(); }

void addGrabForce(const GrabSpring& spring, const std::vector<Vec3>& x, std::vector<Vec3>& forces,
                  StageProfile& profile) {
  StageTimer timer(profile, "grab");
  forces[spring.vertex] += grabForce(spring, x[spring.vertex]);
}

}  // namespace weft
