#include "mesh/mesh_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <tuple>
#include <utility>

namespace weft {

namespace {

// Each check appends one line per problem; every index is range-checked before use, so a
// corrupted mesh is described rather than crashing the checker.
using Problems = std::vector<std::string>;

template <typename... Parts>
void report(Problems& out, const Parts&... parts) {
  std::ostringstream line;
  (line << ... << parts);
  out.push_back(line.str());
}

bool isVertex(const ClothMesh& mesh, int id) { return id >= 0 && id < mesh.vertexCount(); }
bool isTriangle(const ClothMesh& mesh, int id) { return id >= 0 && id < mesh.triangleCount(); }
bool isEdge(const ClothMesh& mesh, int id) { return id >= 0 && id < mesh.edgeCount(); }

// A triangle whose ids are all in range and distinct; the topology checks only look at these
// (the others are already reported).
bool isWellFormed(const ClothMesh& mesh, const Triangle& t) {
  return isVertex(mesh, t.v[0]) && isVertex(mesh, t.v[1]) && isVertex(mesh, t.v[2]) && t.v[0] != t.v[1] &&
         t.v[1] != t.v[2] && t.v[2] != t.v[0];
}

bool joins(const Edge& e, int a, int b) { return (e.v[0] == a && e.v[1] == b) || (e.v[0] == b && e.v[1] == a); }

std::uint64_t pairKey(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

void checkArraySizes(const ClothMesh& mesh, Problems& out) {
  const size_t n = mesh.x.size();
  if (mesh.v.size() != n) report(out, "array sizes: ", mesh.v.size(), " velocities for ", n, " positions");
  if (mesh.mass.size() != n) report(out, "array sizes: ", mesh.mass.size(), " masses for ", n, " positions");
  if (mesh.pinned.size() != n) report(out, "array sizes: ", mesh.pinned.size(), " pinned flags for ", n, " positions");
}

void checkVertexValues(const ClothMesh& mesh, Problems& out) {
  for (size_t i = 0; i < mesh.x.size(); ++i) {
    if (!mesh.x[i].allFinite()) report(out, "vertex ", i, ": non-finite position");
  }
  for (size_t i = 0; i < mesh.v.size(); ++i) {
    if (!mesh.v[i].allFinite()) report(out, "vertex ", i, ": non-finite velocity");
  }
  for (size_t i = 0; i < mesh.mass.size(); ++i) {
    if (!std::isfinite(mesh.mass[i])) {
      report(out, "vertex ", i, ": non-finite mass");
    } else if (mesh.mass[i] < 0.0) {
      report(out, "vertex ", i, ": negative mass ", mesh.mass[i], " kg");
    }
  }
}

void checkTriangles(const ClothMesh& mesh, Problems& out) {
  for (int ti = 0; ti < mesh.triangleCount(); ++ti) {
    const Triangle& t = mesh.tris[ti];
    for (int k = 0; k < 3; ++k) {
      if (!isVertex(mesh, t.v[k])) {
        report(out, "triangle ", ti, ": vertex index ", t.v[k], " out of range [0, ", mesh.vertexCount(), ")");
      }
    }
    for (int k = 0; k < 3; ++k) {
      if (t.v[k] == t.v[(k + 1) % 3]) report(out, "triangle ", ti, ": repeated vertex ", t.v[k]);
    }

    const double area = restArea(t);
    if (!(area > 0.0)) {  // also catches NaN
      report(out, "triangle ", ti, ": non-positive rest area ", area, " m^2 (must be counter-clockwise in material space)");
    }

    for (int k = 0; k < 3; ++k) {
      const int e = t.edge[k];
      const int a = t.v[k];
      const int b = t.v[(k + 1) % 3];
      if (!isEdge(mesh, e)) {
        report(out, "triangle ", ti, ": edge[", k, "] = ", e, " out of range [0, ", mesh.edgeCount(), ")");
      } else if (!joins(mesh.edges[e], a, b)) {
        report(out, "triangle ", ti, ": edge[", k, "] = ", e, " joins ", mesh.edges[e].v[0], "-", mesh.edges[e].v[1],
               ", not its corners ", a, "-", b);
      }
    }
  }
}

void checkDuplicatedTriangles(const ClothMesh& mesh, Problems& out) {
  std::vector<std::pair<std::array<int, 3>, int>> sortedCorners;
  sortedCorners.reserve(mesh.tris.size());
  for (int ti = 0; ti < mesh.triangleCount(); ++ti) {
    if (!isWellFormed(mesh, mesh.tris[ti])) continue;
    std::array<int, 3> corners = mesh.tris[ti].v;
    std::sort(corners.begin(), corners.end());
    sortedCorners.emplace_back(corners, ti);
  }
  std::sort(sortedCorners.begin(), sortedCorners.end());
  for (size_t i = 1; i < sortedCorners.size(); ++i) {
    if (sortedCorners[i].first == sortedCorners[i - 1].first) {
      const auto& c = sortedCorners[i].first;
      report(out, "triangles ", sortedCorners[i - 1].second, " and ", sortedCorners[i].second,
             ": duplicated triangle (same vertices ", c[0], ", ", c[1], ", ", c[2], ")");
    }
  }
}

// Looks at the triangles' sides directly (not at `edges`), so that manifoldness and orientation
// are judged even when the edge list is stale or wrong.
// Every side of every well-formed triangle, sorted by endpoints (then triangle), so that the
// sides a pair of vertices shares are adjacent.
struct Side {
  std::uint64_t key;
  int tri;
  int from;  // the side runs from `from` to the other endpoint in the triangle's winding
};

std::vector<Side> sortedSides(const ClothMesh& mesh) {
  std::vector<Side> sides;
  sides.reserve(3 * mesh.tris.size());
  for (int ti = 0; ti < mesh.triangleCount(); ++ti) {
    const Triangle& t = mesh.tris[ti];
    if (!isWellFormed(mesh, t)) continue;
    for (int k = 0; k < 3; ++k) sides.push_back(Side{pairKey(t.v[k], t.v[(k + 1) % 3]), ti, t.v[k]});
  }
  std::sort(sides.begin(), sides.end(),
            [](const Side& p, const Side& q) { return std::tie(p.key, p.tri) < std::tie(q.key, q.tri); });
  return sides;
}

void checkSharedSides(const ClothMesh& mesh, Problems& out) {
  const std::vector<Side> sides = sortedSides(mesh);

  for (size_t first = 0; first < sides.size();) {
    size_t last = first + 1;
    while (last < sides.size() && sides[last].key == sides[first].key) ++last;
    const int low = static_cast<int>(sides[first].key >> 32);
    const int high = static_cast<int>(sides[first].key & 0xffffffffu);
    const size_t count = last - first;
    if (count > 2) {
      report(out, "vertices ", low, "-", high, ": edge used by ", count, " triangles (non-manifold)");
    } else if (count == 2 && sides[first].from == sides[first + 1].from) {
      report(out, "triangles ", sides[first].tri, " and ", sides[first + 1].tri, " run the same way along edge ", low,
             "-", high, " (inconsistent orientation)");
    }
    first = last;
  }
}

void checkEdges(const ClothMesh& mesh, Problems& out) {
  // Which triangles point at each edge through Triangle::edge.
  std::vector<std::vector<int>> users(mesh.edges.size());
  for (int ti = 0; ti < mesh.triangleCount(); ++ti) {
    for (int e : mesh.tris[ti].edge) {
      if (isEdge(mesh, e)) users[e].push_back(ti);
    }
  }

  std::vector<std::pair<std::uint64_t, int>> endpoints;
  for (int ei = 0; ei < mesh.edgeCount(); ++ei) {
    const Edge& e = mesh.edges[ei];
    const bool endpointsValid = isVertex(mesh, e.v[0]) && isVertex(mesh, e.v[1]);
    if (!endpointsValid) {
      report(out, "edge ", ei, ": vertex index ", e.v[0], "-", e.v[1], " out of range [0, ", mesh.vertexCount(), ")");
    } else if (e.v[0] == e.v[1]) {
      report(out, "edge ", ei, ": joins vertex ", e.v[0], " to itself");
    } else {
      endpoints.emplace_back(pairKey(e.v[0], e.v[1]), ei);
    }

    if (e.tri[0] == kNone && e.tri[1] != kNone) {
      report(out, "edge ", ei, ": tri[0] is empty but tri[1] = ", e.tri[1], " (a border edge keeps its triangle in tri[0])");
    } else if (e.tri[0] == kNone) {
      report(out, "edge ", ei, ": dangling edge (no triangle)");
    }
    if (e.tri[0] != kNone && e.tri[0] == e.tri[1]) {
      report(out, "edge ", ei, ": lists triangle ", e.tri[0], " twice");
    }
    for (int slot = 0; slot < 2; ++slot) {
      const int t = e.tri[slot];
      if (t == kNone) continue;
      if (!isTriangle(mesh, t)) {
        report(out, "edge ", ei, ": tri[", slot, "] = ", t, " out of range [0, ", mesh.triangleCount(), ")");
      } else if (std::find(users[ei].begin(), users[ei].end(), t) == users[ei].end()) {
        report(out, "edge ", ei, ": lists triangle ", t, ", which does not use it");
      }
    }
    for (int t : users[ei]) {
      if (t != e.tri[0] && t != e.tri[1]) report(out, "edge ", ei, ": used by triangle ", t, ", which it does not list");
    }
    if (users[ei].size() > 2) report(out, "edge ", ei, ": used by ", users[ei].size(), " triangles (non-manifold)");
  }

  std::sort(endpoints.begin(), endpoints.end());
  for (size_t i = 1; i < endpoints.size(); ++i) {
    if (endpoints[i].first == endpoints[i - 1].first) {
      report(out, "edges ", endpoints[i - 1].second, " and ", endpoints[i].second, ": duplicated edge (same vertices)");
    }
  }
}

// The corner of triangle t at vertex id, as an index 3 t + k.
int cornerIndex(const ClothMesh& mesh, int t, int id) {
  for (int k = 0; k < 3; ++k) {
    if (mesh.tris[t].v[k] == id) return 3 * t + k;
  }
  return kNone;
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Two triangles sharing a side must agree on its rest length: otherwise the material is stretched
// across a seam that the mesh does not show. Compared relative to the length, since each
// triangle's rest coordinates may sit in its own frame.
constexpr double kRestLengthTolerance = 1e-9;

// Judged from the triangles' sides directly (like checkSharedSides): a vertex is manifold when its
// triangles form one fan, i.e. the corners at it are connected through the sides they share. Two
// or more fans meeting only at the vertex make a bow-tie.
void checkVertexFansAndSeams(const ClothMesh& mesh, Problems& out) {
  const std::vector<Side> sides = sortedSides(mesh);

  std::vector<int> parent(3 * mesh.tris.size());
  for (size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  for (size_t first = 0; first + 1 < sides.size(); ++first) {
    const bool pair = sides[first + 1].key == sides[first].key &&
                      (first + 2 >= sides.size() || sides[first + 2].key != sides[first].key) &&
                      (first == 0 || sides[first - 1].key != sides[first].key);
    if (!pair) continue;  // a border side, or a non-manifold edge (reported elsewhere)
    const int low = static_cast<int>(sides[first].key >> 32);
    const int high = static_cast<int>(sides[first].key & 0xffffffffu);
    const int a = sides[first].tri, b = sides[first + 1].tri;
    for (int id : {low, high}) parent[findRoot(parent, cornerIndex(mesh, a, id))] = findRoot(parent, cornerIndex(mesh, b, id));

    const Triangle& ta = mesh.tris[a];
    const Triangle& tb = mesh.tris[b];
    const double lengthA = (ta.rest[cornerIndex(mesh, a, low) % 3] - ta.rest[cornerIndex(mesh, a, high) % 3]).norm();
    const double lengthB = (tb.rest[cornerIndex(mesh, b, low) % 3] - tb.rest[cornerIndex(mesh, b, high) % 3]).norm();
    if (std::abs(lengthA - lengthB) > kRestLengthTolerance * std::max(lengthA, lengthB)) {
      report(out, "triangles ", a, " and ", b, " disagree on the rest length of edge ", low, "-", high, ": ", lengthA,
             " vs ", lengthB, " m");
    }
  }

  // Distinct fans (corner roots) per vertex.
  std::vector<std::pair<int, int>> vertexRoots;
  for (int ti = 0; ti < mesh.triangleCount(); ++ti) {
    if (!isWellFormed(mesh, mesh.tris[ti])) continue;
    for (int k = 0; k < 3; ++k) vertexRoots.emplace_back(mesh.tris[ti].v[k], findRoot(parent, 3 * ti + k));
  }
  std::sort(vertexRoots.begin(), vertexRoots.end());
  vertexRoots.erase(std::unique(vertexRoots.begin(), vertexRoots.end()), vertexRoots.end());
  for (size_t first = 0; first < vertexRoots.size();) {
    size_t last = first + 1;
    while (last < vertexRoots.size() && vertexRoots[last].first == vertexRoots[first].first) ++last;
    if (last - first > 1) {
      report(out, "vertex ", vertexRoots[first].first, ": non-manifold vertex (its triangles form ", last - first,
             " fans that meet only at it)");
    }
    first = last;
  }
}

void checkDanglingVertices(const ClothMesh& mesh, Problems& out) {
  std::vector<bool> used(mesh.x.size(), false);
  for (const Triangle& t : mesh.tris) {
    for (int id : t.v) {
      if (isVertex(mesh, id)) used[id] = true;
    }
  }
  for (size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) report(out, "vertex ", i, ": dangling vertex (no triangle uses it)");
  }
}

// A problem's kind: its text with every run of digits replaced by '#'.
std::string problemKind(const std::string& line) {
  std::string kind;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const bool digit = line[i] >= '0' && line[i] <= '9';
    if (!digit) kind += line[i];
    else if (kind.empty() || kind.back() != '#') kind += '#';
  }
  return kind;
}

}  // namespace

std::vector<std::string> groupProblems(const std::vector<std::string>& problems, std::size_t maxKinds) {
  std::vector<std::string> kinds;
  std::vector<std::size_t> first, count;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const std::string kind = problemKind(problems[i]);
    const auto it = std::find(kinds.begin(), kinds.end(), kind);
    if (it != kinds.end()) {
      ++count[static_cast<std::size_t>(it - kinds.begin())];
      continue;
    }
    kinds.push_back(kind);
    first.push_back(i);
    count.push_back(1);
  }
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < kinds.size() && k < maxKinds; ++k) {
    lines.push_back(problems[first[k]] +
                    (count[k] > 1 ? " (and " + std::to_string(count[k] - 1) + " more like it)" : std::string()));
  }
  if (kinds.size() > maxKinds) {
    std::size_t rest = 0;
    for (std::size_t k = maxKinds; k < kinds.size(); ++k) rest += count[k];
    lines.push_back(std::to_string(rest) + " more problem(s) of " + std::to_string(kinds.size() - maxKinds) +
                    " other kind(s)");
  }
  return lines;
}

std::vector<std::string> checkMesh(const ClothMesh& mesh) {
  Problems problems;
  checkArraySizes(mesh, problems);
  checkVertexValues(mesh, problems);
  checkTriangles(mesh, problems);
  checkDuplicatedTriangles(mesh, problems);
  checkSharedSides(mesh, problems);
  checkEdges(mesh, problems);
  checkVertexFansAndSeams(mesh, problems);
  checkDanglingVertices(mesh, problems);
  return problems;
}

}  // namespace weft
