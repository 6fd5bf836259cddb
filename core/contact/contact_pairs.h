#pragma once
// The broad phase of every pass: which bodies are tested against which, and the primitive pairs
// (vertex-face, edge-edge) whose swept boxes overlap, in one deterministic list.
#include <utility>
#include <vector>

#include "contact/contact_body.h"

namespace weft {

enum class PairKind { VertexFace, EdgeEdge };

// VertexFace: vertex featureA of body A against triangle featureB of body B.
// EdgeEdge: edge featureA of body A against edge featureB of body B (CollisionMesh edge ids).
struct PrimitivePair {
  PairKind kind = PairKind::VertexFace;
  int bodyA = 0, featureA = 0;
  int bodyB = 0, featureB = 0;
};

// Body pairs to test: (a, b) with a != b, and bodies tested against themselves.
struct ContactPairing {
  std::vector<std::pair<int, int>> between;
  std::vector<int> self;
  bool empty() const { return between.empty() && self.empty(); }
};

// A flag per vertex of each body (indexed like the bodies).
using VertexFlags = std::vector<std::vector<char>>;

// Refreshes every involved body's swept boxes (grown by margin), then lists the candidate pairs.
void findPrimitivePairs(std::vector<ContactBody>& bodies, const ContactPairing& pairing, double margin,
                        CandidatePairs& scratch, std::vector<PrimitivePair>& out);

// The pairs findPrimitivePairs would list (or more: boxes only, no plane culling) that have a
// flagged vertex, in its order, found from the flagged vertices' features alone: what pass 2's
// later iterations need when few vertices moved. Refreshes the involved bodies' swept boxes: all
// of them, or, with `onlyFlaggedMoved` (the boxes were last refreshed by a search with this
// margin, and only flagged vertices have moved since), those around the flagged vertices.
void findPrimitivePairsTouching(std::vector<ContactBody>& bodies, const ContactPairing& pairing, double margin,
                                const VertexFlags& flags, std::vector<PrimitivePair>& out,
                                bool onlyFlaggedMoved = false);

// The Coulomb coefficient of a pair: the obstacle's against cloth, or cloth on cloth.
double pairFriction(const std::vector<ContactBody>& bodies, const PrimitivePair& pair);

// The two sides of a vertex-face pair given the face weights, or of an edge-edge pair given the
// parameters along each edge.
ContactSide vertexSide(int body, int vertex);
ContactSide faceSide(const std::vector<ContactBody>& bodies, int body, int face, const double weights[3]);
ContactSide edgeSide(const std::vector<ContactBody>& bodies, int body, int edge, double parameter);

}  // namespace weft
