#pragma once
// The three passes of Bridson, Fedkiw & Anderson 2002 ("Robust treatment of collisions, contact
// and friction for cloth animation", §7), as the thesis uses them (§2.6, §3.3):
//   1. proximity: pairs closer than the cloth thickness at the start of the step get a repulsion
//      impulse (and friction), which handles resting contact and most collisions cheaply;
//   2. collisions: iterated continuous collision detection over the step; each colliding pair gets
//      an inelastic impulse, until an iteration finds none or the iteration bound is hit;
//   3. rigid impact zones: what pass 2 leaves is merged into zones that move rigidly for the step,
//      which cannot collide among themselves (Provot 1997).
// Each pass reads and changes the bodies' velocities and end positions (contact_body.h).
#include <vector>

#include "collision/candidate_pairs.h"
#include "contact/contact_body.h"
#include "contact/contact_pairs.h"
#include "contact/near_pairs.h"
#include "contact/pair_cache.h"
#include "scene/contact_spec.h"

namespace weft {

struct ContactStepSettings {
  double h = 0.0;               // step (s)
  double thickness = 0.0;       // cloth thickness (m)
  const GroundSpec* ground = nullptr;  // null: no ground
  int ccdIterations = 8;
  int impactZoneIterations = 50;
  bool recheckAllPairs = false;  // pass 2: every pair in every iteration (ContactSpec::recheckAllPairs)
};

// A sharp tool feature that hit the cloth in pass 2 (thesis §3.3): read by cutting.
struct SharpContactRecord {
  enum class Kind { ToolEdgeClothEdge, ToolVertexClothFace };
  Kind kind = Kind::ToolEdgeClothEdge;
  int cloth = 0;             // cloth index in the world
  int obstacle = 0;          // obstacle index in the world
  int clothFeature[2] = {0, 0};  // cloth edge's two vertex ids, or the cloth triangle id (first entry)
  int toolFeature[2] = {0, 0};   // tool edge's two vertex ids, or the tool vertex id (first entry)
  Vec3 point = Vec3::Zero();     // contact point at the time of impact (world, m)
  double time = 0.0;             // time of impact as a fraction of the step, in [0, 1]
  double normalSpeed = 0.0;      // closing speed along the contact normal (m/s), > 0
  double effectiveMass = 0.0;    // of the pair along the normal (kg); infinite mass gives +inf
};

struct PassCounts {
  long long proximityImpulses = 0;
  long long groundContacts = 0;
  long long ccdCollisions = 0;
  int ccdIterations = 0;
  int impactZoneRounds = 0;
  long long impactZones = 0;
  bool unresolved = false;  // pass 3 hit its bound with collisions left
};

// Pass 1, on the pairs near each other at the start of the step (measured with a reach of at
// least the thickness).
void runProximityPass(std::vector<ContactBody>& bodies, const std::vector<NearPair>& nearPairs,
                      const ContactStepSettings& settings, PassCounts& counts);

// Some of the body pairs to test, with the cache that keeps their near pairs (null: none).
struct PairingPart {
  const ContactPairing* pairing = nullptr;
  PairCache* cache = nullptr;
};

// Pass 2 over the body pairs of `parts`, in that order. Returns true when the last iteration found
// no collision. Each iteration takes a part's pairs from its cache when it can answer, else
// searches afresh.
bool runCollisionPass(std::vector<ContactBody>& bodies, const std::vector<PairingPart>& parts,
                      const ContactStepSettings& settings, const std::vector<int>& bodyToWorldIndex,
                      CandidatePairs& scratch, std::vector<PrimitivePair>& pairs, PassCounts& counts,
                      std::vector<SharpContactRecord>& records);

// Pass 3.
void runImpactZonePass(std::vector<ContactBody>& bodies, const ContactPairing& pairing,
                       const ContactStepSettings& settings, CandidatePairs& scratch,
                       std::vector<PrimitivePair>& pairs, PassCounts& counts);

// The colliding pairs among `pairs` in the bodies' current state: a CCD hit whose relative normal
// velocity is short of what keeps the pair apart at the end of the step. Shared by passes 2 and 3.
struct Collision {
  PrimitivePair pair;
  ContactSide a, b;       // b's side of the contact and a's
  Vec3 normal;            // from b towards a
  double time = 0.0;      // fraction of the step
  double targetNormalVelocity = 0.0;
};
bool detectCollision(const std::vector<ContactBody>& bodies, const PrimitivePair& pair,
                     const ContactStepSettings& settings, Collision& out);
// Any CCD hit of the pair over the step, whatever the velocities (pass 3 merges every one: only a
// state with no hit at all is safe).
bool detectCrossing(const std::vector<ContactBody>& bodies, const PrimitivePair& pair, Collision& out);

// Cloth vertices that would end the step below the ground plane stop just above it (an exact
// test: the plane is flat, so no edge or face can cross it without a vertex). Returns how many;
// flags them in `moved` when given.
long long stopAtGround(std::vector<ContactBody>& bodies, const ContactStepSettings& settings,
                       VertexFlags* moved = nullptr);

}  // namespace weft
