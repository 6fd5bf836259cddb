#include "tearing/stress_kernel.h"

#include <cmath>
#include <cstdlib>

namespace weft {

StressKernel::StressKernel(double length) : spacing_(length / std::sqrt(8.0 * (tapVariance() + 1.0 / 3.0))) {}

double StressKernel::along(double a, double b) const {
  const Hat ha = hat(a), hb = hat(b);
  const double wa[2] = {1.0 - ha.fraction, ha.fraction};
  const double wb[2] = {1.0 - hb.fraction, hb.fraction};
  double sum = 0.0;
  for (int p = 0; p < 2; ++p) {
    for (int q = 0; q < 2; ++q) {
      const long offset = (hb.node + q) - (ha.node + p);
      if (std::labs(offset) <= kTapReach) sum += wa[p] * kTaps[offset + kTapReach] * wb[q];
    }
  }
  return sum;
}

}  // namespace weft
