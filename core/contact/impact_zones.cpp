// Pass 3 of Bridson, Fedkiw & Anderson 2002 (§7.4): rigid impact zones (Provot 1997). Vertices
// that pass 2 could not keep apart are merged into zones, and each zone moves rigidly over the
// step with the momentum of its members. Merging goes on until no collision is left: a zone's
// motion (an affine map of its start positions, x -> x + h (v_c + w x (x - x_c))) keeps four
// coplanar-free points coplanar-free, so no collision can happen inside one zone.
//
// Infinitely heavy members decide the zone's motion: a zone touching an obstacle is carried by
// that obstacle's motion over the step (a dynamic body is treated as kinematic here; this is the
// fail-safe, and momentum exchange already happened in passes 1 and 2); a zone with pinned
// vertices and no obstacle moves with their mean velocity.
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

struct ClothVertexIndex {
  std::vector<int> offset;  // first global id of each body (-1: not a cloth)
  std::vector<std::pair<int, int>> owner;  // global id -> (body, vertex)
};

ClothVertexIndex indexClothVertices(const std::vector<ContactBody>& bodies) {
  ClothVertexIndex index;
  index.offset.assign(bodies.size(), -1);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!bodies[b].isCloth()) continue;
    index.offset[b] = static_cast<int>(index.owner.size());
    for (std::size_t i = 0; i < bodies[b].x0->size(); ++i) index.owner.emplace_back(static_cast<int>(b), static_cast<int>(i));
  }
  return index;
}

void mergeCollision(const std::vector<ContactBody>& bodies, const ClothVertexIndex& index, const Collision& c,
                    ZoneSets& zones) {
  int first = -1;
  int obstacle = -1;
  for (const ContactSide* side : {&c.a, &c.b}) {
    if (!bodies[side->body].isCloth()) {
      obstacle = side->body;
      continue;
    }
    for (int k = 0; k < side->count; ++k) {
      const int id = index.offset[side->body] + side->vertex[k];
      if (first < 0) first = id;
      zones.unite(first, id);
    }
  }
  if (first >= 0 && obstacle >= 0) zones.attachObstacle(first, obstacle);
}

// The velocity of each member of one zone (members as global ids).
void moveZoneRigidly(std::vector<ContactBody>& bodies, const ClothVertexIndex& index, const std::vector<int>& members,
                     int obstacleBody, double h) {
  auto vertex = [&](int id) -> std::pair<ContactBody&, int> {
    const auto [b, i] = index.owner[id];
    return {bodies[b], i};
  };
  auto setVelocity = [&](int id, const Vec3& velocity) {
    auto [body, i] = vertex(id);
    if ((*body.inverseMass)[i] == 0.0) return;  // pinned: keeps its scripted motion
    (*body.v)[i] = velocity;
    (*body.x1)[i] = (*body.x0)[i] + h * velocity;
  };

  if (obstacleBody >= 0) {
    const Obstacle& obstacle = *bodies[obstacleBody].obstacle;
    for (int id : members) {
      auto [body, i] = vertex(id);
      setVelocity(id, (carriedByObstacle(obstacle, (*body.x0)[i]) - (*body.x0)[i]) / h);
    }
    return;
  }
  Vec3 pinnedVelocity = Vec3::Zero();
  int pinned = 0;
  double mass = 0.0;
  Vec3 centre = Vec3::Zero(), momentum = Vec3::Zero();
  for (int id : members) {
    auto [body, i] = vertex(id);
    const double inverseMass = (*body.inverseMass)[i];
    if (inverseMass == 0.0) {
      pinnedVelocity += (*body.v)[i];
      ++pinned;
      continue;
    }
    const double m = 1.0 / inverseMass;
    mass += m;
    centre += m * (*body.x0)[i];
    momentum += m * (*body.v)[i];
  }
  if (pinned > 0) {
    for (int id : members) setVelocity(id, pinnedVelocity / pinned);
    return;
  }
  if (!(mass > 0.0)) return;
  centre /= mass;
  const Vec3 velocity = momentum / mass;
  // Angular momentum and inertia about the centre of mass.
  Vec3 angularMomentum = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
  for (int id : members) {
    auto [body, i] = vertex(id);
    const double m = 1.0 / (*body.inverseMass)[i];
    const Vec3 r = (*body.x0)[i] - centre;
    angularMomentum += m * r.cross((*body.v)[i] - velocity);
    inertia += m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
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
    auto [body, i] = vertex(id);
    setVelocity(id, velocity + spin.cross((*body.x0)[i] - centre));
  }
}

}  // namespace

void runImpactZonePass(std::vector<ContactBody>& bodies, const ContactPairing& pairing,
                       const ContactStepSettings& settings, CandidatePairs& scratch,
                       std::vector<PrimitivePair>& pairs, PassCounts& counts) {
  const ClothVertexIndex index = indexClothVertices(bodies);
  ZoneSets zones(static_cast<int>(index.owner.size()));
  long long zoneCount = 0;  // zones moving rigidly after the latest round
  for (int round = 0; round < settings.impactZoneIterations; ++round) {
    ++counts.impactZoneRounds;
    long long collisions = settings.ground != nullptr ? stopAtGround(bodies, settings) : 0;
    findPrimitivePairs(bodies, pairing, 0.0, scratch, pairs);
    for (const PrimitivePair& pair : pairs) {
      Collision c;
      if (!detectCollision(bodies, pair, settings, c)) continue;
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
      moveZoneRigidly(bodies, index, members[root], zones.obstacle(root), settings.h);
    }
  }
  counts.impactZones += zoneCount;
  counts.unresolved = true;
}

}  // namespace weft
