#pragma once
// The cloth mesh: plain arrays of vertices, triangles and edges, built for topology change.
//
// Tears and cuts split vertices and triangles in place: a new vertex, triangle or edge is
// appended with the next free id, and the few neighbours that change are patched. Nothing is
// rebuilt from scratch, so ids are stable and handed out in a fixed order (determinism).
//
// Rest coordinates live per triangle corner, in material space (metres), so that a vertex split
// along a tear can keep distinct rest positions on each side of the seam.
#include <array>
#include <cstdint>
#include <vector>

#include "util/types.h"

namespace weft {

inline constexpr int kNone = -1;

struct Triangle {
  std::array<int, 3> v{kNone, kNone, kNone};  // vertex ids, counter-clockwise in material space
  std::array<Vec2, 3> rest;                    // material-space coordinates of each corner (m)
  std::array<int, 3> edge{kNone, kNone, kNone};  // edge[k] joins v[k] and v[(k+1)%3]
};

struct Edge {
  std::array<int, 2> v{kNone, kNone};    // endpoint vertex ids (v[0] < v[1] when built)
  std::array<int, 2> tri{kNone, kNone};  // one or two incident triangles; tri[1]==kNone on a border
  bool torn = false;                      // created by a tear (drawn red)
  bool cut = false;                       // created by a cut (drawn green)

  bool isBoundary() const { return tri[1] == kNone; }
};

struct ClothMesh {
  // Vertices, structure of arrays.
  std::vector<Vec3> x;          // world position (m)
  std::vector<Vec3> v;          // velocity (m/s)
  std::vector<double> mass;     // lumped mass (kg)
  std::vector<std::uint8_t> pinned;  // 1 when the vertex follows a pin script instead of dynamics

  std::vector<Triangle> tris;
  std::vector<Edge> edges;

  int vertexCount() const { return static_cast<int>(x.size()); }
  int triangleCount() const { return static_cast<int>(tris.size()); }
  int edgeCount() const { return static_cast<int>(edges.size()); }

  // Appends a vertex at rest (zero velocity, zero mass, not pinned); returns its id.
  int addVertex(const Vec3& position);
};

// Signed area of a triangle's rest shape in material space (m^2); positive when counter-clockwise.
double restArea(const Triangle& t);

// Smallest interior angle (rad) of the triangle with corners a, b, c; 0 for a degenerate one.
double smallestAngle(const Vec2& a, const Vec2& b, const Vec2& c);
// Smallest interior angle (rad) of a triangle's rest shape.
double smallestRestAngle(const Triangle& t);

// Builds `edges` and every Triangle::edge from the triangles' vertex ids. Used once when a mesh is
// created; topology changes patch edges locally instead.
void buildEdges(ClothMesh& mesh);

// Sets each vertex's lumped mass to a third of the rest area of every incident triangle times
// the area density (kg/m^2).
void assignLumpedMasses(ClothMesh& mesh, double areaDensity);

// Ids of the triangles around each vertex (computed on demand; not stored in the mesh).
std::vector<std::vector<int>> vertexTriangles(const ClothMesh& mesh);

}  // namespace weft
