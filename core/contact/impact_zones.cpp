// Pass 3 of Bridson, Fedkiw & Anderson 2002 (§7.4): rigid impact zones (Provot 1997). Vertices
// that pass 2 could not keep apart are merged into zones, and each zone moves rigidly over the
// step with the momentum of its members. Merging goes on until no collision is left: a zone's
// motion (an affine map of its start positions, x -> x + h (v_c + w x (x - x_c))) keeps four
// coplanar-free points coplanar-free, so no collision can happen inside one zone.
//
// A dynamic obstacle is a member of the zones it touches, with its mass and inertia, so a zone
// conserves momentum. Infinitely heavy members decide the zone's motion: a zone touching a static
// or kinematic obstacle is carried by that obstacle's motion over the step; a zone with pinned
// vertices and no such obstacle moves with their mean velocity.
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <numeric>

#include "contact/contact_passes.h"
#include "contact/obstacle.h"

namespace weft {
namespace {

class ZoneSets {
 public:
  explicit ZoneSets(int count) : parent_(count), obstacle_(count, -1), size_(count, 1) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(int i, int j) {
    i = find(i);
    j = find(j);
    if (i == j) return;
    if (i > j) std::swap(i, j);  // the lower id stays root: deterministic
    parent_[j] = i;
    size_[i] += size_[j];
    obstacle_[i] = pickObstacle(obstacle_[i], obstacle_[j]);
  }
  void attachObstacle(int i, int body) {
    i = find(i);
    obstacle_[i] = pickObstacle(obstacle_[i], body);
  }
  int obstacle(int root) const { return obstacle_[root]; }
  int size(int root) const { return size_[root]; }

 private:
  static int pickObstacle(int a, int b) { return a < 0 ? b : (b < 0 ? a : std::min(a, b)); }
  std::vector<int> parent_, obstacle_, size_;
};

// The members of zones: every cloth vertex, and every dynamic obstacle as one member (it moves
// with its zone as a whole, with its own mass and inertia). Static and kinematic obstacles are not
// members: a zone touching one is attached to it.
struct ZoneMembers {
  std::vector<int> offset;                 // cloth body: first member id of its vertices; dynamic obstacle: its id; else -1
  std::vector<std::pair<int, int>> owner;  // member id -> (body, vertex), vertex -1 for a rigid body
};

bool isDynamicObstacle(const ContactBody& body) {
  return !body.isCloth() && body.obstacle->motion == ObstacleMotion::Dynamic;
}

ZoneMembers indexMembers(const std::vector<ContactBody>& bodies) {
  ZoneMembers index;
  index.offset.assign(bodies.size(), -1);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].isCloth()) {
      index.offset[b] = static_cast<int>(index.owner.size());
      for (std::size_t i = 0; i < bodies[b].x0->size(); ++i) index.owner.emplace_back(static_cast<int>(b), static_cast<int>(i));
    } else if (isDynamicObstacle(bodies[b])) {
      index.offset[b] = static_cast<int>(index.owner.size());
      index.owner.emplace_back(static_cast<int>(b), -1);
    }
  }
  return index;
}

void mergeCollision(const std::vector<ContactBody>& bodies, const ZoneMembers& index, const Collision& c, ZoneSets& zones) {
  int first = -1;
  int attached = -1;
  auto join = [&](int id) {
    if (first < 0) first = id;
    zones.unite(first, id);
  };
  for (const ContactSide* side : {&c.a, &c.b}) {
    const ContactBody& body = bodies[side->body];
    if (body.isCloth()) {
      for (int k = 0; k < side->count; ++k) join(index.offset[side->body] + side->vertex[k]);
    } else if (isDynamicObstacle(body)) {
      join(index.offset[side->body]);
    } else {
      attached = side->body;
    }
  }
  if (first >= 0 && attached >= 0) zones.attachObstacle(first, attached);
}

// The rigid motion of a zone with no infinitely heavy member: the velocity of its centre of mass
// and the spin that carries its angular momentum, from its cloth vertices (point masses) and
// dynamic bodies (mass and inertia about their own centre).
void moveFreeZone(std::vector<ContactBody>& bodies, const ZoneMembers& index, const std::vector<int>& members, double h) {
  double mass = 0.0;
  Vec3 centre = Vec3::Zero(), momentum = Vec3::Zero();
  for (int id : members) {
    const auto [b, i] = index.owner[id];
    const ContactBody& body = bodies[b];
    const double m = i < 0 ? body.obstacle->body.mass : 1.0 / (*body.inverseMass)[i];
    const Vec3 x = i < 0 ? body.obstacle->start.position : (*body.x0)[i];
    const Vec3 v = i < 0 ? body.obstacle->body.state.linearVelocity : (*body.v)[i];
    mass += m;
    centre += m * x;
    momentum += m * v;
  }
  centre /= mass;
  const Vec3 velocity = momentum / mass;
  Vec3 angularMomentum = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
  for (int id : members) {
    const auto [b, i] = index.owner[id];
    const ContactBody& body = bodies[b];
    const double m = i < 0 ? body.obstacle->body.mass : 1.0 / (*body.inverseMass)[i];
    const Vec3 r = (i < 0 ? body.obstacle->start.position : (*body.x0)[i]) - centre;
    const Vec3 v = i < 0 ? body.obstacle->body.state.linearVelocity : (*body.v)[i];
    angularMomentum += m * r.cross(v - velocity);
    inertia += m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
    if (i < 0) {  // the body's own spin and inertia about its centre
      const RigidBody& rigid = body.obstacle->body;
      const Mat3 rotation = rigid.state.orientation.toRotationMatrix();
      const Mat3 ownInertia = rotation * rigid.inertiaBody * rotation.transpose();
      angularMomentum += ownInertia * rigid.state.angularVelocity;
      inertia += ownInertia;
    }
  }
  // Pseudo-inverse: a zone on a line has no inertia about that line, and no spin about it.
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(inertia);
  const double largest = eigen.eigenvalues().maxCoeff();
  Vec3 spin = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    const double lambda = eigen.eigenvalues()[k];
    if (lambda > 1e-12 * largest) {
      const Vec3 axis = eigen.eigenvectors().col(k);
      spin += axis * (axis.dot(angularMomentum) / lambda);
    }
  }
  for (int id : members) {
    const auto [b, i] = index.owner[id];
    ContactBody& body = bodies[b];
    if (i < 0) {
      setObstacleVelocity(*body.obstacle, velocity + spin.cross(body.obstacle->start.position - centre), spin, h);
    } else {
      (*body.v)[i] = velocity + spin.cross((*body.x0)[i] - centre);
      (*body.x1)[i] = (*body.x0)[i] + h * (*body.v)[i];
    }
  }
}

