#include "contact/held_contacts.h"

#include <algorithm>
#include <map>
#include <tuple>

#include <Eigen/Geometry>

#include "collision/closest_points.h"
#include "contact/obstacle.h"
#include "sim/cloth.h"

namespace weft {

namespace {

// A cloth point touching an obstacle at the end of the step, as weighted cloth vertices.
struct Touch {
  ContactSide cloth;
  int obstacleBody = 0;
  Vec3 normal = Vec3::Zero();  // out of the obstacle
};

// The pair's closest points at the start of the step when they are within reach, cloth side first.
bool touchOf(const std::vector<ContactBody>& bodies, const PrimitivePair& pair, double reach, Touch& out) {
  const std::vector<Vec3>& xa = *bodies[pair.bodyA].x0;
  const std::vector<Vec3>& xb = *bodies[pair.bodyB].x0;
  const bool clothIsA = bodies[pair.bodyA].isCloth();
  ContactSide a, b;
  Vec3 fromBToA;
  double distance = 0.0;
  if (pair.kind == PairKind::VertexFace) {
    const auto& f = bodies[pair.bodyB].topology->triangles[pair.featureB];
    const PointTriangleClosest c = closestPointOnTriangle(xa[pair.featureA], xb[f[0]], xb[f[1]], xb[f[2]]);
    if (!(c.distance < reach)) return false;
    a = vertexSide(pair.bodyA, pair.featureA);
    b = faceSide(bodies, pair.bodyB, pair.featureB, c.weights);
    distance = c.distance;
    fromBToA = xa[pair.featureA] - c.point;
    if (!(distance > 1e-9)) fromBToA = (xb[f[1]] - xb[f[0]]).cross(xb[f[2]] - xb[f[0]]);
  } else {
    const auto& ea = bodies[pair.bodyA].topology->edges[pair.featureA];
    const auto& eb = bodies[pair.bodyB].topology->edges[pair.featureB];
    const SegmentSegmentClosest c = closestSegmentSegment(xa[ea[0]], xa[ea[1]], xb[eb[0]], xb[eb[1]]);
    if (!(c.distance < reach) || !(c.distance > 1e-9)) return false;
    a = edgeSide(bodies, pair.bodyA, pair.featureA, c.s);
    b = edgeSide(bodies, pair.bodyB, pair.featureB, c.t);
    fromBToA = sidePosition(bodies, a, false) - sidePosition(bodies, b, false);
  }
  if (!(fromBToA.squaredNorm() > 0.0)) return false;
  out.cloth = clothIsA ? a : b;
  out.obstacleBody = clothIsA ? pair.bodyB : pair.bodyA;
  out.normal = (clothIsA ? fromBToA : Vec3(-fromBToA)).normalized();
  return true;
}

}  // namespace

void HeldContacts::collect(const std::vector<ContactBody>& bodies, const std::vector<PrimitivePair>& pairs,
                           const GroundSpec* ground, const std::vector<int>& bodyToWorldIndex, double reach) {
  contacts_.clear();
  if (ground != nullptr) collectGround(bodies, *ground, bodyToWorldIndex, reach);

  // Every touching pair is one share of its obstacle's mass, split over the cloth vertices of its
  // cloth side by their weights; a vertex sums the shares of all the pairs it is part of.
  std::vector<int> touches(bodies.size(), 0);
  std::map<std::tuple<int, int, int>, std::pair<double, Vec3>> perVertex;  // (cloth body, vertex, obstacle body) -> (weight, normal sum)
  for (const PrimitivePair& pair : pairs) {
    if (bodies[pair.bodyA].isCloth() == bodies[pair.bodyB].isCloth()) continue;  // cloth on cloth: not held
    Touch touch;
    if (!touchOf(bodies, pair, reach, touch)) continue;
    ++touches[touch.obstacleBody];
    const ContactBody& cloth = bodies[touch.cloth.body];
    for (int k = 0; k < touch.cloth.count; ++k) {
      const int v = touch.cloth.vertex[k];
      if ((*cloth.inverseMass)[v] == 0.0 || touch.cloth.weight[k] <= 0.0) continue;  // pinned: its pin holds it
      if (std::find(released_.begin(), released_.end(), std::make_pair(bodyToWorldIndex[touch.cloth.body], v)) !=
          released_.end()) {
        continue;
      }
      // (Eigen leaves a default-constructed vector uninitialized: start the sum at zero.)
      auto& entry = perVertex.try_emplace({touch.cloth.body, v, touch.obstacleBody}, 0.0, Vec3::Zero()).first->second;
      entry.first += touch.cloth.weight[k];
      entry.second += touch.cloth.weight[k] * touch.normal;
    }
  }
  for (const auto& [key, entry] : perVertex) {  // map order: deterministic
    const auto [clothBody, vertex, obstacleBody] = key;
    const Obstacle& obstacle = *bodies[obstacleBody].obstacle;
    const Vec3 position = (*bodies[clothBody].x0)[vertex];
    Contact contact;
    contact.cloth = bodyToWorldIndex[clothBody];
    contact.vertex = vertex;
    contact.obstacle = bodyToWorldIndex[obstacleBody];
    contact.sharesMass = obstacle.motion == ObstacleMotion::Dynamic;
    contact.massFraction = entry.first / touches[obstacleBody];
    contact.bodyPoint = obstacle.start.toBody(position);
    contact.bodyNormal = obstacle.start.orientation.conjugate() * entry.second.normalized();
    contacts_.push_back(contact);
  }
  released_.clear();
}

void HeldContacts::collectGround(const std::vector<ContactBody>& bodies, const GroundSpec& ground,
                                 const std::vector<int>& bodyToWorldIndex, double reach) {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const ContactBody& body = bodies[b];
    if (!body.isCloth()) continue;
    for (std::size_t i = 0; i < body.x0->size(); ++i) {
      if ((*body.inverseMass)[i] == 0.0 || !((*body.x0)[i].y() - ground.height < reach)) continue;
      const int cloth = bodyToWorldIndex[b];
      const int vertex = static_cast<int>(i);
      if (std::find(released_.begin(), released_.end(), std::make_pair(cloth, vertex)) != released_.end()) continue;
      Contact contact;
      contact.cloth = cloth;
      contact.vertex = vertex;
      contact.obstacle = kGround;
      contact.bodyNormal = Vec3::UnitY();
      contacts_.push_back(contact);
    }
  }
}

