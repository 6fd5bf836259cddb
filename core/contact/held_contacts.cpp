#include "contact/held_contacts.h"

#include <algorithm>
#include <tuple>

#include <Eigen/Geometry>

#include "contact/obstacle.h"
#include "sim/cloth.h"

namespace weft {

void HeldContacts::collect(const std::vector<ContactBody>& bodies, const std::vector<NearPair>& nearPairs,
                           const GroundSpec* ground, const std::vector<int>& bodyToWorldIndex, double reach) {
  contacts_.clear();
  std::sort(released_.begin(), released_.end());  // looked up once per touching pair below
  if (ground != nullptr) collectGround(bodies, *ground, bodyToWorldIndex, reach);

  // Every touching pair is one share of its obstacle's mass, split over the cloth vertices of its
  // cloth side by their weights; a vertex sums the shares of all the pairs it is part of.
  std::vector<int> touches(bodies.size(), 0);
  shares_.clear();
  firstShare_.resize(bodies.size());
  for (const NearPair& near : nearPairs) {
    const bool clothIsA = bodies[near.pair.bodyA].isCloth();
    if (clothIsA == bodies[near.pair.bodyB].isCloth() || !(near.distance < reach)) continue;  // cloth on cloth: not held
    const ContactSide& clothSide = clothIsA ? near.a : near.b;
    const int obstacleBody = clothIsA ? near.pair.bodyB : near.pair.bodyA;
    Vec3 normal = clothIsA ? near.normal : Vec3(-near.normal);  // out of the obstacle
    if (near.touching) {  // no reliable direction: take the side the cloth is on relative to the body's centre
      const Vec3 centre = bodies[obstacleBody].obstacle->start.position;
      if (normal.dot(sidePosition(bodies, clothSide, false) - centre) < 0.0) normal = -normal;
    }
    ++touches[obstacleBody];
    const ContactBody& cloth = bodies[clothSide.body];
    std::vector<int>& first = firstShare_[clothSide.body];
    if (first.size() != cloth.x0->size()) first.assign(cloth.x0->size(), -1);
    for (int k = 0; k < clothSide.count; ++k) {
      const int v = clothSide.vertex[k];
      if ((*cloth.inverseMass)[v] == 0.0 || clothSide.weight[k] <= 0.0) continue;  // pinned: its pin holds it
      if (wasReleased(bodyToWorldIndex[clothSide.body], v)) continue;
      // The vertex's share for this obstacle: a short list per vertex (one entry per obstacle it touches).
      int s = first[v];
      while (s >= 0 && shares_[s].obstacleBody != obstacleBody) s = shares_[s].next;
      if (s < 0) {
        s = static_cast<int>(shares_.size());
        shares_.push_back({clothSide.body, v, obstacleBody, first[v], 0.0, Vec3::Zero()});
        first[v] = s;
      }
      shares_[s].weight += clothSide.weight[k];
      shares_[s].normalSum += clothSide.weight[k] * normal;
    }
  }
  // In (cloth body, vertex, obstacle body) order: deterministic, whatever order the pairs came in.
  shareOrder_.resize(shares_.size());
  for (std::size_t s = 0; s < shares_.size(); ++s) {
    shareOrder_[s] = static_cast<int>(s);
    firstShare_[shares_[s].clothBody][shares_[s].vertex] = -1;  // ready for the next step
  }
  std::sort(shareOrder_.begin(), shareOrder_.end(), [&](int p, int q) {
    const Share &a = shares_[p], &b = shares_[q];
    return std::tie(a.clothBody, a.vertex, a.obstacleBody) < std::tie(b.clothBody, b.vertex, b.obstacleBody);
  });
  for (int s : shareOrder_) {
    const Share& share = shares_[s];
    const Obstacle& obstacle = *bodies[share.obstacleBody].obstacle;
    const Vec3 position = (*bodies[share.clothBody].x0)[share.vertex];
    Contact contact;
    contact.cloth = bodyToWorldIndex[share.clothBody];
    contact.vertex = share.vertex;
    contact.obstacle = bodyToWorldIndex[share.obstacleBody];
    contact.sharesMass = obstacle.motion == ObstacleMotion::Dynamic;
    contact.massFraction = share.weight / touches[share.obstacleBody];
    contact.bodyPoint = obstacle.start.toBody(position);
    contact.bodyNormal = obstacle.start.orientation.conjugate() * share.normalSum.normalized();
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
      if (wasReleased(cloth, vertex)) continue;
      Contact contact;
      contact.cloth = cloth;
      contact.vertex = vertex;
      contact.obstacle = kGround;
      contact.bodyNormal = Vec3::UnitY();
      contacts_.push_back(contact);
    }
  }
}

bool HeldContacts::wasReleased(int cloth, int vertex) const {
  return std::binary_search(released_.begin(), released_.end(), std::make_pair(cloth, vertex));
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
