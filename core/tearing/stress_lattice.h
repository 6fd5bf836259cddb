#pragma once
// The averaged stress computed on a lattice (stress_kernel.h): every source triangle's stress,
// times its weight, spread onto the four lattice nodes around its centroid by the kernel's hat
// (splat), blurred along x then along y by the kernel's taps, and read back at a point by the same
// hat. The reading equals the sum over the sources of kernel weight times stress (to rounding),
// at a cost per source and per node that does not depend on the kernel's reach.
#include <array>
#include <cstddef>
#include <vector>

#include "tearing/stress_kernel.h"
#include "util/types.h"

namespace weft {

class StressLattice {
 public:
  // Emptied, and sized to take sources and readings at the kernel's places (StressKernel::place)
  // whose nodes lie within [lowI, highI] x [lowJ, highJ]. Returns false, leaving the lattice
  // unusable, when that needs more than `maxNodes` nodes. `hotReach` (in nodes): how far a
  // reading's hotNear looks.
  bool reset(long lowI, long highI, long lowJ, long highJ, std::size_t maxNodes, int hotReach);
  // A source at `at` (within the reset's range): `weight` (its area) times `stress`, and whether it
  // is hot (counted, so a reading tells whether any hot source lies within the kernel's reach).
  void splat(const StressKernel::Place& at, double weight, const Mat2& stress, bool hot);
  // After the splats, before the readings: `threads` rows at a time (the result does not depend
  // on it).
  void blur(int threads);
  struct Reading {
    Mat2 weightedStress = Mat2::Zero();  // sum of kernel weight times source weight times stress
    double weight = 0.0;                 // sum of kernel weight times source weight
    bool hot = false;                    // some hot source has a positive kernel weight here
    // Some hot source may lie within `hotReach` along both axes (never false when one does).
    bool hotNear = false;
  };
  Reading read(const StressKernel::Place& at) const;

 private:
  enum Channel { kXX, kYY, kXY, kWeight, kChannels };
  using Node = std::array<double, kChannels>;
  std::size_t index(long i, long j) const {
    return static_cast<std::size_t>(i - lowI_) + static_cast<std::size_t>(j - lowJ_) * static_cast<std::size_t>(countI_);
  }
  int hotReach_ = 0;
  long lowI_ = 0, lowJ_ = 0, countI_ = 0, countJ_ = 0;
  std::vector<Node> nodes_;  // the splatted sources, then (blur) their blurred sums
  // Whether a hot source weighs anything at a point needs only which nodes its hat reaches (with
  // a positive weight) and which the taps join, all positive: counted in integers, the hot
  // sources per node, then summed over the taps' reach (hot) and over hotReach_ (hotNear), not
  // carried through the blur as two more channels of doubles (a third of its work).
  std::vector<int> hotSources_, hot_, hotNear_, countScratch_;
  // `counts` summed over the nodes within `reach` along both axes, into `out`.
  void boxSum(const std::vector<int>& counts, long reach, std::vector<int>& out);
};

}  // namespace weft
