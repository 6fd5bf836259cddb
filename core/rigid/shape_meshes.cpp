#include "rigid/shape_meshes.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <utility>

#include <Eigen/Geometry>

namespace weft {

namespace {

// ---- sphere ----------------------------------------------------------------------------------

// The 12 vertices of an icosahedron are the cyclic permutations of (0, ±1, ±phi); its 20 faces are
// the triples of mutually adjacent vertices (edge length 2). Finding them by adjacency avoids a
// hand-typed face table; each is then turned to face outward.
TriangleMesh unitIcosahedron() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh mesh;
  for (const double a : {-1.0, 1.0}) {
    for (const double b : {-phi, phi}) {
      mesh.vertices.emplace_back(0.0, a, b);
      mesh.vertices.emplace_back(a, b, 0.0);
      mesh.vertices.emplace_back(b, 0.0, a);
    }
  }
  auto adjacent = [&](int i, int j) { return std::abs((mesh.vertices[i] - mesh.vertices[j]).norm() - 2.0) < 1e-9; };
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j)
      for (int k = j + 1; k < 12; ++k) {
        if (!adjacent(i, j) || !adjacent(j, k) || !adjacent(i, k)) continue;
        const Vec3& a = mesh.vertices[i];
        const Vec3 normal = (mesh.vertices[j] - a).cross(mesh.vertices[k] - a);
        mesh.triangles.push_back(normal.dot(a) > 0.0 ? std::array<int, 3>{i, j, k} : std::array<int, 3>{i, k, j});
      }
  for (Vec3& v : mesh.vertices) v.normalize();
  return mesh;
}

// Splits every triangle into four; edge midpoints are shared through `midpointOf` so the surface
// stays closed, and are numbered in order of first use (deterministic).
void subdivideOnUnitSphere(TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> midpointOf;
  auto midpoint = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, isNew] = midpointOf.try_emplace(key, static_cast<int>(mesh.vertices.size()));
    if (isNew) mesh.vertices.push_back((mesh.vertices[a] + mesh.vertices[b]).normalized());
    return it->second;
  };
  std::vector<std::array<int, 3>> finer;
  finer.reserve(4 * mesh.triangles.size());
  for (const std::array<int, 3>& t : mesh.triangles) {
    const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    finer.push_back({t[0], ab, ca});
    finer.push_back({ab, t[1], bc});
    finer.push_back({ca, bc, t[2]});
    finer.push_back({ab, bc, ca});
  }
  mesh.triangles = std::move(finer);
}

// ---- surfaces of revolution about y ----------------------------------------------------------

// Appends a ring of `segments` vertices of radius `r` at height `y`. Angles grow from +x towards
// +z; the stitching below relies on that direction for outward orientation.
int addRing(TriangleMesh& mesh, double r, double y, int segments) {
  const int first = static_cast<int>(mesh.vertices.size());
  for (int i = 0; i < segments; ++i) {
    const double angle = 2.0 * kPi * i / segments;
    mesh.vertices.emplace_back(r * std::cos(angle), y, r * std::sin(angle));
  }
  return first;
}

// Joins a ring to the ring above it with two triangles per segment, facing outward.
void stitchRings(TriangleMesh& mesh, int lower, int upper, int segments) {
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    mesh.triangles.push_back({lower + i, upper + i, lower + j});
    mesh.triangles.push_back({lower + j, upper + i, upper + j});
  }
}

// A fan from `centre` to a ring: facing -y closes the bottom of a shape, +y its top.
void fanToRing(TriangleMesh& mesh, int centre, int ring, int segments, bool facingUp) {
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    mesh.triangles.push_back(facingUp ? std::array<int, 3>{centre, ring + j, ring + i}
                                      : std::array<int, 3>{centre, ring + i, ring + j});
  }
}

int addVertex(TriangleMesh& mesh, const Vec3& position) {
  mesh.vertices.push_back(position);
  return static_cast<int>(mesh.vertices.size()) - 1;
}

}  // namespace

TriangleMesh makeSphereMesh(const SphereShape& shape) {
  assert(shape.radius > 0.0 && shape.subdivisions >= 0);
  TriangleMesh mesh = unitIcosahedron();
  for (int s = 0; s < shape.subdivisions; ++s) subdivideOnUnitSphere(mesh);
  for (Vec3& v : mesh.vertices) v *= shape.radius;
  return mesh;
}

