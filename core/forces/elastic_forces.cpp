#include "forces/elastic_forces.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "sim/cloth.h"

namespace weft {
namespace {

// The value offset of column 0 of every block (v_i, v_j) of one element.
template <int N>
std::array<int, N * N> blockStarts(const SystemMatrix& matrix, const std::array<int, N>& v) {
  std::array<int, N * N> starts;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      starts[i * N + j] = matrix.blockOffset(v[i], v[j], 0);
      // The pattern is made of whole 3x3 blocks, so the three columns of a vertex hold the same
      // rows and a block's columns sit one column length apart.
      assert(matrix.blockOffset(v[i], v[j], 2) - starts[i * N + j] ==
             2 * (matrix.matrix().outerIndexPtr()[3 * v[j] + 1] - matrix.matrix().outerIndexPtr()[3 * v[j]]));
    }
  }
  return starts;
}

// Takes the block offsets of every element from the matrix, unless they were taken from this
// matrix's current pattern already.
void updateBlockStarts(const Cloth& cloth, const SystemMatrix& matrix, ElasticWorkspace& workspace) {
  const long nonZeros = matrix.matrix().nonZeros();
  if (workspace.scatterMatrix == &matrix && workspace.scatterPatternVersion == matrix.patternVersion() &&
      workspace.scatterNonZeros == nonZeros && workspace.membraneBlockStart.size() == cloth.membranes.size() &&
      workspace.hingeBlockStart.size() == cloth.hinges.size())
    return;
  workspace.membraneBlockStart.resize(cloth.membranes.size());
  for (size_t t = 0; t < cloth.membranes.size(); ++t)
    workspace.membraneBlockStart[t] = blockStarts<3>(matrix, cloth.membranes[t].v);
  workspace.hingeBlockStart.resize(cloth.hinges.size());
  for (size_t h = 0; h < cloth.hinges.size(); ++h)
    workspace.hingeBlockStart[h] = blockStarts<4>(matrix, cloth.hinges[h].v);
  workspace.scatterMatrix = &matrix;
  workspace.scatterPatternVersion = matrix.patternVersion();
  workspace.scatterNonZeros = nonZeros;
}

// Adds m, or its transpose, to the 3x3 block whose column 0 starts at `at`, with `stride` values
// between its columns.
inline void addBlockAt(double* at, int stride, const Mat3& m) {
  for (int c = 0; c < 3; ++c) {
    double* column = at + c * stride;
    const double m0 = m(0, c), m1 = m(1, c), m2 = m(2, c);
    column[0] += m0;
    column[1] += m1;
    column[2] += m2;
  }
}

inline void addTransposedBlockAt(double* at, int stride, const Mat3& m) {
  for (int c = 0; c < 3; ++c) {
    double* column = at + c * stride;
    const double m0 = m(c, 0), m1 = m(c, 1), m2 = m(c, 2);
    column[0] += m0;
    column[1] += m1;
    column[2] += m2;
  }
}

// Adds an element's symmetric Hessian to the system matrix: block (i, j) at (v_i, v_j) and its
// transpose at (v_j, v_i).
template <int N>
void addElementHessian(const SymmetricBlocks<N>& blocks, const std::array<int, N>& v,
                       const std::array<int, N * N>& blockStart, SystemMatrix& matrix) {
  SystemMatrix::Sparse& sparse = matrix.matrix();
  const int* outer = sparse.outerIndexPtr();
  double* values = sparse.valuePtr();
  std::array<int, N> columnLength;  // of each vertex's three columns
  for (int i = 0; i < N; ++i) columnLength[i] = outer[3 * v[i] + 1] - outer[3 * v[i]];
  int k = 0;  // blocks are stored (i, j), i <= j, row by row
  for (int i = 0; i < N; ++i) {
    addBlockAt(values + blockStart[i * N + i], columnLength[i], blocks.upper[k++]);
    for (int j = i + 1; j < N; ++j, ++k) {
      addBlockAt(values + blockStart[i * N + j], columnLength[j], blocks.upper[k]);
      addTransposedBlockAt(values + blockStart[j * N + i], columnLength[i], blocks.upper[k]);
    }
  }
}

}  // namespace

double maxPrincipalStrain(const Eigen::Vector3d& e) {
  const double mean = 0.5 * (e[0] + e[1]);
  const double radius = std::sqrt(0.25 * (e[0] - e[1]) * (e[0] - e[1]) + 0.25 * e[2] * e[2]);
  return mean + radius;
}

