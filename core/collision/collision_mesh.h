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
  std::vector<int> edgeOwner;                     // triangle owning each edge
};

// Builds edges and ownership from the triangles. Deterministic: edges are numbered in order of
// first appearance while walking triangles in id order.
CollisionMesh makeCollisionMesh(int vertexCount, const std::vector<std::array<int, 3>>& triangles);

}  // namespace weft
