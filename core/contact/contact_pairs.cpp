#include "contact/contact_pairs.h"

#include <algorithm>
#include <array>

namespace weft {

void findPrimitivePairs(std::vector<ContactBody>& bodies, const ContactPairing& pairing, double margin,
                        CandidatePairs& scratch, std::vector<PrimitivePair>& out) {
  out.clear();
  std::vector<char> involved(bodies.size(), 0);
  for (const auto& [a, b] : pairing.between) involved[a] = involved[b] = 1;
  for (int a : pairing.self) involved[a] = 1;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (involved[i]) updateSweptMesh(bodies[i].swept, margin);
  }
  for (const auto& [a, b] : pairing.between) {
    findCandidatePairs(bodies[a].swept, bodies[b].swept, margin, scratch);
    for (const auto& p : scratch.vfAB) out.push_back({PairKind::VertexFace, a, p.vertex, b, p.face});
    for (const auto& p : scratch.vfBA) out.push_back({PairKind::VertexFace, b, p.vertex, a, p.face});
    for (const auto& p : scratch.ee) out.push_back({PairKind::EdgeEdge, a, p.edgeA, b, p.edgeB});
  }
  for (int a : pairing.self) {
    findSelfCandidatePairs(bodies[a].swept, margin, scratch);
    for (const auto& p : scratch.vfAB) out.push_back({PairKind::VertexFace, a, p.vertex, a, p.face});
    for (const auto& p : scratch.ee) out.push_back({PairKind::EdgeEdge, a, p.edgeA, a, p.edgeB});
  }
}

