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

// The box a feature's vertices sweep over the step (x0 to x1), grown by boxGrowth(margin): what
// the swept triangle boxes of the BVH are for triangles.
template <std::size_t N>
Aabb sweptBox(const SweptMesh& m, const std::array<int, N>& ids, double margin) {
  Aabb box;
  for (int v : ids) {
    box.grow((*m.x0)[v]);
    box.grow((*m.x1)[v]);
  }
  box.inflate(boxGrowth(margin));
  return box;
}

// The features of a mesh with a flagged vertex, each once, ascending.
struct FlaggedFeatures {
  std::vector<int> vertices, edges, faces;
};

FlaggedFeatures flaggedFeatures(const CollisionMesh& mesh, const std::vector<char>& flags) {
  FlaggedFeatures f;
  for (int v = 0; v < mesh.vertexCount; ++v) {
    if (!flags[v]) continue;
    f.vertices.push_back(v);
    for (int t : mesh.trianglesAround[v]) {
      f.faces.push_back(t);
      for (int e : mesh.triangleEdges[t]) {
        if (mesh.edges[e][0] == v || mesh.edges[e][1] == v) f.edges.push_back(e);
      }
    }
  }
  for (std::vector<int>* ids : {&f.edges, &f.faces}) {
    std::sort(ids->begin(), ids->end());
    ids->erase(std::unique(ids->begin(), ids->end()), ids->end());
  }
  return f;
}

void sortUnique(std::vector<std::array<int, 2>>& pairs) {
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

// Vertices of A against faces of B with a flagged vertex on either side: each flagged vertex of A
// against B's tree, and each flagged face of B against A's tree (then its triangles' corners).
// `admit` says which (vertex, face) pairs may be listed at all (self: not the face's own corners).
template <class Admit>
void touchingVertexFace(const SweptMesh& a, const FlaggedFeatures& fa, const SweptMesh& b, const FlaggedFeatures& fb,
                        double margin, Admit admit, std::vector<std::array<int, 2>>& out) {
  out.clear();
  for (int v : fa.vertices) {
    b.bvh.overlapping(sweptBox(a, std::array<int, 1>{v}, margin), [&](int f) {
      if (admit(v, f)) out.push_back({v, f});
    });
  }
  for (int f : fb.faces) {
    const Aabb& faceBox = b.triangleBoxes[f];
    a.bvh.overlapping(faceBox, [&](int t) {
      for (int v : a.mesh->triangles[t]) {
        if (admit(v, f) && Bvh::overlapsBox(sweptBox(a, std::array<int, 1>{v}, margin), faceBox)) out.push_back({v, f});
      }
    });
  }
  sortUnique(out);
}

// Edges of A against edges of B with a flagged vertex on either side, as (edge of A, edge of B).
// `admit` says which pairs may be listed at all (self: not an edge with itself or a neighbour).
template <class Admit>
void touchingEdgeEdge(const SweptMesh& a, const FlaggedFeatures& fa, const SweptMesh& b, const FlaggedFeatures& fb,
                      double margin, Admit admit, std::vector<std::array<int, 2>>& out) {
  out.clear();
  auto search = [&](const SweptMesh& from, const std::vector<int>& edges, const SweptMesh& into, bool fromIsA) {
    for (int e : edges) {
      const Aabb box = sweptBox(from, from.mesh->edges[e], margin);
      into.bvh.overlapping(box, [&](int t) {
        for (int other : into.mesh->triangleEdges[t]) {
          const int edgeA = fromIsA ? e : other, edgeB = fromIsA ? other : e;
          if (admit(edgeA, edgeB) && Bvh::overlapsBox(box, sweptBox(into, into.mesh->edges[other], margin))) {
            out.push_back({edgeA, edgeB});
          }
        }
      });
    }
  };
  search(a, fa.edges, b, true);
  if (&a != &b) search(b, fb.edges, a, false);
  sortUnique(out);
}

}  // namespace

void findPrimitivePairsTouching(std::vector<ContactBody>& bodies, const ContactPairing& pairing, double margin,
                                const VertexFlags& flags, std::vector<PrimitivePair>& out, bool onlyFlaggedMoved) {
  out.clear();
  std::vector<char> involved(bodies.size(), 0);
  for (const auto& [a, b] : pairing.between) involved[a] = involved[b] = 1;
  for (int a : pairing.self) involved[a] = 1;
  std::vector<FlaggedFeatures> flagged(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!involved[i]) continue;
    if (onlyFlaggedMoved) {
      updateSweptMeshAround(bodies[i].swept, margin, flags[i]);
    } else {
      updateSweptMesh(bodies[i].swept, margin);
    }
    flagged[i] = flaggedFeatures(*bodies[i].topology, flags[i]);
  }
  std::vector<std::array<int, 2>> found;
  auto emit = [&](PairKind kind, int bodyA, int bodyB) {
    for (const auto& [p, q] : found) out.push_back({kind, bodyA, p, bodyB, q});
  };
  const auto anyPair = [](int, int) { return true; };
  for (const auto& [a, b] : pairing.between) {
    const SweptMesh &A = bodies[a].swept, &B = bodies[b].swept;
    touchingVertexFace(A, flagged[a], B, flagged[b], margin, anyPair, found);
    emit(PairKind::VertexFace, a, b);
    touchingVertexFace(B, flagged[b], A, flagged[a], margin, anyPair, found);
    emit(PairKind::VertexFace, b, a);
    touchingEdgeEdge(A, flagged[a], B, flagged[b], margin, anyPair, found);
    emit(PairKind::EdgeEdge, a, b);
  }
  for (int a : pairing.self) {
    const SweptMesh& A = bodies[a].swept;
    const CollisionMesh& mesh = *A.mesh;
    touchingVertexFace(A, flagged[a], A, flagged[a], margin,
                       [&](int v, int f) { return !isCorner(mesh.triangles[f], v); }, found);
    emit(PairKind::VertexFace, a, a);
    // Each unordered pair once, as (smaller, larger), as findSelfCandidatePairs lists them.
    touchingEdgeEdge(A, flagged[a], A, flagged[a], margin,
                     [&](int e, int f) { return e != f && !shareVertex(mesh.edges[e], mesh.edges[f]); }, found);
    for (auto& pair : found) {
      if (pair[0] > pair[1]) std::swap(pair[0], pair[1]);
    }
    sortUnique(found);
    emit(PairKind::EdgeEdge, a, a);
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
