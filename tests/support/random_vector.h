#pragma once
// A reproducible vector of uniform entries in [-1, 1] (right-hand sides of solver tests).
#include <random>

#include <Eigen/Core>

namespace weft::test {

inline Eigen::VectorXd randomVector(Eigen::Index size, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd v(size);
  for (Eigen::Index k = 0; k < size; ++k) v[k] = uniform(random);
  return v;
}

}  // namespace weft::test
