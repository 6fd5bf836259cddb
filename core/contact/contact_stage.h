#pragma once
// The collision stage of the step: builds what the three passes (contact_passes.h) see of the
// cloths and obstacles, runs them, and keeps the statistics and the sharp-contact records.
//
// It runs after the integrator has produced each cloth's candidate end-of-step state and before
// the obstacles commit their poses. A scene with no obstacle, no ground and no self-collision has
// no collision stage at all (runs() is false).
#include <vector>

#include "collision/candidate_pairs.h"
#include "collision/collision_mesh.h"
#include "contact/contact_body.h"
#include "contact/contact_pairs.h"
#include "contact/contact_passes.h"
#include "contact/held_contacts.h"
#include "mesh/cloth_mesh.h"
#include "mesh/topology_change.h"
#include "scene/scene.h"
#include "sim/stage_profile.h"

namespace weft {

struct Cloth;
struct Obstacle;

// Totals since the start of the run.
struct ContactStats {
  long long steps = 0;               // steps the stage ran
  long long proximityImpulses = 0;   // pass 1
  long long groundContacts = 0;      // cloth vertices kept above the ground (passes 1-3)
  long long ccdCollisions = 0;       // pass 2 impulses
  long long ccdIterations = 0;       // pass 2 iterations
  long long impactZoneSteps = 0;     // steps that needed pass 3
  long long impactZoneRounds = 0;    // pass 3 rounds
  long long impactZones = 0;         // zones moved rigidly (summed over steps)
  long long unresolvedSteps = 0;     // steps where pass 3 hit its bound with collisions left
  long long sharpContacts = 0;       // sharp-tool records made
  long long heldVertices = 0;        // cloth vertices held by obstacles or the ground in the solve (summed over steps)
  PairCacheStats pairCache;          // the near pairs kept from step to step (pair_cache.h)
};

class ContactStage {
 public:
  explicit ContactStage(const Scene& scene);
  // After a live edit of what the stage is built from (an obstacle added at runtime, the collision
  // switches, the integrator kind, which decides whether vertices are held): rebuilt from `scene`
  // as the constructor builds it, keeping the statistics. Broad-phase structures are rebuilt at
  // the next step.
  void reconfigure(const Scene& scene);

  bool runs() const { return runs_; }
  bool selfCollision() const { return selfCollision_; }

  // Resolves contact over one (sub)step of length h. startPositions[c] holds cloth c's positions
  // at the start of the step; each cloth's mesh holds the candidate end state (x, v), which is
  // changed in place. Obstacles must have begun the step (beginObstacleStep).
  void resolve(std::vector<Cloth>& cloths, const std::vector<std::vector<Vec3>>& startPositions,
               std::vector<Obstacle>& obstacles, double h, StageProfile& profile);

  // Before the integrators (each cloth's mesh still at its start positions, obstacles begun): the
  // primitive pairs near each other at the start of the step (pass 1 uses them after the solve),
  // and the cloth vertices held in the solve by what they rest on (held_contacts.h).
  // heldVertices(c) is null when cloth c holds none; after the integrators, applyHeldReactions
  // gives dynamic obstacles the opposite of what they gave the cloth.
  void prepare(std::vector<Cloth>& cloths, const std::vector<std::vector<Vec3>>& startPositions,
               std::vector<Obstacle>& obstacles, double h, StageProfile& profile);
  std::vector<HeldVertex>* heldVertices(int cloth);
  void applyHeldReactions(const std::vector<Cloth>& cloths, std::vector<Obstacle>& obstacles, double h);

  // After a tear of cloth `cloth` (`change` already made to `mesh`): edits its collision topology
  // and patches its broad-phase structures locally (cloth_collision_mesh.h, patchSweptMesh).
  // A change it is not told about is still caught by the next step, which then rebuilds them.
  void clothTopologyChanged(int cloth, const ClothMesh& mesh, const TopologyChange& change);

  const ContactStats& stats() const { return stats_; }
  std::size_t heapBytes() const;  // util/heap_bytes.h (defined in sim/world_memory.cpp)
  // Sharp-tool contacts of the latest step (cutting reads these).
  const std::vector<SharpContactRecord>& sharpRecords() const { return records_; }

 private:
  // Adds what the pair cache did since `before` to the statistics.
  PairCacheStats pairCacheStats() const;  // both caches' counts, summed
  void countPairCache(const PairCacheStats& before);
  void refreshBodies(std::vector<Cloth>& cloths, const std::vector<std::vector<Vec3>>& startPositions,
                     std::vector<Obstacle>& obstacles);

  bool runs_ = false;
  bool selfCollision_ = false;
  ContactSpec spec_;
  GroundSpec ground_;
  // One body per cloth, then one per obstacle; kept between steps for their BVHs.
  std::vector<ContactBody> bodies_;
  std::vector<CollisionMesh> clothTopology_;
  // Each cloth's material-space triangle corners, copied with its topology: they change only with
  // it (a tear or cut, reported through clothTopologyChanged) or with a new world.
  std::vector<RestCorners> clothRest_;
  std::vector<std::vector<double>> clothInverseMass_;
  std::vector<int> bodyToWorldIndex_;
  ContactPairing pairing_;
  ContactPairing obstaclePairing_;  // cloths against obstacles
  ContactPairing clothPairing_;     // cloths against themselves and each other
  bool holdsVertices_ = false;     // the integrator takes held vertices (linearized backward Euler)
  HeldContacts held_;
  std::vector<std::vector<HeldVertex>> heldVertices_;
  // The near pairs kept from step to step (pair_cache.h). Its skin, as a multiple of the
  // thickness: a vertex re-anchors after moving half of it.
  // (Measured on weft bench --contact: 0.75, 1.25 and 1.5 were all slower than 1, the last by
  // 1.7x with self-collision, whose in-plane neighbours a larger keep distance lets in.)
  static constexpr double kSkinPerThickness = 1.0;
  // One cache for the pairs with obstacles, one for cloth on cloth, each stepping aside on its
  // own: a pile of layers jittering against each other re-anchors a third of a cloth's vertices
  // every few steps, which costs the cloth's cache more than a fresh search, but costs little
  // against an obstacle's small trees, where the fresh search (the whole cloth grown by the held
  // reach) is dear. So the obstacles' cache keeps answering up to this share of the vertices
  // re-anchored at once.
  static constexpr double kObstacleMostReanchoredShare = 0.6;
  PairCache obstacleCache_, clothCache_;
  CandidatePairs scratch_;
  std::vector<PrimitivePair> pairs_;
  std::vector<PrimitivePair> startPairs_;  // candidate pairs at the start of the step
  std::vector<NearPair> nearPairs_;         // those within the reach, measured
  std::vector<NearPair> nearClothPairs_;
  // Resting cloth sits between a tenth of the thickness (where pass 2 stops a pair) and the
  // thickness (where pass 1 pushes it); a little beyond catches it all, and every extra
  // millimetre of margin adds pairs to measure.
  double holdReach() const { return 1.25 * spec_.thickness; }
  ContactStats stats_;
  std::vector<SharpContactRecord> records_;
};

}  // namespace weft
