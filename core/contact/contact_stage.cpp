#include "contact/contact_stage.h"

#include "contact/cloth_collision_mesh.h"
#include "contact/obstacle.h"
#include "sim/cloth.h"

namespace weft {
namespace {

void copyRestCorners(const ClothMesh& mesh, RestCorners& out) {
  out.resize(mesh.tris.size());
  for (std::size_t t = 0; t < mesh.tris.size(); ++t) out[t] = mesh.tris[t].rest;
}

}  // namespace

ContactStage::ContactStage(const Scene& scene) : spec_(scene.contact), ground_(scene.ground) {
  const int clothCount = static_cast<int>(scene.cloths.size());
  const int obstacleCount = static_cast<int>(scene.obstacles.size());
  if (scene.stages.collision) {
    for (int c = 0; c < clothCount; ++c) {
      if (spec_.obstacles) {
        for (int o = 0; o < obstacleCount; ++o) obstaclePairing_.between.emplace_back(c, clothCount + o);
      }
      if (spec_.self) {
        clothPairing_.self.push_back(c);
        for (int other = c + 1; other < clothCount; ++other) clothPairing_.between.emplace_back(c, other);
      }
    }
  }
  // Every body pair: the obstacles' first, as pass 2 meets them (one part after the other).
  pairing_ = obstaclePairing_;
  pairing_.between.insert(pairing_.between.end(), clothPairing_.between.begin(), clothPairing_.between.end());
  pairing_.self = clothPairing_.self;
  const bool groundRuns = scene.stages.collision && spec_.obstacles && ground_.enabled;
  if (!groundRuns) ground_.enabled = false;
  runs_ = !pairing_.empty() || groundRuns;
  selfCollision_ = !pairing_.self.empty();
  obstacleCache_ = PairCache(kSkinPerThickness * spec_.thickness, kObstacleMostReanchoredShare);
  obstacleCache_.add(obstaclePairing_, holdReach());
  clothCache_ = PairCache(kSkinPerThickness * spec_.thickness);
  clothCache_.add(clothPairing_, spec_.thickness);
  // The implicit integrators hold them; BDF2 then takes a backward Euler step (integrate/bdf2.h).
  holdsVertices_ = (!obstaclePairing_.empty() || ground_.enabled) &&
                   scene.solver.integrator != IntegratorKind::SymplecticEuler;
  bodies_.resize(static_cast<std::size_t>(clothCount + obstacleCount));
  clothTopology_.resize(static_cast<std::size_t>(clothCount));
  clothRest_.resize(static_cast<std::size_t>(clothCount));
  clothInverseMass_.resize(static_cast<std::size_t>(clothCount));
  for (int c = 0; c < clothCount; ++c) bodyToWorldIndex_.push_back(c);
  for (int o = 0; o < obstacleCount; ++o) bodyToWorldIndex_.push_back(o);
}

void ContactStage::reconfigure(const Scene& scene) {
  const ContactStats kept = stats_;
  *this = ContactStage(scene);
  stats_ = kept;
}

void ContactStage::refreshBodies(std::vector<Cloth>& cloths, const std::vector<std::vector<Vec3>>& startPositions,
                                 std::vector<Obstacle>& obstacles) {
  for (std::size_t c = 0; c < cloths.size(); ++c) {
    ClothMesh& mesh = cloths[c].mesh;
    CollisionMesh& topology = clothTopology_[c];
    // First use, or a change nobody reported (clothTopologyChanged keeps the counts in step).
    if (topology.vertexCount != mesh.vertexCount() ||
        topology.triangles.size() != static_cast<std::size_t>(mesh.triangleCount())) {
      topology = makeClothCollisionMesh(mesh);
      copyRestCorners(mesh, clothRest_[c]);
    }
    std::vector<double>& inverseMass = clothInverseMass_[c];
    inverseMass.resize(static_cast<std::size_t>(mesh.vertexCount()));
    for (int i = 0; i < mesh.vertexCount(); ++i) {
      inverseMass[i] = mesh.pinned[i] || !(mesh.mass[i] > 0.0) ? 0.0 : 1.0 / mesh.mass[i];
    }
    ContactBody& body = bodies_[c];
    body.topology = &topology;
    body.x0 = &startPositions[c];
    body.x1 = &mesh.x;
    body.v = &mesh.v;
    body.inverseMass = &inverseMass;
    body.obstacle = nullptr;
    body.friction = spec_.selfFriction;
    body.swept.mesh = &topology;
    body.swept.x0 = body.x0;
    body.swept.x1 = body.x1;
    body.swept.rest = &clothRest_[c];
  }
  for (std::size_t o = 0; o < obstacles.size(); ++o) {
    Obstacle& obstacle = obstacles[o];
    ContactBody& body = bodies_[cloths.size() + o];
    body.topology = &obstacle.topology;
    body.x0 = &obstacle.x0;
    body.x1 = &obstacle.x1;
    body.v = nullptr;
    body.inverseMass = nullptr;
    body.obstacle = &obstacle;
    body.friction = obstacle.friction;
    body.swept.mesh = &obstacle.topology;
    body.swept.x0 = body.x0;
    body.swept.x1 = body.x1;
    body.swept.rest = nullptr;
  }
}

PairCacheStats ContactStage::pairCacheStats() const {
  PairCacheStats sum = obstacleCache_.stats();
  sum += clothCache_.stats();
  return sum;
}

void ContactStage::countPairCache(const PairCacheStats& before) { stats_.pairCache += pairCacheStats() - before; }

void ContactStage::clothTopologyChanged(int cloth, const ClothMesh& mesh, const TopologyChange& change) {
  CollisionMesh& topology = clothTopology_[cloth];
  if (topology.triangles.empty()) return;  // not built yet: refreshBodies builds it
  const CollisionMeshChange edit = updateClothCollisionMesh(topology, mesh, change);
  copyRestCorners(mesh, clothRest_[cloth]);
  SweptMesh& swept = bodies_[cloth].swept;
  if (swept.mesh == &topology) patchSweptMesh(swept, edit);
}

void ContactStage::resolve(std::vector<Cloth>& cloths, const std::vector<std::vector<Vec3>>& startPositions,
                           std::vector<Obstacle>& obstacles, double h, StageProfile& profile) {
  records_.clear();
  if (!runs_) return;
  refreshBodies(cloths, startPositions, obstacles);
  ContactStepSettings settings;
  settings.h = h;
  settings.thickness = spec_.thickness;
  settings.ground = ground_.enabled ? &ground_ : nullptr;
  settings.ccdIterations = spec_.ccdIterations;
  settings.impactZoneIterations = spec_.impactZoneIterations;
  settings.recheckAllPairs = spec_.recheckAllPairs;

  PassCounts counts;
  const PairCacheStats cacheBefore = pairCacheStats();
  {
    StageTimer timer(profile, "contact_proximity");
    runProximityPass(bodies_, nearPairs_, settings, counts);
  }
  bool resolved = false;
  {
    StageTimer timer(profile, "contact_ccd");
    const std::vector<PairingPart> parts{{&obstaclePairing_, spec_.reusePairs ? &obstacleCache_ : nullptr},
                                         {&clothPairing_, spec_.reusePairs ? &clothCache_ : nullptr}};
    resolved = runCollisionPass(bodies_, parts, settings, bodyToWorldIndex_, scratch_, pairs_, counts, records_);
  }
  if (!resolved) {
    StageTimer timer(profile, "contact_impact_zones");
    ++stats_.impactZoneSteps;
    runImpactZonePass(bodies_, pairing_, settings, scratch_, pairs_, counts);
  }
  countPairCache(cacheBefore);
  ++stats_.steps;
  stats_.proximityImpulses += counts.proximityImpulses;
  stats_.groundContacts += counts.groundContacts;
  stats_.ccdCollisions += counts.ccdCollisions;
  stats_.ccdIterations += counts.ccdIterations;
  stats_.impactZoneRounds += counts.impactZoneRounds;
  stats_.impactZones += counts.impactZones;
  stats_.unresolvedSteps += counts.unresolved ? 1 : 0;
  stats_.sharpContacts += static_cast<long long>(records_.size());
}

void ContactStage::prepare(std::vector<Cloth>& cloths, const std::vector<std::vector<Vec3>>& startPositions,
                           std::vector<Obstacle>& obstacles, double h, StageProfile& profile) {
  if (!runs_) return;
  refreshBodies(cloths, startPositions, obstacles);
  {
    // Pass 1 and the held vertices look at the start of the step only: boxes around the start
    // positions (not swept over the step) grown by the reach find every pair both need. Cloth on
    // cloth is never held, so those pairs need only the thickness (a smaller margin finds far
    // fewer pairs in a sheet, whose neighbouring triangles all nearly touch).
    StageTimer timer(profile, "contact_start_pairs");
    const PairCacheStats cacheBefore = pairCacheStats();
    for (ContactBody& body : bodies_) body.swept.x1 = body.x0;
    auto findStartPairs = [&](const ContactPairing& pairing, PairCache& cache, double reach) {
      if (!spec_.reusePairs || !cache.findPairs(bodies_, pairing, reach, PairCache::Span::Start, h, startPairs_)) {
        findPrimitivePairs(bodies_, pairing, reach, scratch_, startPairs_);
      }
    };
    findStartPairs(obstaclePairing_, obstacleCache_, holdReach());
    measureNearPairs(bodies_, startPairs_, holdReach(), nearPairs_);
    if (!clothPairing_.empty()) {
      findStartPairs(clothPairing_, clothCache_, spec_.thickness);
      measureNearPairs(bodies_, startPairs_, spec_.thickness, nearClothPairs_);
      nearPairs_.insert(nearPairs_.end(), nearClothPairs_.begin(), nearClothPairs_.end());
    }
    for (ContactBody& body : bodies_) body.swept.x1 = body.x1;
    countPairCache(cacheBefore);
  }
  if (!holdsVertices_) return;
  StageTimer timer(profile, "contact_held");
  held_.collect(bodies_, nearPairs_, ground_.enabled ? &ground_ : nullptr, bodyToWorldIndex_, holdReach());
  held_.prescribe(cloths, obstacles, h, heldVertices_);
  stats_.heldVertices += static_cast<long long>(held_.size());
}

std::vector<HeldVertex>* ContactStage::heldVertices(int cloth) {
  if (!holdsVertices_ || heldVertices_[cloth].empty()) return nullptr;
  return &heldVertices_[cloth];
}

void ContactStage::applyHeldReactions(const std::vector<Cloth>& cloths, std::vector<Obstacle>& obstacles, double h) {
  if (!holdsVertices_) return;
  held_.applyReactions(cloths, obstacles, heldVertices_, h);
}

}  // namespace weft
