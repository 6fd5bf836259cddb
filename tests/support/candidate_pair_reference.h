#pragma once
// The reference the broad phase is checked against: a mesh moving over one step, and the
// brute-force enumeration of the primitive pairs whose swept boxes overlap.
#include <array>
#include <initializer_list>
#include <utility>
#include <vector>

#include "collision/candidate_pairs.h"

namespace weft::test {

using PairList = std::vector<std::pair<int, int>>;

// A mesh moving over one step.
struct Motion {
  CollisionMesh mesh;
  std::vector<Vec3> x0, x1;
};

inline SweptMesh sweep(const Motion& motion, double margin) {
  SweptMesh swept;
  swept.mesh = &motion.mesh;
  swept.x0 = &motion.x0;
  swept.x1 = &motion.x1;
  updateSweptMesh(swept, margin);
  return swept;
}

// The swept box of some vertices over the step, grown by half the margin (boxGrowth, computed the
// same way as the implementation documents, so the comparison with it is exact).
inline Aabb sweptBox(const Motion& m, std::initializer_list<int> vertices, double margin) {
  Aabb box;
  for (int v : vertices) {
    box.grow(m.x0[v]);
    box.grow(m.x1[v]);
  }
  box.inflate(boxGrowth(margin));
  return box;
}

inline Aabb faceBox(const Motion& m, int f, double margin) {
  const auto& t = m.mesh.triangles[f];
  return sweptBox(m, {t[0], t[1], t[2]}, margin);
}

inline Aabb edgeBox(const Motion& m, int e, double margin) {
  return sweptBox(m, {m.mesh.edges[e][0], m.mesh.edges[e][1]}, margin);
}

inline bool isCorner(const std::array<int, 3>& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

inline PairList toList(const std::vector<VertexFacePair>& pairs) {
  PairList list;
  for (const auto& p : pairs) list.emplace_back(p.vertex, p.face);
  return list;
}

inline PairList toList(const std::vector<EdgeEdgePair>& pairs) {
  PairList list;
  for (const auto& p : pairs) list.emplace_back(p.edgeA, p.edgeB);
  return list;
}

// Every vertex of `vertices` (in some triangle) against every face of `faces` whose boxes overlap.
inline PairList bruteForceVertexFace(const Motion& vertices, const Motion& faces, double margin, bool self) {
  std::vector<Aabb> faceBoxes;
  for (int f = 0; f < static_cast<int>(faces.mesh.triangles.size()); ++f) faceBoxes.push_back(faceBox(faces, f, margin));
  PairList pairs;
  for (int v = 0; v < vertices.mesh.vertexCount; ++v) {
    if (vertices.mesh.vertexOwner[v] < 0) continue;
    const Aabb box = sweptBox(vertices, {v}, margin);
    for (int f = 0; f < static_cast<int>(faceBoxes.size()); ++f) {
      if (self && isCorner(faces.mesh.triangles[f], v)) continue;
      if (box.overlaps(faceBoxes[f])) pairs.emplace_back(v, f);
    }
  }
  return pairs;
}

inline PairList bruteForceEdgeEdge(const Motion& a, const Motion& b, double margin, bool self) {
  std::vector<Aabb> boxesB;
  for (int e = 0; e < static_cast<int>(b.mesh.edges.size()); ++e) boxesB.push_back(edgeBox(b, e, margin));
  PairList pairs;
  for (int ea = 0; ea < static_cast<int>(a.mesh.edges.size()); ++ea) {
    const Aabb box = edgeBox(a, ea, margin);
    for (int eb = self ? ea + 1 : 0; eb < static_cast<int>(boxesB.size()); ++eb) {
      if (self) {
        const auto& p = a.mesh.edges[ea];
        const auto& q = b.mesh.edges[eb];
        if (p[0] == q[0] || p[0] == q[1] || p[1] == q[0] || p[1] == q[1]) continue;
      }
      if (box.overlaps(boxesB[eb])) pairs.emplace_back(ea, eb);
    }
  }
  return pairs;
}

}  // namespace weft::test
