#pragma once
// A random closed or open fan of random tensile stresses and uneven sectors, for the tests of
// separation strength and its bounds.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "tearing/separation_strength.h"
#include "tearing/tensile_stress.h"

namespace weft::test {

inline StressFan randomFan(std::mt19937& rng, bool closed, double stressScale = 200.0) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double pi = std::numbers::pi;
  const int n = 3 + static_cast<int>(unit(rng) * 6);
  const double total = closed ? 2.0 * pi : pi * (0.3 + 1.5 * unit(rng));
  std::vector<double> weights(n);
  double sum = 0.0;
  for (double& w : weights) sum += (w = 0.2 + unit(rng));
  StressFan fan;
  fan.closed = closed;
  fan.openStart = 2.0 * pi * unit(rng);
  fan.openSpan = total;
  double angle = fan.openStart;
  for (int k = 0; k < n; ++k) {
    Mat2 a;
    a << unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5;
    fan.sectors.push_back(makeSector(angle, total * weights[k] / sum, tensilePart(stressScale * (a + a.transpose()))));
    angle += fan.sectors.back().span;
  }
  return fan;
}

}  // namespace weft::test