namespace {

// The pairs of one body pair (A, B), or of a body with itself (then all vertex-face pairs are in
// vfAB and each edge pair is (smaller, larger)), as (feature of the first, feature of the second).
struct TouchingLists {
  std::vector<std::array<int, 2>> vfAB, vfBA, ee;
  void clear() {
    vfAB.clear();
    vfBA.clear();
    ee.clear();
  }
};

// Every pair made of a feature around vertex u of `from` (u itself, a triangle holding it, an edge
// ending at it) and a feature of `into` whose grown swept boxes overlap, with one query of
// `into`'s tree: each such pair's other feature lies in a triangle whose (grown) box overlaps the
// box of u's triangles. `fromIsA` says on which side of the lists `from` is; `self` that from and
// into are one mesh (then features touching by topology are left out). Each box is computed once:
// u's edges' before the query, each reported triangle's corners' and edges' once per triangle.
void touchingAround(const SweptMesh& from, int u, const SweptMesh& into, double growth, bool fromIsA, bool self,
                    std::vector<int>& edgesAround, std::vector<Aabb>& edgeBoxes, std::vector<int>& triangles,
                    TouchingLists& out) {
  const CollisionMesh& fromMesh = *from.mesh;
  const CollisionMesh& intoMesh = *into.mesh;
  const std::vector<int>& facesAround = fromMesh.trianglesAround[u];
  if (facesAround.empty()) return;  // in no triangle: no feature a search lists
  Aabb star;
  edgesAround.clear();
  for (int f : facesAround) {
    star.grow(from.triangleBoxes[f]);
    for (int e : fromMesh.triangleEdges[f]) {
      if (fromMesh.edges[e][0] == u || fromMesh.edges[e][1] == u) edgesAround.push_back(e);
    }
  }
  std::sort(edgesAround.begin(), edgesAround.end());
  edgesAround.erase(std::unique(edgesAround.begin(), edgesAround.end()), edgesAround.end());
  edgeBoxes.clear();
  for (int e : edgesAround) edgeBoxes.push_back(sweptBox(from, fromMesh.edges[e]));
  triangles.clear();
  into.bvh.overlapping(star, [&](int t) { triangles.push_back(t); });

  // Where each kind of pair goes: (vertex of from, face of into), (vertex of into, face of from).
  std::vector<std::array<int, 2>>& fromVertexIntoFace = self ? out.vfAB : (fromIsA ? out.vfAB : out.vfBA);
  std::vector<std::array<int, 2>>& intoVertexFromFace = self ? out.vfAB : (fromIsA ? out.vfBA : out.vfAB);
  const Aabb uBox = sweptBox(from, std::array<int, 1>{u});
  std::array<Aabb, 3> cornerBoxes, sideBoxes;
  for (int t : triangles) {
    const Aabb& faceBox = into.triangleBoxes[t];  // grown already
    const auto& corners = intoMesh.triangles[t];
    const auto& sides = intoMesh.triangleEdges[t];
    for (int k = 0; k < 3; ++k) {
      cornerBoxes[k] = sweptBox(into, std::array<int, 1>{corners[k]});
      sideBoxes[k] = sweptBox(into, intoMesh.edges[sides[k]]);
    }
    if (!(self && isCorner(corners, u)) && grownOverlap(uBox, growth, faceBox, 0.0)) {
      fromVertexIntoFace.push_back({u, t});
    }
    for (int f : facesAround) {
      const Aabb& ownFace = from.triangleBoxes[f];
      if (!grownOverlap(ownFace, 0.0, faceBox, 0.0)) continue;
      for (int k = 0; k < 3; ++k) {
        if (self && isCorner(fromMesh.triangles[f], corners[k])) continue;
        if (grownOverlap(cornerBoxes[k], growth, ownFace, 0.0)) intoVertexFromFace.push_back({corners[k], f});
      }
    }
    for (std::size_t i = 0; i < edgesAround.size(); ++i) {
      const int e = edgesAround[i];
      if (!grownOverlap(edgeBoxes[i], growth, faceBox, 0.0)) continue;
      for (int k = 0; k < 3; ++k) {
        const int other = sides[k];
        if (self && (other == e || shareVertex(fromMesh.edges[e], intoMesh.edges[other]))) continue;
        if (!grownOverlap(edgeBoxes[i], growth, sideBoxes[k], growth)) continue;
        if (self) {
          out.ee.push_back({std::min(e, other), std::max(e, other)});
        } else {
          out.ee.push_back(fromIsA ? std::array<int, 2>{e, other} : std::array<int, 2>{other, e});
        }
      }
    }
  }
}

void sortUnique(std::vector<std::array<int, 2>>& pairs) {
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

}  // namespace

void findPrimitivePairsTouching(std::vector<ContactBody>& bodies, const ContactPairing& pairing, double margin,
                                const VertexFlags& flags, std::vector<PrimitivePair>& out, bool onlyFlaggedMoved) {
  out.clear();
  std::vector<char> involved(bodies.size(), 0);
  for (const auto& [a, b] : pairing.between) involved[a] = involved[b] = 1;
  for (int a : pairing.self) involved[a] = 1;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!involved[i]) continue;
    if (onlyFlaggedMoved) {
      updateSweptMeshAround(bodies[i].swept, margin, flags[i]);
    } else {
      updateSweptMesh(bodies[i].swept, margin);
    }
  }
  const double growth = boxGrowth(margin);
  std::vector<int> edgesAround, triangles;
  std::vector<Aabb> edgeBoxes;
  TouchingLists lists;
  auto searchFrom = [&](int from, int into, bool fromIsA, bool self) {
    const std::vector<char>& flagged = flags[from];
    for (int u = 0; u < static_cast<int>(flagged.size()); ++u) {
      if (flagged[u]) {
        touchingAround(bodies[from].swept, u, bodies[into].swept, growth, fromIsA, self, edgesAround, edgeBoxes,
                       triangles, lists);
      }
    }
  };
  auto emit = [&](std::vector<std::array<int, 2>>& found, PairKind kind, int bodyA, int bodyB) {
    sortUnique(found);
    for (const auto& [p, q] : found) out.push_back({kind, bodyA, p, bodyB, q});
  };
  for (const auto& [a, b] : pairing.between) {
    lists.clear();
    searchFrom(a, b, true, false);
    searchFrom(b, a, false, false);
    emit(lists.vfAB, PairKind::VertexFace, a, b);
    emit(lists.vfBA, PairKind::VertexFace, b, a);
    emit(lists.ee, PairKind::EdgeEdge, a, b);
  }
  for (int a : pairing.self) {
    lists.clear();
    searchFrom(a, a, true, true);
    emit(lists.vfAB, PairKind::VertexFace, a, a);
    emit(lists.ee, PairKind::EdgeEdge, a, a);
  }
}

double pairFriction(const std::vector<ContactBody>& bodies, const PrimitivePair& pair) {
  const ContactBody& a = bodies[pair.bodyA];
  return a.isCloth() ? bodies[pair.bodyB].friction : a.friction;
}

ContactSide vertexSide(int body, int vertex) {
  ContactSide side;
  side.body = body;
  side.count = 1;
  side.vertex[0] = vertex;
  side.weight[0] = 1.0;
  return side;
}

ContactSide faceSide(const std::vector<ContactBody>& bodies, int body, int face, const double weights[3]) {
  ContactSide side;
  side.body = body;
  side.count = 3;
  const auto& corners = bodies[body].topology->triangles[face];
  for (int k = 0; k < 3; ++k) {
    side.vertex[k] = corners[k];
    side.weight[k] = weights[k];
  }
  return side;
}

ContactSide edgeSide(const std::vector<ContactBody>& bodies, int body, int edge, double parameter) {
  ContactSide side;
  side.body = body;
  side.count = 2;
  const auto& ends = bodies[body].topology->edges[edge];
  side.vertex[0] = ends[0];
  side.vertex[1] = ends[1];
  side.weight[0] = 1.0 - parameter;
  side.weight[1] = parameter;
  return side;
}

}  // namespace weft
