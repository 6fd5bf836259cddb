#include "tearing/split_edge.h"

#include <algorithm>
#include <cmath>

#include "tearing/vertex_fan.h"

namespace weft {
namespace {

// One triangle on the split edge, seen along its own winding: corners u -> w is the edge, c the
// opposite corner.
struct SplitSide {
  int triangle;
  int corner;  // v[corner] = u, v[corner+1] = w, v[corner+2] = c
};

std::vector<SplitSide> sidesOf(const ClothMesh& mesh, int edgeId) {
  const Edge& edge = mesh.edges[edgeId];
  std::vector<SplitSide> sides;
  for (int t : edge.tri) {
    if (t == kNone) continue;
    for (int k = 0; k < 3; ++k) {
      if (mesh.tris[t].edge[k] == edgeId) sides.push_back(SplitSide{t, k});
    }
  }
  return sides;
}

// The new vertex's rest coordinates in triangle `t`: interpolated from the edge's `from`
// endpoint, whichever way the triangle runs along it, so that two triangles that agree on the
// endpoints agree on the new point to the bit.
Vec2 splitPointRest(const Triangle& t, int from, int to, double fraction) {
  const Vec2& a = t.rest[cornerOf(t, from)];
  const Vec2& b = t.rest[cornerOf(t, to)];
  return a + fraction * (b - a);
}

std::array<std::array<Vec2, 3>, 2> piecesOf(const Triangle& t, int corner, const Vec2& q) {
  const Vec2& u = t.rest[corner];
  const Vec2& w = t.rest[(corner + 1) % 3];
  const Vec2& c = t.rest[(corner + 2) % 3];
  return {std::array<Vec2, 3>{u, q, c}, std::array<Vec2, 3>{q, w, c}};
}

}  // namespace

std::vector<std::array<Vec2, 3>> restShapesAfterSplit(const ClothMesh& mesh, const EdgeSplitPoint& at) {
  const Triangle& t = mesh.tris[at.triangle];
  const int from = t.v[at.side];
  const int to = t.v[(at.side + 1) % 3];
  std::vector<std::array<Vec2, 3>> shapes;
  for (const SplitSide& side : sidesOf(mesh, t.edge[at.side])) {
    const Triangle& split = mesh.tris[side.triangle];
    for (const auto& piece : piecesOf(split, side.corner, splitPointRest(split, from, to, at.fraction))) {
      shapes.push_back(piece);
    }
  }
  return shapes;
}

// Mass and momentum. Lumped mass gives each corner a third of its triangle's rest area times the
// area density (assignLumpedMasses). Splitting (u, w, c) at q into (u, q, c) and (q, w, c) leaves
// c's share unchanged (the two pieces' areas sum to the old area), moves part of u's and w's
// shares to q, and gives q the rest: each old vertex's mass only decreases. To keep momentum
// sum m v exactly, q takes the mass the old vertices lost together with their velocities:
//   v_q = sum_i (m_i_old - m_i_new) v_i / m_q,
// a positive-weight average of the old velocities (the weights sum to m_q up to round-off, and
// c's weight is round-off itself). The masses are patched by taking each old triangle's thirds
// off its corners and adding the pieces' thirds, so no fan is re-summed.
int splitEdge(ClothMesh& mesh, const EdgeSplitPoint& at, double areaDensity, TopologyChange& change) {
  const int edgeId = mesh.tris[at.triangle].edge[at.side];
  const int from = mesh.tris[at.triangle].v[at.side];
  const int to = mesh.tris[at.triangle].v[(at.side + 1) % 3];
  const std::vector<SplitSide> sides = sidesOf(mesh, edgeId);

  // The old corners with their masses, for the momentum transfer below.
  std::vector<std::pair<int, double>> oldMasses;
  for (const SplitSide& side : sides) {
    for (int id : mesh.tris[side.triangle].v) {
      const bool listed = std::any_of(oldMasses.begin(), oldMasses.end(), [id](const auto& m) { return m.first == id; });
      if (!listed) oldMasses.emplace_back(id, mesh.mass[id]);
    }
  }

  const int q = mesh.addVertex((1.0 - at.fraction) * mesh.x[from] + at.fraction * mesh.x[to]);
  change.newVertices.push_back(q);
  // An edge pinned at both ends lies in a clamp's jaws, which hold every point of it: so is the
  // point inserted on it (else a crack could reach the clamp's edge there and go on into the jaws
  // from a vertex that is not pinned; tear_mesh.h).
  if (mesh.pinned[from] && mesh.pinned[to]) {
    mesh.pinned[q] = 1;
    change.pinnedSplits.push_back(PinnedSplit{q, from, to, at.fraction});
  }

  // The edge keeps the half at `from`; the half at `to` is appended with the same tags.
  const int toHalf = mesh.edgeCount();
  Edge half = mesh.edges[edgeId];
  half.v = {std::min(q, to), std::max(q, to)};
  half.tri = {kNone, kNone};
  mesh.edges.push_back(half);
  Edge& fromHalf = mesh.edges[edgeId];
  fromHalf.v = {std::min(q, from), std::max(q, from)};
  fromHalf.tri = {kNone, kNone};
  change.changedEdges.push_back(edgeId);
  change.newEdges.push_back(toHalf);

  auto addTriangleToEdge = [&](int e, int t) {
    Edge& edge = mesh.edges[e];
    edge.tri[edge.tri[0] == kNone ? 0 : 1] = t;
  };
  auto addMassThirds = [&](const Triangle& t, double sign) {
    const double third = sign * areaDensity * std::abs(restArea(t)) / 3.0;
    for (int id : t.v) mesh.mass[id] += third;
  };

  for (const SplitSide& side : sides) {
    const Triangle old = mesh.tris[side.triangle];
    const int k = side.corner;
    const int u = old.v[k], w = old.v[(k + 1) % 3], c = old.v[(k + 2) % 3];
    const auto pieces = piecesOf(old, k, splitPointRest(old, from, to, at.fraction));
    const int uq = u == from ? edgeId : toHalf;
    const int qw = u == from ? toHalf : edgeId;

    const int second = mesh.triangleCount();
    const int spoke = mesh.edgeCount();
    Edge qc;
    qc.v = {std::min(q, c), std::max(q, c)};
    qc.tri = {side.triangle, second};
    mesh.edges.push_back(qc);

    Triangle first;
    first.v = {u, q, c};
    first.rest = pieces[0];
    first.edge = {uq, spoke, old.edge[(k + 2) % 3]};
    Triangle appended;
    appended.v = {q, w, c};
    appended.rest = pieces[1];
    appended.edge = {qw, old.edge[(k + 1) % 3], spoke};

    addMassThirds(old, -1.0);
    mesh.tris[side.triangle] = first;
    mesh.tris.push_back(appended);
    addMassThirds(first, 1.0);
    addMassThirds(appended, 1.0);

    // The side w-c now belongs to the appended piece.
    Edge& wc = mesh.edges[old.edge[(k + 1) % 3]];
    for (int& t : wc.tri) {
      if (t == side.triangle) t = second;
    }
    addTriangleToEdge(uq, side.triangle);
    addTriangleToEdge(qw, second);

    change.changedTriangles.push_back(side.triangle);
    change.changedTriangles.push_back(second);
    change.newTriangles.push_back(second);
    change.newEdges.push_back(spoke);
    change.changedEdges.push_back(old.edge[(k + 1) % 3]);
  }
  Vec3 momentumLost = Vec3::Zero();
  for (const auto& [id, massBefore] : oldMasses) {
    momentumLost += (massBefore - mesh.mass[id]) * mesh.v[id];
    change.massChangedVertices.push_back(id);
  }
  mesh.v[q] = momentumLost / mesh.mass[q];
  change.massChangedVertices.push_back(q);
  return q;
}

}  // namespace weft