ElasticSummary evaluateElasticForces(const Cloth& cloth, const std::vector<Vec3>& x, const ElasticOptions& options,
                                     ElasticWorkspace& workspace, std::vector<Vec3>& forces, SystemMatrix* hessian,
                                     StageProfile& profile) {
  ElasticSummary summary;
  forces.assign(x.size(), Vec3::Zero());
  const HessianMode mode = hessian ? options.hessian : HessianMode::None;
  if (mode != HessianMode::None) updateBlockStarts(cloth, *hessian, workspace);
  // With one thread each element is added as soon as it is evaluated (its result stays in cache);
  // with more, all are evaluated in parallel into per-element buffers first. Either way the sums
  // run in element order over the same numbers, so the result never depends on the thread count.
  const bool buffered = options.threads > 1;

  const int triangleCount = static_cast<int>(cloth.membranes.size());
  {
    StageTimer timer(profile, "membrane");
    const PreparedElasticity law = prepareElasticity(cloth.material.elasticity);
    const MembraneAhead* ahead =
        options.ahead != nullptr && options.ahead->serves(cloth.material.elasticity) && options.ahead->mode() == mode
            ? options.ahead
            : nullptr;
    // The element's contribution: the one evaluated ahead when it holds exactly this element at
    // these positions, else evaluated into `scratch`.
    auto contributionOf = [&](int t, MembraneContribution& scratch) -> const MembraneContribution& {
      const MembraneElement& element = cloth.membranes[t];
      const Vec3& xa = x[element.v[0]];
      const Vec3& xb = x[element.v[1]];
      const Vec3& xc = x[element.v[2]];
      if (ahead != nullptr) {
        if (const MembraneContribution* found = ahead->find(t, element, xa, xb, xc)) return *found;
      }
      evaluateMembrane(element, law, xa, xb, xc, mode, scratch);
      return scratch;
    };
    auto add = [&](int t, const MembraneContribution& r) {
      const MembraneElement& element = cloth.membranes[t];
      summary.membraneEnergy += r.energy;
      summary.maxPrincipalStrain = std::max(summary.maxPrincipalStrain, maxPrincipalStrain(r.strain));
      for (int i = 0; i < 3; ++i) forces[element.v[i]] += r.force[i];
      if (mode != HessianMode::None) addElementHessian<3>(r.hessian, element.v, workspace.membraneBlockStart[t], *hessian);
    };
    if (buffered) {
      // Evaluated in parallel into per-element buffers (or found in the cache), then added in order.
      workspace.membrane.resize(triangleCount);
      workspace.membraneTaken.resize(triangleCount);
#pragma omp parallel for num_threads(options.threads) schedule(static)
      for (int t = 0; t < triangleCount; ++t) workspace.membraneTaken[t] = &contributionOf(t, workspace.membrane[t]);
      for (int t = 0; t < triangleCount; ++t) add(t, *workspace.membraneTaken[t]);
    } else {
      MembraneContribution contribution;
      for (int t = 0; t < triangleCount; ++t) add(t, contributionOf(t, contribution));
    }
  }
  if (options.bending && !cloth.hinges.empty()) {
    StageTimer timer(profile, "bending");
    const int hingeCount = static_cast<int>(cloth.hinges.size());
    auto evaluate = [&](int h, HingeContribution& out) {
      const BendingHinge& hinge = cloth.hinges[h];
      evaluateHinge(hinge, cloth.material.bending, x[hinge.v[0]], x[hinge.v[1]], x[hinge.v[2]], x[hinge.v[3]], mode,
                    out);
    };
    auto add = [&](int h, const HingeContribution& r) {
      const BendingHinge& hinge = cloth.hinges[h];
      summary.bendingEnergy += r.energy;
      for (int i = 0; i < 4; ++i) forces[hinge.v[i]] += r.force[i];
      if (mode != HessianMode::None) addElementHessian<4>(r.hessian, hinge.v, workspace.hingeBlockStart[h], *hessian);
    };
    if (buffered) {
      workspace.bending.resize(hingeCount);
#pragma omp parallel for num_threads(options.threads) schedule(static)
      for (int h = 0; h < hingeCount; ++h) evaluate(h, workspace.bending[h]);
      for (int h = 0; h < hingeCount; ++h) add(h, workspace.bending[h]);
    } else {
      HingeContribution contribution;
      for (int h = 0; h < hingeCount; ++h) {
        evaluate(h, contribution);
        add(h, contribution);
      }
    }
  }
  return summary;
}

}  // namespace weft
