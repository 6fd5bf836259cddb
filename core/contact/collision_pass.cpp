// Pass 2 of Bridson, Fedkiw & Anderson 2002 (§7.3, first half): iterated continuous collision
// detection over the step, each collision stopped by an inelastic impulse. Also what pass 3 uses
// to find the collisions left.
#include <algorithm>
#include <limits>

#include "collision/ccd.h"
#include "contact/contact_impulse.h"
#include "contact/contact_passes.h"
#include "contact/obstacle.h"

namespace weft {
namespace {

// A stopped pair is left this fraction of the thickness apart at the end of the step, so that the
// next iteration does not find it touching again (the proximity pass of the next step then
// restores the full thickness).
constexpr double kSeparationFraction = 0.1;

}  // namespace

bool detectCrossing(const std::vector<ContactBody>& bodies, const PrimitivePair& pair, Collision& out) {
  const ContactBody& A = bodies[pair.bodyA];
  const ContactBody& B = bodies[pair.bodyB];
  const std::vector<Vec3>&a0 = *A.x0, &a1 = *A.x1, &b0 = *B.x0, &b1 = *B.x1;
  if (pair.kind == PairKind::VertexFace) {
    const int v = pair.featureA;
    const auto& f = B.topology->triangles[pair.featureB];
    const auto hit = vertexFaceCcd(a0[v], b0[f[0]], b0[f[1]], b0[f[2]], a1[v], b1[f[0]], b1[f[1]], b1[f[2]]);
    if (!hit) return false;
    out.a = vertexSide(pair.bodyA, v);
    out.b = faceSide(bodies, pair.bodyB, pair.featureB, hit->weights);
    out.normal = hit->normal;
    out.time = hit->t;
  } else {
    const auto& ea = A.topology->edges[pair.featureA];
    const auto& eb = B.topology->edges[pair.featureB];
    const auto hit = edgeEdgeCcd(a0[ea[0]], a0[ea[1]], b0[eb[0]], b0[eb[1]], a1[ea[0]], a1[ea[1]], b1[eb[0]], b1[eb[1]]);
    if (!hit) return false;
    out.a = edgeSide(bodies, pair.bodyA, pair.featureA, hit->s);
    out.b = edgeSide(bodies, pair.bodyB, pair.featureB, hit->u);
    out.normal = hit->normal;
    out.time = hit->t;
  }
  out.pair = pair;
  return true;
}

namespace {

void recordIfSharp(const std::vector<ContactBody>& bodies, const Collision& c, const ImpulseResult& impulse,
                   const std::vector<int>& bodyToWorldIndex, std::vector<SharpContactRecord>& records) {
  // Only an impact counts: a pair already separating, pushed a little further apart so it ends the
  // step clear, is not a blow that could cut.
  if (!(impulse.normalVelocityBefore < 0.0)) return;
  const PrimitivePair& p = c.pair;
  const ContactBody& A = bodies[p.bodyA];
  const ContactBody& B = bodies[p.bodyB];
  SharpContactRecord record;
  if (p.kind == PairKind::EdgeEdge && A.isCloth() != B.isCloth()) {
    const bool toolIsA = !A.isCloth();
    const ContactBody& tool = toolIsA ? A : B;
    const int toolEdge = toolIsA ? p.featureA : p.featureB;
    if (!isSharpEdge(*tool.obstacle, toolEdge)) return;
    record.kind = SharpContactRecord::Kind::ToolEdgeClothEdge;
    const ContactBody& cloth = toolIsA ? B : A;
    const auto& clothEdge = cloth.topology->edges[toolIsA ? p.featureB : p.featureA];
    const auto& edge = tool.topology->edges[toolEdge];
    record.cloth = bodyToWorldIndex[toolIsA ? p.bodyB : p.bodyA];
    record.obstacle = bodyToWorldIndex[toolIsA ? p.bodyA : p.bodyB];
    record.clothFeature[0] = clothEdge[0];
    record.clothFeature[1] = clothEdge[1];
    record.toolFeature[0] = edge[0];
    record.toolFeature[1] = edge[1];
  } else if (p.kind == PairKind::VertexFace && !A.isCloth() && B.isCloth()) {
    if (!isSharpVertex(*A.obstacle, p.featureA)) return;
    record.kind = SharpContactRecord::Kind::ToolVertexClothFace;
    record.cloth = bodyToWorldIndex[p.bodyB];
    record.obstacle = bodyToWorldIndex[p.bodyA];
    record.clothFeature[0] = p.featureB;
    record.toolFeature[0] = p.featureA;
  } else {
    return;
  }
  // The contact point at the time of impact, on the tool's side.
  const ContactSide& toolSide = A.isCloth() ? c.b : c.a;
  record.point = (1.0 - c.time) * sidePosition(bodies, toolSide, false) + c.time * sidePosition(bodies, toolSide, true);
  record.time = c.time;
  record.normalSpeed = -impulse.normalVelocityBefore;
  record.effectiveMass =
      impulse.inverseMass > 0.0 ? 1.0 / impulse.inverseMass : std::numeric_limits<double>::infinity();
  records.push_back(record);
}

}  // namespace

long long stopAtGround(std::vector<ContactBody>& bodies, const ContactStepSettings& settings, VertexFlags* moved) {
  const GroundSpec& ground = *settings.ground;
  const double rest = ground.height + kSeparationFraction * settings.thickness;
  long long count = 0;
  for (ContactBody& body : bodies) {
    if (!body.isCloth()) continue;
    for (std::size_t i = 0; i < body.x0->size(); ++i) {
      if ((*body.inverseMass)[i] == 0.0 || !((*body.x1)[i].y() < ground.height)) continue;
      Vec3& v = (*body.v)[i];
      applyGroundImpulse(v, (rest - (*body.x0)[i].y()) / settings.h, ground.friction);
      (*body.x1)[i] = (*body.x0)[i] + settings.h * v;
      if (moved) (*moved)[static_cast<std::size_t>(&body - bodies.data())][i] = 1;
      ++count;
    }
  }
  return count;
}


bool detectCollision(const std::vector<ContactBody>& bodies, const PrimitivePair& pair,
                     const ContactStepSettings& settings, Collision& out) {
  if (!detectCrossing(bodies, pair, out)) return false;
  // Separation along the normal at the start (>= 0 up to rounding: the normal points to a's side
  // at t = 0), and the relative normal velocity that ends the step a small gap apart.
  const double startGap =
      std::max(0.0, out.normal.dot(sidePosition(bodies, out.a, false) - sidePosition(bodies, out.b, false)));
  out.targetNormalVelocity = (kSeparationFraction * settings.thickness - startGap) / settings.h;
  const double normalVelocity =
      out.normal.dot(sideVelocity(bodies, out.a, settings.h) - sideVelocity(bodies, out.b, settings.h));
  return normalVelocity < out.targetNormalVelocity;
}

namespace {

// Flags the vertices of a crossing pair's two features: an impulse of this iteration may move
// them, and even unmoved the pair crosses again in the next iteration, where an impulse met
// before it may turn it into a collision. A dynamic obstacle is flagged whole: an impulse moves
// its whole pose.
void flagCrossingPair(const std::vector<ContactBody>& bodies, const PrimitivePair& pair, VertexFlags& flags) {
  auto flagFeature = [&](int body, bool isVertex, bool isFace, int feature) {
    const ContactBody& b = bodies[body];
    std::vector<char>& bodyFlags = flags[body];
    if (!b.isCloth() && b.obstacle->motion == ObstacleMotion::Dynamic) {
      std::fill(bodyFlags.begin(), bodyFlags.end(), char{1});
    } else if (isVertex) {
      bodyFlags[feature] = 1;
    } else if (isFace) {
      for (int v : b.topology->triangles[feature]) bodyFlags[v] = 1;
    } else {
      for (int v : b.topology->edges[feature]) bodyFlags[v] = 1;
    }
  };
  const bool vertexFace = pair.kind == PairKind::VertexFace;
  flagFeature(pair.bodyA, vertexFace, false, pair.featureA);
  flagFeature(pair.bodyB, false, vertexFace, pair.featureB);
}

}  // namespace

bool runCollisionPass(std::vector<ContactBody>& bodies, const std::vector<PairingPart>& parts,
                      const ContactStepSettings& settings, const std::vector<int>& bodyToWorldIndex,
                      CandidatePairs& scratch, std::vector<PrimitivePair>& pairs, PassCounts& counts,
                      std::vector<SharpContactRecord>& records) {
  std::vector<PrimitivePair> crossing, partPairs;
  // After the first iteration, only a pair with a vertex flagged by the last one (stopped at the
  // ground, or in a crossing pair) can cross: every other pair is where it was when it was last
  // tested, and did not cross then. So each later iteration looks at those pairs only (Bridson,
  // Fedkiw & Anderson 2002 §7.3 go over the whole list each time; the crossings met, their order
  // and every impulse are the same).
  VertexFlags flagged(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) flagged[b].assign(bodies[b].x0->size(), 0);
  // Per part: its bodies' swept boxes were refreshed by its own search in the last iteration (not
  // served by a cache), so the next search needs to refresh only those around flagged vertices.
  std::vector<char> searchedLast(parts.size(), 0);
  for (int iteration = 0; iteration < settings.ccdIterations; ++iteration) {
    ++counts.ccdIterations;
    const VertexFlags* onlyTouching = iteration == 0 || settings.recheckAllPairs ? nullptr : &flagged;
    long long collisions = settings.ground != nullptr ? stopAtGround(bodies, settings, &flagged) : 0;
    counts.groundContacts += collisions;
    pairs.clear();
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const PairingPart& part = parts[k];
      if (part.pairing->empty()) continue;
      const ContactPairing& pairing = *part.pairing;
      const bool served =
          part.cache &&
          part.cache->findPairs(bodies, pairing, 0.0, PairCache::Span::WholeStep, settings.h, partPairs, onlyTouching);
      if (!served) {
        if (onlyTouching) {
          findPrimitivePairsTouching(bodies, pairing, 0.0, flagged, partPairs, searchedLast[k] != 0);
        } else {
          findPrimitivePairs(bodies, pairing, 0.0, scratch, partPairs);
        }
      }
      searchedLast[k] = served ? 0 : 1;
      pairs.insert(pairs.end(), partPairs.begin(), partPairs.end());
    }
    for (std::vector<char>& flags : flagged) std::fill(flags.begin(), flags.end(), char{0});
    // Only the pairs that cross in the state the iteration starts from are stopped in it: those
    // are the same whichever search listed them (the pair cache lists more candidates than a
    // fresh search), so the result never depends on the search. A collision that an impulse of
    // this iteration causes is the next iteration's.
    crossing.clear();
    Collision hit;
    for (const PrimitivePair& pair : pairs) {
      if (!detectCrossing(bodies, pair, hit)) continue;
      crossing.push_back(pair);
      flagCrossingPair(bodies, pair, flagged);
    }
    for (const PrimitivePair& pair : crossing) {
      Collision c;
      if (!detectCollision(bodies, pair, settings, c)) continue;
      const ImpulseResult impulse =
          applyContactImpulse(bodies, c.a, c.b, c.normal, c.targetNormalVelocity, pairFriction(bodies, pair), settings.h);
      ++collisions;  // one that no impulse can stop (both sides infinitely heavy) is left to pass 3
      if (!impulse.applied) continue;
      ++counts.ccdCollisions;
      recordIfSharp(bodies, c, impulse, bodyToWorldIndex, records);
    }
    if (collisions == 0) return true;
  }
  return false;
}

}  // namespace weft