void HeldContacts::prescribe(const std::vector<Cloth>& cloths, const std::vector<Obstacle>& obstacles, double h,
                             std::vector<std::vector<HeldVertex>>& out) const {
  out.assign(cloths.size(), {});
  for (const Contact& c : contacts_) {
    HeldVertex held;
    held.vertex = c.vertex;
    if (c.obstacle == kGround) {
      held.kind = HeldVertex::Kind::NormalSupport;
      held.normal = Vec3::UnitY();
      out[c.cloth].push_back(held);
      continue;
    }
    const Obstacle& obstacle = obstacles[c.obstacle];
    held.velocity = (obstacle.end.toWorld(c.bodyPoint) - obstacle.start.toWorld(c.bodyPoint)) / h;
    held.normal = obstacle.start.orientation * c.bodyNormal;
    if (c.sharesMass) {
      held.kind = HeldVertex::Kind::ShareMass;
      held.massShare = c.massFraction * obstacle.body.mass;
    } else {
      held.kind = HeldVertex::Kind::NormalSupport;
    }
    out[c.cloth].push_back(held);
  }
}

void HeldContacts::applyReactions(const std::vector<Cloth>& cloths, std::vector<Obstacle>& obstacles,
                                  const std::vector<std::vector<HeldVertex>>& held, double h) {
  std::vector<std::size_t> next(cloths.size(), 0);
  for (const Contact& c : contacts_) {
    const HeldVertex& vertex = held[c.cloth][next[c.cloth]++];
    // The obstacle should push the vertex out of its surface; a pull means the cloth is leaving.
    if (vertex.reaction.dot(vertex.normal) < 0.0) released_.emplace_back(c.cloth, c.vertex);
    if (c.obstacle == kGround || !c.sharesMass) continue;  // infinitely heavy: nothing to push back
    Obstacle& obstacle = obstacles[c.obstacle];
    applyObstacleImpulse(obstacle, -vertex.reaction, obstacle.start.toWorld(c.bodyPoint), h);
  }
}

}  // namespace weft
