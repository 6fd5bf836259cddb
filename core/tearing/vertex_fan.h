#pragma once
// The fan of a vertex: its triangles in counter-clockwise order around it in material space.
//
// The mesh stores no vertex-to-triangle map; a fan is walked through Triangle::edge and
// Edge::tri, so it costs only the fan's size once one triangle at the vertex is known. In the
// triangle with the vertex at corner k (counter-clockwise), the side v[k] -> v[k+1] is the fan's
// clockwise spoke and v[k+2] -> v[k] its counter-clockwise spoke; the next triangle
// counter-clockwise lies across the latter.
#include <vector>

#include "mesh/cloth_mesh.h"

namespace weft {

struct VertexFan {
  int vertex = kNone;
  std::vector<int> triangles;  // counter-clockwise around `vertex`; an open fan starts at a border spoke
  std::vector<int> corners;    // corner of `vertex` in each triangle (tris[triangles[i]].v[corners[i]] == vertex)
  bool closed = false;         // true when the last triangle is followed by the first (an interior vertex)
};

// Corner of `vertex` in `t`, or kNone.
int cornerOf(const Triangle& t, int vertex);

// The edge of triangle `t` (an index into mesh.edges) that joins a and b, or kNone.
int edgeJoining(const ClothMesh& mesh, int t, int a, int b);

// The other triangle of an edge, across from `t` (kNone on a border).
int triangleAcross(const Edge& edge, int t);

// Spokes of the fan's i-th triangle at the vertex: the clockwise and counter-clockwise side.
int clockwiseSpoke(const ClothMesh& mesh, const VertexFan& fan, int i);
int counterClockwiseSpoke(const ClothMesh& mesh, const VertexFan& fan, int i);

// Some triangle that uses `vertex`, or kNone. A scan of all triangles (the one step of a tear
// that is not local, since the mesh keeps no vertex-to-triangle map); callers that already know
// a triangle at the vertex should walk from it instead.
int findTriangleAt(const ClothMesh& mesh, int vertex);

// The fan of `vertex` that contains `startTriangle` (which must use the vertex). On a
// non-manifold vertex (a bow-tie) this is only the one fan through `startTriangle`.
VertexFan walkFan(const ClothMesh& mesh, int vertex, int startTriangle);

// Index into fan.triangles of the triangle that the ray from the vertex along `direction`
// (material space) enters, judged in each triangle's own rest coordinates; a ray along a spoke
// enters the first of its two triangles. kNone when the ray leaves the fan (it points out of a
// border vertex's fan, into the gap of an open fan).
int fanTriangleHitBy(const ClothMesh& mesh, const VertexFan& fan, const Vec2& direction);

}  // namespace weft
