#include "tearing/crack_relaxation.h"

#include <algorithm>
#include <unordered_map>

#include <Eigen/Cholesky>

#include "forces/membrane.h"
#include "sim/cloth.h"
#include "tearing/tensile_stress.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

// A vertex's Newton step is halved at most this often to lower its energy; else it stays.
constexpr int kMaxHalvings = 6;

struct Patch {
  std::vector<int> freeVertices;  // sorted
  std::vector<int> triangles;     // every triangle at a free vertex, sorted
};

// Vertices within `rings` edges of the crack ends, found through their fans (each vertex is
// reached through a triangle that holds it, so no vertex-to-triangle map is needed beyond the
// crack ends' own).
Patch patchAround(const ClothMesh& mesh, const std::vector<int>& crackEnds, int rings) {
  std::unordered_map<int, int> reachedThrough;  // vertex -> a triangle at it
  std::vector<int> frontier;
  for (int v : crackEnds) {
    const int t = findTriangleAt(mesh, v);
    if (t != kNone && reachedThrough.emplace(v, t).second) frontier.push_back(v);
  }
  std::vector<int> triangles;
  for (int ring = 0; ring <= rings && !frontier.empty(); ++ring) {
    std::vector<int> next;
    for (int v : frontier) {
      for (int t : walkFan(mesh, v, reachedThrough[v]).triangles) {
        triangles.push_back(t);
        if (ring == rings) continue;
        for (int w : mesh.tris[t].v) {
          if (reachedThrough.emplace(w, t).second) next.push_back(w);
        }
      }
    }
    frontier = std::move(next);
  }
  Patch patch;
  for (const auto& [v, t] : reachedThrough) patch.freeVertices.push_back(v);
  std::sort(patch.freeVertices.begin(), patch.freeVertices.end());
  std::sort(triangles.begin(), triangles.end());
  triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
  patch.triangles = std::move(triangles);
  return patch;
}

}  // namespace

std::vector<int> relaxAroundCrack(Cloth& cloth, const std::vector<int>& crackEnds,
                                  const CrackRelaxationSettings& settings, std::vector<Mat2>& ioStress) {
  ClothMesh& mesh = cloth.mesh;
  const Patch patch = patchAround(mesh, crackEnds, std::max(0, settings.rings));
  const PreparedElasticity law = prepareElasticity(cloth.material.elasticity);
  std::vector<Vec3> saved(patch.freeVertices.size());
  for (std::size_t i = 0; i < patch.freeVertices.size(); ++i) saved[i] = mesh.x[patch.freeVertices[i]];
  auto slotOf = [&](int v) {
    const auto it = std::lower_bound(patch.freeVertices.begin(), patch.freeVertices.end(), v);
    return it != patch.freeVertices.end() && *it == v ? static_cast<int>(it - patch.freeVertices.begin()) : kNone;
  };
  std::vector<std::array<int, 3>> slots(patch.triangles.size());
  for (std::size_t k = 0; k < patch.triangles.size(); ++k) {
    for (int c = 0; c < 3; ++c) slots[k][c] = slotOf(cloth.membranes[patch.triangles[k]].v[c]);
  }

  // Each free vertex's triangles, for its local energy.
  std::vector<std::vector<std::pair<int, int>>> trianglesOf(patch.freeVertices.size());  // (triangle, corner)
  for (std::size_t k = 0; k < patch.triangles.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      if (slots[k][c] != kNone) trianglesOf[slots[k][c]].emplace_back(patch.triangles[k], c);
    }
  }
  MembraneContribution contribution;
  auto localEnergy = [&](std::size_t i, Vec3* force, Mat3* block) {
    double energy = 0.0;
    if (force) force->setZero();
    if (block) block->setZero();
    for (const auto& [t, c] : trianglesOf[i]) {
      const MembraneElement& element = cloth.membranes[t];
      evaluateMembrane(element, law, mesh.x[element.v[0]], mesh.x[element.v[1]], mesh.x[element.v[2]],
                       block ? HessianMode::Definite : HessianMode::None, contribution);
      energy += contribution.energy;
      if (force) *force += contribution.force[c];
      if (block) *block += contribution.hessian(c, c);
    }
    return energy;
  };
  for (int sweep = 0; sweep < settings.sweeps; ++sweep) {
    for (std::size_t i = 0; i < patch.freeVertices.size(); ++i) {
      const int v = patch.freeVertices[i];
      if (mesh.pinned[v]) continue;
      Vec3 force;
      Mat3 block;
      const double before = localEnergy(i, &force, &block);
      const Eigen::LDLT<Mat3> solve(block);
      if (solve.info() != Eigen::Success || !(solve.vectorD().minCoeff() > 0.0)) continue;
      const Vec3 step = solve.solve(force);
      if (!step.allFinite()) continue;
      // Backtracking: the vertex's own energy must fall, so the sweep never diverges.
      const Vec3 start = mesh.x[v];
      double scale = 1.0;
      for (int halving = 0; halving < kMaxHalvings; ++halving, scale *= 0.5) {
        mesh.x[v] = start + scale * step;
        if (localEnergy(i, nullptr, nullptr) < before) break;
        mesh.x[v] = start;
      }
    }
  }

  tensileStresses(cloth, patch.triangles, ioStress);
  for (std::size_t i = 0; i < patch.freeVertices.size(); ++i) mesh.x[patch.freeVertices[i]] = saved[i];
  return patch.triangles;
}

}  // namespace weft
