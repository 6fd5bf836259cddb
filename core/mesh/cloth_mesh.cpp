#include "mesh/cloth_mesh.h"

#include <algorithm>
#include <cmath>

namespace weft {

int ClothMesh::addVertex(const Vec3& position) {
  x.push_back(position);
  v.push_back(Vec3::Zero());
  mass.push_back(0.0);
  pinned.push_back(0);
  return vertexCount() - 1;
}

double restArea(const Triangle& t) {
  const Vec2 e1 = t.rest[1] - t.rest[0];
  const Vec2 e2 = t.rest[2] - t.rest[0];
  return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
}

double smallestAngle(const Vec2& a, const Vec2& b, const Vec2& c) {
  // Each corner's angle as atan2(|cross|, dot) of its two sides: accurate at every angle, where
  // acos of a normalised dot product loses precision near 0 (the slivers this is meant to catch).
  auto angleAt = [](const Vec2& corner, const Vec2& p, const Vec2& q) {
    const Vec2 u = p - corner;
    const Vec2 w = q - corner;
    return std::atan2(std::abs(u.x() * w.y() - u.y() * w.x()), u.dot(w));
  };
  return std::min({angleAt(a, b, c), angleAt(b, c, a), angleAt(c, a, b)});
}

double smallestRestAngle(const Triangle& t) { return smallestAngle(t.rest[0], t.rest[1], t.rest[2]); }

namespace {

// One triangle side seen from its lower endpoint: the side joins `low` (the bucket it sits in)
// and `high`, and is side `corner` of triangle `tri`.
struct TriangleSide {
  int high;
  int tri;
  int corner;
};

}  // namespace

// Edges come out sorted by (lower endpoint, higher endpoint), and each edge's triangles by id.
// A bucket per lower endpoint (counting sort) keeps this linear in the mesh size, which matters
// for 256 x 256 grids; filling the buckets in triangle order and sorting them stably by the higher
// endpoint gives each edge's triangles in ascending id without a second key.
void buildEdges(ClothMesh& mesh) {
  mesh.edges.clear();

  // Size the buckets from the triangles as well as the vertices, so that a corrupted mesh (an
  // index past the vertex arrays) is still indexed safely; checkMesh reports it.
  int bucketCount = mesh.vertexCount();
  for (const Triangle& t : mesh.tris) {
    for (int id : t.v) bucketCount = std::max(bucketCount, id + 1);
  }

  std::vector<int> bucketStart(static_cast<size_t>(bucketCount) + 1, 0);
  for (Triangle& t : mesh.tris) {
    for (int k = 0; k < 3; ++k) {
      t.edge[k] = kNone;
      const int a = t.v[k];
      const int b = t.v[(k + 1) % 3];
      if (a < 0 || b < 0) continue;  // no edge for a negative id
      ++bucketStart[static_cast<size_t>(std::min(a, b)) + 1];
    }
  }
  for (int i = 0; i < bucketCount; ++i) bucketStart[i + 1] += bucketStart[i];

  std::vector<TriangleSide> sides(static_cast<size_t>(bucketStart.back()));
  std::vector<int> fill(bucketStart.begin(), bucketStart.end() - 1);
  for (int ti = 0; ti < mesh.triangleCount(); ++ti) {
    const Triangle& t = mesh.tris[ti];
    for (int k = 0; k < 3; ++k) {
      const int a = t.v[k];
      const int b = t.v[(k + 1) % 3];
      if (a < 0 || b < 0) continue;
      sides[fill[std::min(a, b)]++] = TriangleSide{std::max(a, b), ti, k};
    }
  }

  for (int low = 0; low < bucketCount; ++low) {
    const auto first = sides.begin() + bucketStart[low];
    const auto last = sides.begin() + bucketStart[low + 1];
    std::stable_sort(first, last, [](const TriangleSide& p, const TriangleSide& q) { return p.high < q.high; });

    for (auto side = first; side != last;) {
      const int edgeId = mesh.edgeCount();
      Edge edge;
      edge.v = {low, side->high};
      int used = 0;
      const int high = side->high;
      for (; side != last && side->high == high; ++side) {
        mesh.tris[side->tri].edge[side->corner] = edgeId;
        // A non-manifold edge (three or more triangles) keeps its first two; the others still
        // point at it through Triangle::edge, which is how checkMesh finds them.
        if (used < 2) edge.tri[used++] = side->tri;
      }
      mesh.edges.push_back(edge);
    }
  }
}

void assignLumpedMasses(ClothMesh& mesh, double areaDensity) {
  mesh.mass.assign(mesh.x.size(), 0.0);
  for (const Triangle& t : mesh.tris) {
    const double third = areaDensity * std::abs(restArea(t)) / 3.0;
    for (int id : t.v) mesh.mass[id] += third;
  }
}

std::vector<std::vector<int>> vertexTriangles(const ClothMesh& mesh) {
  std::vector<std::vector<int>> around(mesh.x.size());
  for (int ti = 0; ti < mesh.triangleCount(); ++ti) {
    const Triangle& t = mesh.tris[ti];
    for (int k = 0; k < 3; ++k) {
      // A triangle that repeats a vertex (invalid, but possible mid-edit) is listed once.
      const bool seenEarlier = (k > 0 && t.v[k] == t.v[0]) || (k > 1 && t.v[k] == t.v[1]);
      if (!seenEarlier) around[t.v[k]].push_back(ti);
    }
  }
  return around;
}

}  // namespace weft
