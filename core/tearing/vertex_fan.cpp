#include "tearing/vertex_fan.h"

namespace weft {

int cornerOf(const Triangle& t, int vertex) {
  for (int k = 0; k < 3; ++k) {
    if (t.v[k] == vertex) return k;
  }
  return kNone;
}

int edgeJoining(const ClothMesh& mesh, int t, int a, int b) {
  const Triangle& tri = mesh.tris[t];
  for (int k = 0; k < 3; ++k) {
    const int from = tri.v[k];
    const int to = tri.v[(k + 1) % 3];
    if ((from == a && to == b) || (from == b && to == a)) return tri.edge[k];
  }
  return kNone;
}

int triangleAcross(const Edge& edge, int t) { return edge.tri[0] == t ? edge.tri[1] : edge.tri[0]; }

int clockwiseSpoke(const ClothMesh& mesh, const VertexFan& fan, int i) {
  return mesh.tris[fan.triangles[i]].edge[fan.corners[i]];
}

int counterClockwiseSpoke(const ClothMesh& mesh, const VertexFan& fan, int i) {
  return mesh.tris[fan.triangles[i]].edge[(fan.corners[i] + 2) % 3];
}

int findTriangleAt(const ClothMesh& mesh, int vertex) {
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    if (cornerOf(mesh.tris[t], vertex) != kNone) return t;
  }
  return kNone;
}

VertexFan walkFan(const ClothMesh& mesh, int vertex, int startTriangle) {
  VertexFan fan;
  fan.vertex = vertex;
  // Every step moves to a different triangle of the fan, so a fan has at most triangleCount()
  // of them; the bound only guards the walk against a corrupted mesh.
  const int maxSteps = mesh.triangleCount();

  // Clockwise to the first triangle: stop at a border spoke, or back at the start (closed fan).
  int first = startTriangle;
  for (int step = 0; step < maxSteps; ++step) {
    const Triangle& t = mesh.tris[first];
    const int previous = triangleAcross(mesh.edges[t.edge[cornerOf(t, vertex)]], first);
    if (previous == kNone) break;
    if (previous == startTriangle) {
      fan.closed = true;
      break;
    }
    first = previous;
  }

  // Counter-clockwise from there, collecting.
  int current = first;
  for (int step = 0; step < maxSteps && current != kNone; ++step) {
    const int corner = cornerOf(mesh.tris[current], vertex);
    fan.triangles.push_back(current);
    fan.corners.push_back(corner);
    const int next = triangleAcross(mesh.edges[mesh.tris[current].edge[(corner + 2) % 3]], current);
    if (next == first) break;
    current = next;
  }
  return fan;
}

int fanTriangleHitBy(const ClothMesh& mesh, const VertexFan& fan, const Vec2& direction) {
  for (size_t i = 0; i < fan.triangles.size(); ++i) {
    const Triangle& t = mesh.tris[fan.triangles[i]];
    const int k = fan.corners[i];
    const Vec2 toClockwise = t.rest[(k + 1) % 3] - t.rest[k];
    const Vec2 toCounterClockwise = t.rest[(k + 2) % 3] - t.rest[k];
    // A triangle's angle at a corner is below pi, so the two half-planes meet in exactly the
    // wedge between its spokes.
    if (cross2(toClockwise, direction) >= 0.0 && cross2(direction, toCounterClockwise) >= 0.0) {
      return static_cast<int>(i);
    }
  }
  return kNone;
}

}  // namespace weft
