#pragma once
// Internal (elastic) forces of a cloth: the membrane of every triangle and the bending of every
// hinge, with their energy and Hessian. One thread adds each element as it evaluates it, in element
// order; several split the vertices into ranges, each evaluating the elements that touch its range
// and adding what falls in it, so every sum still runs in element order over the same numbers and
// the result never depends on the thread count.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "forces/bending.h"
#include "forces/membrane.h"
#include "forces/membrane_ahead.h"
#include "integrate/system_matrix.h"
#include "sim/stage_profile.h"

namespace weft {

struct Cloth;

struct ElasticOptions {
  bool bending = true;                     // evaluate bending hinges
  HessianMode hessian = HessianMode::None; // None: energy and forces only
  int threads = 1;
  // The membrane contributions evaluated at the end of the last step (membrane_ahead.h): each
  // triangle it holds at exactly these positions is taken from it instead of evaluated. Null: none.
  const MembraneAhead* ahead = nullptr;
};

struct ElasticSummary {
  double membraneEnergy = 0.0;  // J
  double bendingEnergy = 0.0;   // J
  double maxPrincipalStrain = 0.0;
};

// Scratch space reused across steps (no allocation once sized).
struct ElasticWorkspace {
  // With several threads: per vertex range (one per thread), the elements with a vertex in it,
  // each range's forces and Hessian columns added by one thread (elastic_forces.cpp, addOwnedPart);
  // and per element its energy and largest principal strain, summed in element order afterwards.
  std::vector<std::vector<int>> elementsOfPart;
  std::vector<double> energy;
  std::vector<double> strain;

  // Where each element's 3x3 Hessian blocks sit among the system matrix's values: entry i*N + j
  // is the offset of column 0 of block (v_i, v_j); the block's other columns follow at the length
  // of vertex v_j's columns. Looked up once per matrix pattern rather than by search per block.
  std::vector<std::array<int, 9>> membraneBlockStart;
  std::vector<std::array<int, 16>> hingeBlockStart;
  const SystemMatrix* scatterMatrix = nullptr;  // the matrix and pattern the offsets were taken from
  int scatterPatternVersion = -1;
  long scatterNonZeros = -1;
};

// Sets `forces` to the elastic forces at positions x (size n). When options.hessian != None,
// also adds the Hessian of the elastic energy into `hessian` (which the caller zeroed or filled).
ElasticSummary evaluateElasticForces(const Cloth& cloth, const std::vector<Vec3>& x, const ElasticOptions& options,
                                     ElasticWorkspace& workspace, std::vector<Vec3>& forces, SystemMatrix* hessian,
                                     StageProfile& profile);

// Largest principal value of the Green strain G = [[e_uu, g/2], [g/2, e_vv]].
double maxPrincipalStrain(const Eigen::Vector3d& strain);

}  // namespace weft
