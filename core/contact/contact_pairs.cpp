#include "contact/contact_pairs.h"

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

bool pairTouches(const std::vector<ContactBody>& bodies, const PrimitivePair& pair, const VertexFlags& flags) {
  const std::vector<char>& a = flags[pair.bodyA];
  const std::vector<char>& b = flags[pair.bodyB];
  if (pair.kind == PairKind::VertexFace) {
    const auto& face = bodies[pair.bodyB].topology->triangles[pair.featureB];
    return a[pair.featureA] | b[face[0]] | b[face[1]] | b[face[2]];
  }
  const auto& edgeA = bodies[pair.bodyA].topology->edges[pair.featureA];
  const auto& edgeB = bodies[pair.bodyB].topology->edges[pair.featureB];
  return a[edgeA[0]] | a[edgeA[1]] | b[edgeB[0]] | b[edgeB[1]];
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
