#include "rigid/closed_surface_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include <Eigen/Geometry>

namespace weft {

namespace {

// A triangle whose area is below this fraction of the squared bounding-box diagonal has no usable
// normal (contact would divide by its length).
constexpr double kMinRelativeArea = 1e-12;

std::string edgeName(int a, int b) { return std::to_string(a) + "-" + std::to_string(b); }

// One triangle's use of an edge, keyed by the edge's lower vertex id first.
struct EdgeUse {
  int low = 0;
  int high = 0;
  bool lowToHigh = true;  // the triangle walks the edge from `low` to `high`
  int triangle = 0;

  bool sameEdge(const EdgeUse& other) const { return low == other.low && high == other.high; }
};

void checkEdges(const TriangleMesh& mesh, std::vector<std::string>& problems) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.triangles.size());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), a < b, t});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.low, x.high, x.triangle) < std::tie(y.low, y.high, y.triangle);
  });
  for (size_t first = 0; first < uses.size();) {
    size_t end = first;
    int forward = 0;
    while (end < uses.size() && uses[end].sameEdge(uses[first])) forward += uses[end++].lowToHigh ? 1 : 0;
    const int count = static_cast<int>(end - first);
    const std::string edge = "edge " + edgeName(uses[first].low, uses[first].high);
    const std::string triangle = "triangle " + std::to_string(uses[first].triangle);
    if (count == 1) {
      problems.push_back(edge + " borders only " + triangle + ": the surface has a hole");
    } else if (count > 2) {
      problems.push_back(edge + " is shared by " + std::to_string(count) + " triangles (first " + triangle +
                         "): not a 2-manifold");
    } else if (forward != 1) {
      problems.push_back(edge + " is walked in the same direction by triangles " +
                         std::to_string(uses[first].triangle) + " and " + std::to_string(uses[first + 1].triangle) +
                         ": inconsistent orientation (one of them is flipped)");
    }
    first = end;
  }
}

// Around a vertex v of a closed, consistently oriented mesh, each triangle (v, a, b) leads from a
// to b; the triangles form one fan exactly when following a -> b visits them all in one cycle.
void checkVertexFans(const TriangleMesh& mesh, std::vector<std::string>& problems) {
  const int n = static_cast<int>(mesh.vertices.size());
  std::vector<std::vector<std::array<int, 2>>> spokes(n);  // per vertex: (a, b) of each triangle (v, a, b)
  for (const std::array<int, 3>& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) spokes[t[k]].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
  }
  for (int v = 0; v < n; ++v) {
    std::vector<std::array<int, 2>>& fan = spokes[v];
    if (fan.empty()) {
      problems.push_back("vertex " + std::to_string(v) + " is in no triangle");
      continue;
    }
    std::sort(fan.begin(), fan.end());
    int visited = 0;
    int at = fan.front()[0];
    do {
      const auto next = std::lower_bound(fan.begin(), fan.end(), std::array<int, 2>{at, -1});
      if (next == fan.end() || (*next)[0] != at) break;  // an edge problem, already reported
      at = (*next)[1];
      ++visited;
    } while (at != fan.front()[0] && visited <= static_cast<int>(fan.size()));
    if (visited < static_cast<int>(fan.size())) {
      problems.push_back("vertex " + std::to_string(v) +
                         " joins separate fans of triangles (the surface touches itself there)");
    }
  }
}

}  // namespace

std::vector<std::string> closedSurfaceProblems(const TriangleMesh& mesh) {
  std::vector<std::string> problems;
  if (mesh.triangles.empty()) return {"has no triangles"};
  const int n = static_cast<int>(mesh.vertices.size());

  const double huge = std::numeric_limits<double>::infinity();
  Vec3 low = Vec3::Constant(huge), high = Vec3::Constant(-huge);
  for (int v = 0; v < n; ++v) {
    if (!mesh.vertices[v].allFinite()) problems.push_back("vertex " + std::to_string(v) + " has a non-finite position");
    low = low.cwiseMin(mesh.vertices[v]);
    high = high.cwiseMax(mesh.vertices[v]);
  }
  const double minDoubleArea = 2.0 * kMinRelativeArea * (high - low).squaredNorm();

  bool idsValid = true;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const std::array<int, 3>& tri = mesh.triangles[t];
    const std::string name = "triangle " + std::to_string(t);
    if (std::any_of(tri.begin(), tri.end(), [n](int v) { return v < 0 || v >= n; })) {
      problems.push_back(name + " has a vertex id out of range (the mesh has " + std::to_string(n) + " vertices)");
      idsValid = false;
    } else if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      problems.push_back(name + " repeats a vertex");
      idsValid = false;
    } else {
      const Vec3 doubleArea =
          (mesh.vertices[tri[1]] - mesh.vertices[tri[0]]).cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
      if (!(doubleArea.norm() > minDoubleArea)) problems.push_back(name + " has zero area");
    }
  }
  if (!idsValid) return problems;  // the topology checks below index by vertex id

  const size_t before = problems.size();
  checkEdges(mesh, problems);
  if (problems.size() == before) {
    checkVertexFans(mesh, problems);
  } else {
    // Unused vertices are worth reporting even when edges are broken.
    std::vector<char> used(n, 0);
    for (const std::array<int, 3>& t : mesh.triangles)
      for (int v : t) used[v] = 1;
    for (int v = 0; v < n; ++v)
      if (!used[v]) problems.push_back("vertex " + std::to_string(v) + " is in no triangle");
  }
  return problems;
}

}  // namespace weft
