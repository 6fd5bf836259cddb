#pragma once
// Meshes for the collision tests: a grid cloth and a closed sphere-like obstacle, as positions
// plus the collision topology.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "collision/collision_mesh.h"
#include "mesh/grid.h"

namespace weft::test {

struct PositionedMesh {
  std::vector<Vec3> x;
  CollisionMesh mesh;
};

// makeGrid's n x n cloth over [0, size]^2.
inline ClothMesh gridCloth(int n, double size) {
  GridSpec spec;
  spec.resolutionX = n;
  spec.resolutionY = n;
  spec.width = size;
  spec.height = size;
  return makeGrid(spec);
}

// makeGrid's n x n cloth over [0, size]^2 in the plane z = 0.
inline PositionedMesh gridMesh(int n, double size) {
  const ClothMesh cloth = gridCloth(n, size);
  std::vector<std::array<int, 3>> triangles;
  for (const Triangle& t : cloth.tris) triangles.push_back(t.v);
  return {cloth.x, makeCollisionMesh(cloth.vertexCount(), triangles)};
}

// An icosahedron whose faces are split into four `subdivisions` times, vertices pushed onto the
// sphere: 20 * 4^subdivisions outward-facing triangles (80, 320, 1280, ...).
inline PositionedMesh icosphere(int subdivisions, const Vec3& centre, double radius) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> x = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<int, 3>> triangles = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      x.push_back(0.5 * (x[a] + x[b]));
      midpoints.emplace(key, static_cast<int>(x.size()) - 1);
      return static_cast<int>(x.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : triangles) {
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({b, bc, ab});
      finer.push_back({c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    triangles = std::move(finer);
  }
  for (Vec3& p : x) p = centre + radius * p.normalized();
  const int vertexCount = static_cast<int>(x.size());
  return {std::move(x), makeCollisionMesh(vertexCount, triangles)};
}

}  // namespace weft::test
