#include "tearing/flip_edge.h"

#include <algorithm>
#include <utility>
#include <array>
#include <cmath>

#include "tearing/vertex_fan.h"

namespace weft {
namespace {

// The corner of `t` whose edge is `e` (edge[k] joins v[k] and v[k+1]), or kNone.
int sideOf(const Triangle& t, int e) {
  for (int k = 0; k < 3; ++k) {
    if (t.edge[k] == e) return k;
  }
  return kNone;
}

void replaceTriangle(Edge& edge, int from, int to) {
  for (int& t : edge.tri) {
    if (t == from) t = to;
  }
}

}  // namespace

bool flipIfBetter(ClothMesh& mesh, int e, double areaDensity, TopologyChange& change) {
  const Edge edge = mesh.edges[e];
  if (edge.isBoundary() || edge.torn || edge.cut || edge.tri[0] == kNone) return false;
  const int t0 = edge.tri[0], t1 = edge.tri[1];
  const int k0 = sideOf(mesh.tris[t0], e), k1 = sideOf(mesh.tris[t1], e);
  if (k0 == kNone || k1 == kNone) return false;
  const Triangle old0 = mesh.tris[t0], old1 = mesh.tris[t1];
  // t0 = (a, b, c) along its winding with the edge a -> b; t1 runs b -> a, then d.
  const int a = old0.v[k0], b = old0.v[(k0 + 1) % 3], c = old0.v[(k0 + 2) % 3];
  if (old1.v[k1] != b || old1.v[(k1 + 1) % 3] != a) return false;
  const int d = old1.v[(k1 + 2) % 3];
  const Vec2 ra = old0.rest[k0], rb = old0.rest[(k0 + 1) % 3], rc = old0.rest[(k0 + 2) % 3];
  const Vec2 rd = old1.rest[(k1 + 2) % 3];
  if ((old1.rest[k1] - rb).norm() > 1e-12 || (old1.rest[(k1 + 1) % 3] - ra).norm() > 1e-12) return false;  // a seam
  // The new triangles (a, d, c) and (d, b, c), both counter-clockwise when the quad a, d, b, c is
  // strictly convex.
  if (!(cross2(rd - ra, rc - ra) > 0.0) || !(cross2(rb - rd, rc - rd) > 0.0)) return false;
  // c and d must not be joined already (a vertex of valence three): the flip would double an edge.
  for (int t : walkFan(mesh, c, t0).triangles) {
    if (cornerOf(mesh.tris[t], d) != kNone) return false;
  }
  const double before = std::min(smallestAngle(ra, rb, rc), smallestAngle(rb, ra, rd));
  const double after = std::min(smallestAngle(ra, rd, rc), smallestAngle(rd, rb, rc));
  if (!(after > before * (1.0 + 1e-9))) return false;

  const int eBC = old0.edge[(k0 + 1) % 3], eCA = old0.edge[(k0 + 2) % 3];
  const int eAD = old1.edge[(k1 + 1) % 3], eDB = old1.edge[(k1 + 2) % 3];
  const std::array<int, 4> quad{a, b, c, d};
  std::array<double, 4> massBefore{};
  for (int i = 0; i < 4; ++i) massBefore[i] = mesh.mass[quad[i]];
  auto addMassThirds = [&](const Triangle& t, double sign) {
    const double third = sign * areaDensity * std::abs(restArea(t)) / 3.0;
    for (int id : t.v) mesh.mass[id] += third;
  };
  addMassThirds(old0, -1.0);
  addMassThirds(old1, -1.0);
  Triangle& n0 = mesh.tris[t0];
  n0.v = {a, d, c};
  n0.rest = {ra, rd, rc};
  n0.edge = {eAD, e, eCA};
  Triangle& n1 = mesh.tris[t1];
  n1.v = {d, b, c};
  n1.rest = {rd, rb, rc};
  n1.edge = {eDB, eBC, e};
  addMassThirds(n0, 1.0);
  addMassThirds(n1, 1.0);
  Edge& flipped = mesh.edges[e];
  flipped.v = {std::min(c, d), std::max(c, d)};
  flipped.tri = {t0, t1};
  replaceTriangle(mesh.edges[eAD], t1, t0);
  replaceTriangle(mesh.edges[eBC], t0, t1);

  // Momentum: sum m v over the quad is kept by one velocity correction shared by its vertices.
  Vec3 lost = Vec3::Zero();
  double massAfter = 0.0;
  for (int i = 0; i < 4; ++i) {
    lost += (massBefore[i] - mesh.mass[quad[i]]) * mesh.v[quad[i]];
    massAfter += mesh.mass[quad[i]];
  }
  for (int i = 0; i < 4; ++i) {
    mesh.v[quad[i]] += lost / massAfter;
    change.massChangedVertices.push_back(quad[i]);
  }
  change.changedTriangles.push_back(t0);
  change.changedTriangles.push_back(t1);
  for (int id : {e, eBC, eCA, eAD, eDB}) change.changedEdges.push_back(id);
  return true;
}

bool improveByFlips(ClothMesh& mesh, std::vector<int> triangles, const std::vector<int>& keep, double areaDensity,
                    TopologyChange& change, int maxPasses) {
  bool any = false;
  for (int pass = 0; pass < maxPasses; ++pass) {
    std::vector<int> edges;
    for (int t : triangles) {
      for (int e : mesh.tris[t].edge) edges.push_back(e);
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    bool flipped = false;
    for (int e : edges) {
      if (std::find(keep.begin(), keep.end(), e) != keep.end()) continue;
      if (flipIfBetter(mesh, e, areaDensity, change)) {
        flipped = any = true;
        for (int t : mesh.edges[e].tri) triangles.push_back(t);
      }
    }
    std::sort(triangles.begin(), triangles.end());
    triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
    if (!flipped) break;
  }
  return any;
}

void appendFlips(TopologyChange& into, const TopologyChange& flips) {
  for (auto [to, from] : {std::pair{&into.changedTriangles, &flips.changedTriangles},
                          std::pair{&into.changedEdges, &flips.changedEdges},
                          std::pair{&into.massChangedVertices, &flips.massChangedVertices}}) {
    to->insert(to->end(), from->begin(), from->end());
  }
}

}  // namespace weft
