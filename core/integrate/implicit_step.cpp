#include "integrate/implicit_step.h"

namespace weft {

void setBdf2Step(const std::vector<Vec3>& previousX, const std::vector<Vec3>& previousV, const std::vector<Vec3>& x,
                 const std::vector<Vec3>& v, double h, ImplicitStep& step) {
  // x+ = (4 x_n - x_{n-1})/3 + (2h/3) v+,  v+ = (4 v_n - v_{n-1})/3 + (2h/3) M^-1 f(x+, v+)
  // (implicit_step.h).
  const size_t n = x.size();
  step.h = 2.0 * h / 3.0;
  step.x.resize(n);
  step.v.resize(n);
  for (size_t i = 0; i < n; ++i) {
    step.x[i] = (4.0 * x[i] - previousX[i]) / 3.0;
    step.v[i] = (4.0 * v[i] - previousV[i]) / 3.0;
  }
}

}  // namespace weft
