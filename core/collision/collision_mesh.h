#pragma once
// The topology a triangle mesh needs for collision detection: its triangles, its undirected edges
// and which feature (vertex, edge) each triangle "owns". Cloths and obstacles both use it; it is
// rebuilt when a cloth's topology changes (a tear or a cut), never per step.
//
// Ownership: every vertex and every edge is owned by exactly one of its triangles (the lowest
// triangle id that uses it). Candidate generation emits a vertex-face or edge-edge pair only from
// the triangle pair whose triangles own the features, so each primitive pair appears once.
#include <array>
#include <vector>

namespace weft {

struct CollisionMesh {
  int vertexCount = 0;
  std::vector<std::array<int, 3>> triangles;      // vertex ids, counter-clockwise
  std::vector<std::array<int, 2>> edges;          // each undirected edge once, v[0] < v[1]
  std::vector<std::array<int, 3>> triangleEdges;  // edge ids of triangle t: (v0,v1), (v1,v2), (v2,v0)
  std::vector<int> vertexOwner;                   // triangle owning each vertex (-1: vertex in no triangle)
  std::vector<int> edgeOwner;                     // triangle owning each edge (-1: edge in no triangle)
  std::vector<std::vector<int>> trianglesAround;  // triangles using each vertex, ascending
  // Edits so far (editCollisionMesh counts them): with the counts above, what tells a structure
  // built on the mesh that it changed, without comparing every triangle.
  long long revision = 0;
};

// Vertex v is a corner of `triangle`.
inline bool isCorner(const std::array<int, 3>& triangle, int v) {
  return triangle[0] == v || triangle[1] == v || triangle[2] == v;
}
// Edges e and f (vertex pairs) share a vertex.
inline bool shareVertex(const std::array<int, 2>& e, const std::array<int, 2>& f) {
  return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1];
}

// Builds edges and ownership from the triangles. Deterministic: edges are numbered in order of
// first appearance while walking triangles in id order.
CollisionMesh makeCollisionMesh(int vertexCount, const std::vector<std::array<int, 3>>& triangles);

// A triangle as an edit sets it: its corners and the ids of its edges (corners[k], corners[k+1]).
struct TriangleEdit {
  int id = 0;
  std::array<int, 3> corners{};
  std::array<int, 3> edges{};
};
// An edge as an edit sets it (its ends in any order).
struct EdgeEdit {
  int id = 0;
  std::array<int, 2> ends{};
};

// What editCollisionMesh changed, for the structures built on the mesh (candidate_pairs.h).
struct CollisionMeshChange {
  int oldTriangleCount = 0;              // triangles before the edit (ids from here on are new)
  std::vector<int> changedTriangles;     // edited triangles, appended ones included (sorted)
  std::vector<int> regroupedTriangles;   // triangles that gained or lost an owned vertex or edge (sorted)
  std::vector<std::array<int, 3>> oldCorners;  // corners of each changed triangle before the edit (new: -1)
};

// Sets the given triangles and edges (ids past the end append; appended ids must all be edited)
// and grows the vertex count to `vertexCount`, then restores trianglesAround and the ownership
// rule for the touched vertices and edges only. Cost: the edit and the triangles around the
// touched vertices. Edits are applied in order; a later edit of the same id wins.
CollisionMeshChange editCollisionMesh(CollisionMesh& mesh, int vertexCount, const std::vector<TriangleEdit>& triangles,
                                      const std::vector<EdgeEdit>& edges);

}  // namespace weft
