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
  mesh.trianglesAround.assign(vertexCount, {});

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
      mesh.trianglesAround[v[k]].push_back(t);
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

namespace {

void sortUnique(std::vector<int>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

void removeTriangle(std::vector<int>& around, int t) {
  const auto found = std::lower_bound(around.begin(), around.end(), t);
  if (found != around.end() && *found == t) around.erase(found);
}

void insertTriangle(std::vector<int>& around, int t) {
  const auto slot = std::lower_bound(around.begin(), around.end(), t);
  if (slot == around.end() || *slot != t) around.insert(slot, t);
}

// The lowest triangle using edge e: one around its first end (the lists are ascending).
int lowestUser(const CollisionMesh& mesh, int e) {
  for (int t : mesh.trianglesAround[mesh.edges[e][0]]) {
    const std::array<int, 3>& edges = mesh.triangleEdges[t];
    if (edges[0] == e || edges[1] == e || edges[2] == e) return t;
  }
  return -1;
}

// Sets an owner, recording both the triangle that lost the feature and the one that gained it.
void setOwner(int& owner, int lowest, std::vector<int>& regrouped) {
  if (owner == lowest) return;
  if (owner >= 0) regrouped.push_back(owner);
  if (lowest >= 0) regrouped.push_back(lowest);
  owner = lowest;
}

}  // namespace

CollisionMeshChange editCollisionMesh(CollisionMesh& mesh, int vertexCount, const std::vector<TriangleEdit>& triangles,
                                      const std::vector<EdgeEdit>& edges) {
  ++mesh.revision;
  assert(vertexCount >= mesh.vertexCount && "vertices are never removed");
  CollisionMeshChange change;
  change.oldTriangleCount = static_cast<int>(mesh.triangles.size());
  mesh.vertexCount = vertexCount;
  mesh.vertexOwner.resize(vertexCount, -1);
  mesh.trianglesAround.resize(vertexCount);

  std::vector<int> touchedEdges;
  for (const EdgeEdit& edit : edges) {
    if (edit.id >= static_cast<int>(mesh.edges.size())) {
      mesh.edges.resize(edit.id + 1, {-1, -1});
      mesh.edgeOwner.resize(edit.id + 1, -1);
    }
    mesh.edges[edit.id] = {std::min(edit.ends[0], edit.ends[1]), std::max(edit.ends[0], edit.ends[1])};
    touchedEdges.push_back(edit.id);
  }

  std::vector<int> touchedVertices;
  for (const TriangleEdit& edit : triangles) {
    const int t = edit.id;
    std::array<int, 3> old{-1, -1, -1};
    if (t >= static_cast<int>(mesh.triangles.size())) {
      mesh.triangles.resize(t + 1, {-1, -1, -1});
      mesh.triangleEdges.resize(t + 1, {-1, -1, -1});
    } else {
      old = mesh.triangles[t];
      for (int e : mesh.triangleEdges[t]) touchedEdges.push_back(e);
    }
    if (t < change.oldTriangleCount) {
      change.changedTriangles.push_back(t);
      change.oldCorners.push_back(old);
    }
    for (int v : old) {
      if (v >= 0) removeTriangle(mesh.trianglesAround[v], t);
    }
    mesh.triangles[t] = edit.corners;
    mesh.triangleEdges[t] = edit.edges;
    for (int v : edit.corners) {
      assert(v >= 0 && v < vertexCount && "triangle corner out of range");
      insertTriangle(mesh.trianglesAround[v], t);
      touchedVertices.push_back(v);
    }
    for (int v : old) {
      if (v >= 0) touchedVertices.push_back(v);
    }
    for (int e : edit.edges) touchedEdges.push_back(e);
  }
  // Appended triangles are all edited (and so are listed after the changed ones, in id order).
  for (int t = change.oldTriangleCount; t < static_cast<int>(mesh.triangles.size()); ++t) {
    assert(mesh.triangles[t][0] >= 0 && "an appended triangle was not edited");
    change.changedTriangles.push_back(t);
    change.oldCorners.push_back({-1, -1, -1});
  }
  // Keep oldCorners parallel to the sorted changedTriangles (a repeated id keeps its first old corners).
  {
    std::vector<int> order(change.changedTriangles.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return change.changedTriangles[a] < change.changedTriangles[b]; });
    std::vector<int> ids;
    std::vector<std::array<int, 3>> corners;
    for (int k : order) {
      if (!ids.empty() && ids.back() == change.changedTriangles[k]) continue;
      ids.push_back(change.changedTriangles[k]);
      corners.push_back(change.oldCorners[k]);
    }
    change.changedTriangles = std::move(ids);
    change.oldCorners = std::move(corners);
  }

  sortUnique(touchedVertices);
  sortUnique(touchedEdges);
  for (int v : touchedVertices) {
    const std::vector<int>& around = mesh.trianglesAround[v];
    setOwner(mesh.vertexOwner[v], around.empty() ? -1 : around.front(), change.regroupedTriangles);
  }
  for (int e : touchedEdges) {
    assert(e >= 0 && e < static_cast<int>(mesh.edges.size()) && mesh.edges[e][0] >= 0 && "edge id not edited");
    setOwner(mesh.edgeOwner[e], lowestUser(mesh, e), change.regroupedTriangles);
  }
  sortUnique(change.regroupedTriangles);
  return change;
}

}  // namespace weft