TriangleMesh makeBoxMesh(const BoxShape& shape) {
  assert((shape.halfExtents.array() > 0.0).all() && shape.maxCellSize >= 0.0);
  // Cells per axis, and the lattice of (cells + 1)^3 points whose surface points become vertices.
  std::array<int, 3> cells{1, 1, 1};
  if (shape.maxCellSize > 0.0) {
    for (int a = 0; a < 3; ++a)
      cells[a] = std::max(1, static_cast<int>(std::ceil(2.0 * shape.halfExtents[a] / shape.maxCellSize - 1e-9)));
  }
  TriangleMesh mesh;
  std::vector<int> vertexOf(static_cast<size_t>(cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1), -1);
  auto vertex = [&](const std::array<int, 3>& lattice) {
    int& id = vertexOf[(static_cast<size_t>(lattice[0]) * (cells[1] + 1) + lattice[1]) * (cells[2] + 1) + lattice[2]];
    if (id < 0) {
      id = static_cast<int>(mesh.vertices.size());
      Vec3 p;
      for (int a = 0; a < 3; ++a) p[a] = shape.halfExtents[a] * (2.0 * lattice[a] / cells[a] - 1.0);
      mesh.vertices.push_back(p);
    }
    return id;
  };
  // Face normal along axis a; (u, v) = (a+1, a+2) mod 3 satisfies u x v = +a, so cells walked
  // counter-clockwise in (u, v) face +a and are reversed on the -a side.
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (const int side : {0, cells[a]}) {
      for (int i = 0; i < cells[u]; ++i) {
        for (int j = 0; j < cells[v]; ++j) {
          std::array<int, 4> corner;
          const int steps[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
          for (int c = 0; c < 4; ++c) {
            std::array<int, 3> lattice;
            lattice[a] = side;
            lattice[u] = i + steps[c][0];
            lattice[v] = j + steps[c][1];
            corner[c] = vertex(lattice);
          }
          if (side == 0) std::swap(corner[1], corner[3]);
          mesh.triangles.push_back({corner[0], corner[1], corner[2]});
          mesh.triangles.push_back({corner[0], corner[2], corner[3]});
        }
      }
    }
  }
  return mesh;
}

TriangleMesh makeCapsuleMesh(const CapsuleShape& shape) {
  assert(shape.radius > 0.0 && shape.halfLength >= 0.0 && shape.segments >= 3);
  const int latitudeRings = std::max(1, shape.segments / 4);  // per hemisphere, the equator included
  TriangleMesh mesh;
  const int bottomPole = addVertex(mesh, Vec3(0.0, -shape.halfLength - shape.radius, 0.0));
  std::vector<int> rings;
  // Bottom hemisphere up to its equator at y = -halfLength, then the top one from its equator at
  // +halfLength (skipped when it coincides with the bottom one).
  for (int j = 1; j <= latitudeRings; ++j) {
    const double latitude = -0.5 * kPi + 0.5 * kPi * j / latitudeRings;
    rings.push_back(addRing(mesh, shape.radius * std::cos(latitude),
                            -shape.halfLength + shape.radius * std::sin(latitude), shape.segments));
  }
  for (int j = shape.halfLength > 0.0 ? 0 : 1; j < latitudeRings; ++j) {
    const double latitude = 0.5 * kPi * j / latitudeRings;
    rings.push_back(addRing(mesh, shape.radius * std::cos(latitude),
                            shape.halfLength + shape.radius * std::sin(latitude), shape.segments));
  }
  const int topPole = addVertex(mesh, Vec3(0.0, shape.halfLength + shape.radius, 0.0));
  fanToRing(mesh, bottomPole, rings.front(), shape.segments, /*facingUp=*/false);
  for (size_t r = 0; r + 1 < rings.size(); ++r) stitchRings(mesh, rings[r], rings[r + 1], shape.segments);
  fanToRing(mesh, topPole, rings.back(), shape.segments, /*facingUp=*/true);
  return mesh;
}

TriangleMesh makeCylinderMesh(const CylinderShape& shape) {
  assert(shape.radius > 0.0 && shape.halfHeight > 0.0 && shape.segments >= 3 && shape.heightSegments >= 1);
  TriangleMesh mesh;
  const int bottomCentre = addVertex(mesh, Vec3(0.0, -shape.halfHeight, 0.0));
  std::vector<int> rings;
  for (int k = 0; k <= shape.heightSegments; ++k) {
    const double y = shape.halfHeight * (2.0 * k / shape.heightSegments - 1.0);
    rings.push_back(addRing(mesh, shape.radius, y, shape.segments));
  }
  const int topCentre = addVertex(mesh, Vec3(0.0, shape.halfHeight, 0.0));
  fanToRing(mesh, bottomCentre, rings.front(), shape.segments, /*facingUp=*/false);
  for (size_t r = 0; r + 1 < rings.size(); ++r) stitchRings(mesh, rings[r], rings[r + 1], shape.segments);
  fanToRing(mesh, topCentre, rings.back(), shape.segments, /*facingUp=*/true);
  return mesh;
}

}  // namespace weft
