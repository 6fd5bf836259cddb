#pragma once
// The kernel the tear stage averages stress with (nonlocal_stress.h).
//
// Separable: the weight between two material points is the product of one weight along x and one
// along y. Along an axis it is a lattice's hat (linear interpolation between nodes at spacing h),
// blurred by the taps kTaps and read back by the same hat. So it can be evaluated two ways that
// agree to rounding: pair by pair, and on the lattice (stress_lattice.h: splat every triangle's
// stress onto the nodes, blur, read back), whose cost per triangle does not grow with the
// averaging length as a neighbour list's does (at 64^2 a list was ~100 terms a triangle, 1 ms a
// step, half of the tear stage).
//
// Shape, for an averaging length r: the bell (1 - (d/r)^2)^2 over a disc of radius r, which the
// lists still use beside cracks (nonlocal_stress.h), has a second moment of r^2/8 along an axis
// and a height of 0.955 / r^2 at its centre (as a share of its integral). The taps 1 3 4 4 4 3 1
// have a variance of 2.5 h^2; with the two hats' h^2/6 each that is r^2/8 for h = 0.210 r, and
// the height at the centre is then 0.907 / r^2: a flat-topped kernel like the bell. Tried first
// and not kept: a binomial blur (1 4 6 4 1) of that second moment is a third higher at the centre,
// and a crack tip's singular stress averaged by it converged more slowly as the mesh was refined
// (+6.8% from 33^2 to 65^2 against the bell's +5.5% and these taps' +5.2%:
// nonlocal_stress_test.cpp); five taps (1 3 3 3 1, h = 0.279 r) had the bell's height but let the
// heavy ball of `balls-on-cloth-ceiling` stay in the sag when dropped 2 cm aside (tearing tests).
// Where a point falls between the nodes changes the kernel's second moment by up to h^2/4, 9% of
// it with these taps (16% with five), so the lists, which decide a crack tip's path, keep the bell.
// The weight is zero once x or y differ by 5h = 1.05 r.
#include <cmath>

#include "util/types.h"

namespace weft {

class StressKernel {
 public:
  explicit StressKernel(double length = 0.0);
  double spacing() const { return spacing_; }
  // The weight is zero when the points' x or y differ by this much or more.
  double reach() const { return (kTapReach + 2) * spacing_; }
  double weight(const Vec2& a, const Vec2& b) const { return along(a.x(), b.x()) * along(a.y(), b.y()); }
  // The weight along one axis between coordinates a and b.
  double along(double a, double b) const;

  // Where a coordinate falls on the lattice: the node at or below it and the fraction of the way
  // to the next (the hat's weights are 1 - fraction and fraction).
  struct Hat {
    long node = 0;
    double fraction = 0.0;
  };
  Hat hat(double coordinate) const {
    const double scaled = coordinate / spacing_;
    const double node = std::floor(scaled);
    return {static_cast<long>(node), scaled - node};
  }
  // Both axes' hats of a point.
  struct Place {
    Hat x, y;
  };
  Place place(const Vec2& point) const { return {hat(point.x()), hat(point.y())}; }
  // The blur: node i reads node i + k with kTaps[k + kTapReach].
  static constexpr int kTapReach = 3;
  static constexpr double kTaps[2 * kTapReach + 1] = {1.0, 3.0, 4.0, 4.0, 4.0, 3.0, 1.0};
  // The taps' variance in units of the spacing squared.
  static constexpr double tapVariance() {
    double sum = 0.0, moment = 0.0;
    for (int k = -kTapReach; k <= kTapReach; ++k) {
      sum += kTaps[k + kTapReach];
      moment += k * k * kTaps[k + kTapReach];
    }
    return moment / sum;
  }

 private:
  double spacing_ = 0.0;
};

}  // namespace weft