// A zone with infinitely heavy members: carried by the obstacle it touches, or else moving with the
// mean velocity of its pinned vertices (which keep their scripted motion).
void moveHeldZone(std::vector<ContactBody>& bodies, const ZoneMembers& index, const std::vector<int>& members,
                  int obstacleBody, double h) {
  Vec3 pinnedVelocity = Vec3::Zero();
  int pinned = 0;
  for (int id : members) {
    const auto [b, i] = index.owner[id];
    if (i >= 0 && (*bodies[b].inverseMass)[i] == 0.0) {
      pinnedVelocity += (*bodies[b].v)[i];
      ++pinned;
    }
  }
  if (pinned > 0) pinnedVelocity /= pinned;
  const Obstacle* holder = obstacleBody >= 0 ? bodies[obstacleBody].obstacle : nullptr;
  const PoseChange holderMotion = holder ? PoseChange{holder->start, holder->end, h} : PoseChange{};
  for (int id : members) {
    const auto [b, i] = index.owner[id];
    ContactBody& body = bodies[b];
    if (i < 0) {  // a dynamic body held by the zone: it takes the holder's motion (fail-safe)
      const Vec3 centre = body.obstacle->start.position;
      const Vec3 v = holder ? holderMotion.pointVelocity(centre) : pinnedVelocity;
      setObstacleVelocity(*body.obstacle, v, holder ? holderMotion.angularVelocity() : Vec3::Zero(), h);
      continue;
    }
    if ((*body.inverseMass)[i] == 0.0) continue;  // pinned: keeps its scripted motion
    const Vec3& x0 = (*body.x0)[i];
    (*body.v)[i] = holder ? (carriedByObstacle(*holder, x0) - x0) / h : pinnedVelocity;
    (*body.x1)[i] = x0 + h * (*body.v)[i];
  }
}

bool hasPinnedMember(const std::vector<ContactBody>& bodies, const ZoneMembers& index, const std::vector<int>& members) {
  for (int id : members) {
    const auto [b, i] = index.owner[id];
    if (i >= 0 && (*bodies[b].inverseMass)[i] == 0.0) return true;
  }
  return false;
}

}  // namespace

void runImpactZonePass(std::vector<ContactBody>& bodies, const ContactPairing& pairing,
                       const ContactStepSettings& settings, CandidatePairs& scratch,
                       std::vector<PrimitivePair>& pairs, PassCounts& counts) {
  const ZoneMembers index = indexMembers(bodies);
  ZoneSets zones(static_cast<int>(index.owner.size()));
  long long zoneCount = 0;  // zones moving rigidly after the latest round
  for (int round = 0; round < settings.impactZoneIterations; ++round) {
    ++counts.impactZoneRounds;
    long long collisions = settings.ground != nullptr ? stopAtGround(bodies, settings) : 0;
    findPrimitivePairs(bodies, pairing, 0.0, scratch, pairs);
    for (const PrimitivePair& pair : pairs) {
      Collision c;
      if (!detectCrossing(bodies, pair, c)) continue;
      mergeCollision(bodies, index, c, zones);
      ++collisions;
    }
    if (collisions == 0) {
      counts.impactZones += zoneCount;
      return;
    }

    // Every zone of more than one vertex, or touching an obstacle, moves rigidly.
    std::vector<std::vector<int>> members(index.owner.size());
    for (int id = 0; id < static_cast<int>(index.owner.size()); ++id) {
      const int root = zones.find(id);
      if (zones.size(root) > 1 || zones.obstacle(root) >= 0) members[root].push_back(id);
    }
    zoneCount = 0;
    for (int root = 0; root < static_cast<int>(members.size()); ++root) {
      if (members[root].empty()) continue;
      ++zoneCount;
      const int holder = zones.obstacle(root);
      if (holder >= 0 || hasPinnedMember(bodies, index, members[root])) {
        moveHeldZone(bodies, index, members[root], holder, settings.h);
      } else {
        moveFreeZone(bodies, index, members[root], settings.h);
      }
    }
  }
  counts.impactZones += zoneCount;
  counts.unresolved = true;
}

}  // namespace weft
