#include "tearing/move_vertex.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace weft {
namespace {

// Rest positions closer than this (m) are the same material point (no seam).
constexpr double kSamePoint = 1e-9;
// Two border edges whose directions differ by less than this (sine) make a straight border.
constexpr double kStraight = 1e-9;

bool touchesCrack(const ClothMesh& mesh, const VertexFan& fan) {
  for (size_t i = 0; i < fan.triangles.size(); ++i) {
    const Triangle& t = mesh.tris[fan.triangles[i]];
    const Edge& clockwise = mesh.edges[t.edge[fan.corners[i]]];
    const Edge& counterClockwise = mesh.edges[t.edge[(fan.corners[i] + 2) % 3]];
    if (clockwise.torn || clockwise.cut || counterClockwise.torn || counterClockwise.cut) return true;
  }
  return false;
}

std::array<Vec2, 3> movedShape(const Triangle& t, int corner, const Vec2& to) {
  std::array<Vec2, 3> shape = t.rest;
  shape[corner] = to;
  return shape;
}

// Barycentric coordinates of p in the triangle a, b, c (material space).
Vec3 barycentric(const Vec2& p, const std::array<Vec2, 3>& corners) {
  const double area = cross2(corners[1] - corners[0], corners[2] - corners[0]);
  const double l1 = cross2(corners[2] - corners[1], p - corners[1]) / area;
  const double l2 = cross2(corners[0] - corners[2], p - corners[2]) / area;
  return Vec3(l1, l2, 1.0 - l1 - l2);
}

}  // namespace

std::optional<VertexMove> planVertexMove(const ClothMesh& mesh, int vertex, const Vec2& linePoint,
                                         const Vec2& lineDirection, const TearGuards& guards) {
  if (vertex < 0 || vertex >= mesh.vertexCount() || mesh.pinned[vertex]) return std::nullopt;
  const int start = findTriangleAt(mesh, vertex);
  if (start == kNone) return std::nullopt;
  const VertexFan fan = walkFan(mesh, vertex, start);
  const Vec2 from = mesh.tris[fan.triangles[0]].rest[fan.corners[0]];
  for (size_t i = 0; i < fan.triangles.size(); ++i) {
    if ((mesh.tris[fan.triangles[i]].rest[fan.corners[i]] - from).norm() > kSamePoint) return std::nullopt;
  }

  VertexMove move;
  move.vertex = vertex;
  if (fan.closed) {
    move.to = linePoint + lineDirection * lineDirection.dot(from - linePoint);
  } else {
    // Along a straight original border only: the outline of the cloth must not change, and the
    // lips of a crack are where it ends, not a border to slide on.
    if (touchesCrack(mesh, fan)) return std::nullopt;
    const Triangle& first = mesh.tris[fan.triangles.front()];
    const Triangle& last = mesh.tris[fan.triangles.back()];
    const Vec2 toClockwiseEnd = first.rest[(fan.corners.front() + 1) % 3] - from;
    const Vec2 toCounterClockwiseEnd = last.rest[(fan.corners.back() + 2) % 3] - from;
    if (std::abs(cross2(toClockwiseEnd.normalized(), toCounterClockwiseEnd.normalized())) > kStraight) {
      return std::nullopt;
    }
    const Vec2 border = toClockwiseEnd.normalized();
    const double sine = cross2(border, lineDirection);
    if (std::abs(sine) < 1e-6) return std::nullopt;  // the line runs along the border
    move.to = from + (cross2(linePoint - from, lineDirection) / sine) * border;
  }
  if (!move.to.allFinite() || (move.to - from).norm() <= kSamePoint) return std::nullopt;

  // The guards, judged against the fan as it is: a move may not make it worse than it was.
  double smallestBefore = kPi;
  for (size_t i = 0; i < fan.triangles.size(); ++i) {
    smallestBefore = std::min(smallestBefore, smallestRestAngle(mesh.tris[fan.triangles[i]]));
  }
  const double minAngle = std::min(degToRad(guards.minAngleDeg), smallestBefore) * (1.0 - 1e-9);
  for (size_t i = 0; i < fan.triangles.size(); ++i) {
    const int k = fan.corners[i];
    const std::array<Vec2, 3> shape = movedShape(mesh.tris[fan.triangles[i]], k, move.to);
    if (!(cross2(shape[1] - shape[0], shape[2] - shape[0]) > 0.0)) return std::nullopt;
    if (!((shape[(k + 1) % 3] - shape[k]).norm() >= guards.minEdgeLength)) return std::nullopt;
    if (!((shape[(k + 2) % 3] - shape[k]).norm() >= guards.minEdgeLength)) return std::nullopt;
    if (!(smallestAngle(shape[0], shape[1], shape[2]) >= minAngle)) return std::nullopt;
  }
  return move;
}

