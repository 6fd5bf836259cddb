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

// Adds the part of an element's forces and Hessian that falls to vertices [first, end): the forces
// of those vertices and the blocks stored in their columns (block (v_i, v_j) lives in v_j's columns).
// Every value of the matrix and every force belongs to exactly one such range, so parts running
// side by side never write the same number, and each number still receives the elements in element
// order: the sums are bit for bit those of one thread adding every element.
template <int N>
void addOwnedPart(const std::array<Vec3, N>& force, const SymmetricBlocks<N>* blocks, const std::array<int, N>& v,
                  const std::array<int, N * N>& blockStart, int first, int end, std::vector<Vec3>& forces,
                  SystemMatrix* matrix) {
  auto owns = [&](int vertex) { return vertex >= first && vertex < end; };
  for (int i = 0; i < N; ++i) {
    if (owns(v[i])) forces[v[i]] += force[i];
  }
  if (blocks == nullptr) return;
  SystemMatrix::Sparse& sparse = matrix->matrix();
  const int* outer = sparse.outerIndexPtr();
  double* values = sparse.valuePtr();
  int k = 0;
  for (int i = 0; i < N; ++i) {
    const int lengthI = outer[3 * v[i] + 1] - outer[3 * v[i]];
    if (owns(v[i])) addBlockAt(values + blockStart[i * N + i], lengthI, blocks->upper[k]);
    ++k;
    for (int j = i + 1; j < N; ++j, ++k) {
      if (owns(v[j])) addBlockAt(values + blockStart[i * N + j], outer[3 * v[j] + 1] - outer[3 * v[j]], blocks->upper[k]);
      if (owns(v[i])) addTransposedBlockAt(values + blockStart[j * N + i], lengthI, blocks->upper[k]);
    }
  }
}

// Per part, the elements with a vertex in its range, in element order.
template <typename Element>
void elementsByPart(const std::vector<Element>& elements, int vertexCount, int parts,
                    std::vector<std::vector<int>>& out) {
  out.resize(parts);
  for (std::vector<int>& list : out) list.clear();
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    std::array<int, 4> seen{};
    int count = 0;
    for (int vertex : elements[e].v) {
      const int part = static_cast<int>(static_cast<long>(vertex) * parts / std::max(vertexCount, 1));
      if (std::find(seen.begin(), seen.begin() + count, part) != seen.begin() + count) continue;
      seen[count++] = part;
      out[part].push_back(e);
    }
  }
}

inline int partStart(int part, int parts, int vertexCount) {
  // The first vertex whose part (vertex * parts / vertexCount, as elementsByPart reads it) is `part`.
  return static_cast<int>((static_cast<long>(part) * vertexCount + parts - 1) / parts);
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
  // with more, each thread evaluates the elements touching its range of vertices and adds what
  // falls in it (addOwnedPart). Either way the sums run in element order over the same numbers, so
  // the result never depends on the thread count.
  const bool byParts = options.threads > 1;
  const int vertexCount = static_cast<int>(x.size());
  const int parts = std::clamp(options.threads, 1, std::max(1, vertexCount));

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
    if (byParts) {
      // Each thread evaluates the triangles touching its vertex range and adds what falls in the
      // range (addOwnedPart says why the sums are those of one thread); a triangle across two ranges
      // is evaluated by both, the same arithmetic on the same numbers. The energies and strains are
      // summed afterwards in triangle order.
      elementsByPart(cloth.membranes, vertexCount, parts, workspace.elementsOfPart);
      workspace.energy.resize(triangleCount);
      workspace.strain.resize(triangleCount);
#pragma omp parallel for num_threads(parts) schedule(static, 1)
      for (int part = 0; part < parts; ++part) {
        const int first = partStart(part, parts, vertexCount), end = partStart(part + 1, parts, vertexCount);
        MembraneContribution scratch;
        for (int t : workspace.elementsOfPart[part]) {
          const MembraneContribution& r = contributionOf(t, scratch);
          const std::array<int, 3>& v = cloth.membranes[t].v;
          if (const int lowest = std::min({v[0], v[1], v[2]}); lowest >= first && lowest < end) {
            workspace.energy[t] = r.energy;
            workspace.strain[t] = maxPrincipalStrain(r.strain);
          }
          addOwnedPart<3>(r.force, mode != HessianMode::None ? &r.hessian : nullptr, v,
                          mode != HessianMode::None ? workspace.membraneBlockStart[t] : std::array<int, 9>{}, first, end,
                          forces, hessian);
        }
      }
      for (int t = 0; t < triangleCount; ++t) {
        summary.membraneEnergy += workspace.energy[t];
        summary.maxPrincipalStrain = std::max(summary.maxPrincipalStrain, workspace.strain[t]);
      }
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
    if (byParts) {
      // As the membrane's: each thread its vertex range, the energies summed in hinge order.
      elementsByPart(cloth.hinges, vertexCount, parts, workspace.elementsOfPart);
      workspace.energy.resize(hingeCount);
#pragma omp parallel for num_threads(parts) schedule(static, 1)
      for (int part = 0; part < parts; ++part) {
        const int first = partStart(part, parts, vertexCount), end = partStart(part + 1, parts, vertexCount);
        HingeContribution r;
        for (int h : workspace.elementsOfPart[part]) {
          evaluate(h, r);
          const std::array<int, 4>& v = cloth.hinges[h].v;
          if (const int lowest = std::min({v[0], v[1], v[2], v[3]}); lowest >= first && lowest < end) {
            workspace.energy[h] = r.energy;
          }
          addOwnedPart<4>(r.force, mode != HessianMode::None ? &r.hessian : nullptr, v,
                          mode != HessianMode::None ? workspace.hingeBlockStart[h] : std::array<int, 16>{}, first, end,
                          forces, hessian);
        }
      }
      for (int h = 0; h < hingeCount; ++h) summary.bendingEnergy += workspace.energy[h];
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
