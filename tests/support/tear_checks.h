#pragma once
// Measurements the tearing tests compare before and after a change.
#include <algorithm>
#include <numeric>
#include <vector>

#include "mesh/cloth_mesh.h"

namespace weft::test {

inline double totalMass(const ClothMesh& mesh) { return std::accumulate(mesh.mass.begin(), mesh.mass.end(), 0.0); }

inline Vec3 totalMomentum(const ClothMesh& mesh) {
  Vec3 p = Vec3::Zero();
  for (int i = 0; i < mesh.vertexCount(); ++i) p += mesh.mass[i] * mesh.v[i];
  return p;
}

// sum m |v|: the scale against which a momentum error is relative.
inline double momentumScale(const ClothMesh& mesh) {
  double s = 0.0;
  for (int i = 0; i < mesh.vertexCount(); ++i) s += mesh.mass[i] * mesh.v[i].norm();
  return s;
}

inline double totalRestArea(const ClothMesh& mesh) {
  double a = 0.0;
  for (const Triangle& t : mesh.tris) a += restArea(t);
  return a;
}

inline int boundaryEdgeCount(const ClothMesh& mesh) {
  return static_cast<int>(std::count_if(mesh.edges.begin(), mesh.edges.end(), [](const Edge& e) { return e.isBoundary(); }));
}

inline int tornEdgeCount(const ClothMesh& mesh) {
  return static_cast<int>(std::count_if(mesh.edges.begin(), mesh.edges.end(), [](const Edge& e) { return e.torn; }));
}

// Pieces of cloth: triangles connected through shared vertices.
inline int connectedComponents(const ClothMesh& mesh) {
  std::vector<int> parent(mesh.x.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const Triangle& t : mesh.tris) {
    parent[root(t.v[1])] = root(t.v[0]);
    parent[root(t.v[2])] = root(t.v[0]);
  }
  int count = 0;
  for (int i = 0; i < mesh.vertexCount(); ++i) count += root(i) == i;
  return count;
}

}  // namespace weft::test