void moveVertex(ClothMesh& mesh, const VertexMove& move, double areaDensity, TopologyChange& change) {
  const int a = move.vertex;
  const VertexFan fan = walkFan(mesh, a, findTriangleAt(mesh, a));

  // The deformation map at the new material point: the old triangle that holds it (the one it is
  // deepest inside, so round-off at a shared side cannot pick a wrong one).
  int holder = 0;
  Vec3 weights = Vec3::Zero();
  double deepest = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < fan.triangles.size(); ++i) {
    const Vec3 l = barycentric(move.to, mesh.tris[fan.triangles[i]].rest);
    if (l.minCoeff() > deepest) {
      deepest = l.minCoeff();
      holder = static_cast<int>(i);
      weights = l;
    }
  }
  const Triangle& held = mesh.tris[fan.triangles[holder]];
  const Vec3 position = weights[0] * mesh.x[held.v[0]] + weights[1] * mesh.x[held.v[1]] + weights[2] * mesh.x[held.v[2]];

  // Old masses of every vertex whose share changes, for the momentum below.
  std::vector<std::pair<int, double>> oldMasses;
  auto remember = [&](int id) {
    if (std::none_of(oldMasses.begin(), oldMasses.end(), [id](const auto& m) { return m.first == id; })) {
      oldMasses.emplace_back(id, mesh.mass[id]);
    }
  };
  for (int t : fan.triangles) {
    for (int id : mesh.tris[t].v) remember(id);
  }
  auto addMassThirds = [&](const Triangle& t, double sign) {
    const double third = sign * areaDensity * std::abs(restArea(t)) / 3.0;
    for (int id : t.v) mesh.mass[id] += third;
  };
  for (size_t i = 0; i < fan.triangles.size(); ++i) {
    Triangle& t = mesh.tris[fan.triangles[i]];
    addMassThirds(t, -1.0);
    t.rest[fan.corners[i]] = move.to;
    addMassThirds(t, 1.0);
    change.changedTriangles.push_back(fan.triangles[i]);
    for (int e : t.edge) change.changedEdges.push_back(e);
  }
  mesh.x[a] = position;

  // Momentum: the neighbours keep their velocities, so the moved vertex takes what their masses
  // gave up (or took) with its own: sum m v is unchanged exactly (up to round-off).
  Vec3 momentum = Vec3::Zero();
  for (const auto& [id, massBefore] : oldMasses) {
    momentum += massBefore * mesh.v[id];
    if (id != a) momentum -= mesh.mass[id] * mesh.v[id];
    change.massChangedVertices.push_back(id);
  }
  mesh.v[a] = momentum / mesh.mass[a];
  std::sort(change.changedTriangles.begin(), change.changedTriangles.end());
  std::sort(change.changedEdges.begin(), change.changedEdges.end());
  change.changedEdges.erase(std::unique(change.changedEdges.begin(), change.changedEdges.end()),
                            change.changedEdges.end());
  std::sort(change.massChangedVertices.begin(), change.massChangedVertices.end());
  change.movedVertices.push_back(a);
}

}  // namespace weft
