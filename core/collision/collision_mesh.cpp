#include "collision/collision_mesh.h"

#include <algorithm>
#include <cassert>
#include <utility>

namespace weft {

CollisionMesh makeCollisionMesh(int vertexCount, const std::vector<std::array<int, 3>>& triangles) {
  CollisionMesh mesh;
  mesh.vertexCount = vertexCount;
  mesh.triangles = triangles;
  mesh.triangleEdges.resize(triangles.size());
  mesh.vertexOwner.assign(vertexCount, -1);

  // The edges met so far at each vertex, as (other endpoint, edge id), kept at the lower endpoint.
  // A vertex has a handful of edges, so a linear scan beats a hash map and keeps the numbering
  // trivially deterministic.
  std::vector<std::vector<std::pair<int, int>>> edgesAtVertex(vertexCount);
  const int triangleCount = static_cast<int>(triangles.size());
  for (int t = 0; t < triangleCount; ++t) {
    const std::array<int, 3>& v = triangles[t];
    for (int k = 0; k < 3; ++k) {
      assert(v[k] >= 0 && v[k] < vertexCount && "triangle corner out of range");
      // Walking triangles in id order, the first triangle to use a vertex has the lowest id.
      if (mesh.vertexOwner[v[k]] < 0) mesh.vertexOwner[v[k]] = t;
    }
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(v[k], v[(k + 1) % 3]);
      const int b = std::max(v[k], v[(k + 1) % 3]);
      assert(a != b && "triangle with a repeated corner");
      int id = -1;
      for (const auto& [other, edge] : edgesAtVertex[a]) {
        if (other == b) {
          id = edge;
          break;
        }
      }
      if (id < 0) {
        id = static_cast<int>(mesh.edges.size());
        mesh.edges.push_back({a, b});
        mesh.edgeOwner.push_back(t);  // first appearance = lowest triangle id
        edgesAtVertex[a].emplace_back(b, id);
      }
      mesh.triangleEdges[t][k] = id;
    }
  }
  return mesh;
}

}  // namespace weft
