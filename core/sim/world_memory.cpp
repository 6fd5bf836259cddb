// World::approximateBytes: what a copy of the world keeps in memory, for the editor's timeline
// budget (a copy per cached frame). It walks the world's parts down to their vectors
// (util/heap_bytes.h); the members of the classes below that keep private state are counted
// here too, so the whole estimate reads in one place. A member added to one of these classes
// belongs here when it can grow with the mesh. Compared with the heap the copies really take
// (glibc's mallinfo2 around World::clone, 30 steps into ball-into-sheet-table4.1-cloth2: 10.80 MB
// taken, 10.81 estimated; sword-into-sheet 3.54 / 3.55; sheet-folds-on-ground 3.77 / 3.77;
// hanging-sheet 0.57 / 0.57), the WorldMemory test keeps the estimate within [0.8, 1.2] of it.
#include "collision/bvh.h"
#include "collision/candidate_pairs.h"
#include "collision/collision_mesh.h"
#include "contact/contact_stage.h"
#include "contact/held_contacts.h"
#include "contact/pair_cache.h"
#include "sim/world.h"
#include "sim/world_impl.h"
#include "tearing/nonlocal_stress.h"
#include "tearing/tear_search.h"
#include "tearing/tear_stage.h"
#include "util/heap_bytes.h"

namespace weft {

std::size_t heapBytes(const CollisionMesh& m) {
  return heapBytes(m.triangles) + heapBytes(m.edges) + heapBytes(m.triangleEdges) + heapBytes(m.vertexOwner) +
         heapBytes(m.edgeOwner) + heapBytes(m.trianglesAround);
}

template <typename T>
std::size_t heapBytes(const TriangleRuns<T>& runs) {
  return heapBytes(runs.begin) + heapBytes(runs.end) + heapBytes(runs.items);
}

std::size_t heapBytes(const OwnedFeatures& f) { return heapBytes(f.ids) + heapBytes(f.boxes); }

std::size_t heapBytes(const MaterialPatches& p) {
  return heapBytes(p.tilesConvexRegion) + heapBytes(p.smallestAltitude) + heapBytes(p.parent) +
         heapBytes(p.triangles) + heapBytes(p.first) + heapBytes(p.last) + heapBytes(p.restInverse);
}

std::size_t heapBytes(const Bvh& bvh) { return bvh.heapBytes(); }

std::size_t heapBytes(const SweptFeatures& f) {
  return heapBytes(f.triangles) + heapBytes(f.vertices) + heapBytes(f.edges) + heapBytes(f.neighbourVertexFace) +
         heapBytes(f.neighbourEdgeEdge) + heapBytes(f.patches);
}

std::size_t heapBytes(const SweptMesh& m) {
  return heapBytes(m.triangleBoxes) + heapBytes(m.planes) + heapBytes(m.bvh) + heapBytes(m.features);
}

std::size_t heapBytes(const ContactBody& body) { return heapBytes(body.swept); }

std::size_t heapBytes(const ContactPairing& p) { return heapBytes(p.between) + heapBytes(p.self); }

std::size_t heapBytes(const CandidatePairs& c) { return heapBytes(c.vfAB) + heapBytes(c.vfBA) + heapBytes(c.ee); }

std::size_t heapBytes(const ClothMesh& m) {
  return heapBytes(m.x) + heapBytes(m.v) + heapBytes(m.mass) + heapBytes(m.pinned) + heapBytes(m.tris) +
         heapBytes(m.edges);
}

std::size_t heapBytes(const PinTrack& pins) {
  return heapBytes(pins.vertices) + heapBytes(pins.start) + heapBytes(pins.script);
}

std::size_t heapBytes(const Cloth& cloth) {
  return heapBytes(cloth.mesh) + heapBytes(cloth.membranes) + heapBytes(cloth.hinges) + heapBytes(cloth.pins);
}

std::size_t heapBytes(const Obstacle& o) {
  return heapBytes(o.bodyVertices) + heapBytes(o.topology) + heapBytes(o.sharpVertex) + heapBytes(o.sharpEdge) +
         heapBytes(o.x0) + heapBytes(o.x1);
}

std::size_t Bvh::heapBytes() const {
  return weft::heapBytes(nodes_) + weft::heapBytes(leafOrder_) + weft::heapBytes(slotBoxes_) +
         weft::heapBytes(leafOfBox_);
}

std::size_t PairCache::heapBytes() const {
  std::size_t bytes = weft::heapBytes(foundScratch_) + weft::heapBytes(mergeScratch_) + weft::heapBytes(groupBoxes_) +
                      weft::heapBytes(entries_) + weft::heapBytes(states_);
  for (const Entry& e : entries_) bytes += weft::heapBytes(e.vfAB) + weft::heapBytes(e.vfBA) + weft::heapBytes(e.ee);
  for (const BodyState& s : states_) {
    bytes += weft::heapBytes(s.anchor) + weft::heapBytes(s.radius) + weft::heapBytes(s.drift);
    for (int k = 0; k < 3; ++k) {
      bytes += weft::heapBytes(s.boxes[k]) + s.trees[k].heapBytes() + weft::heapBytes(s.dirty[k]) +
               weft::heapBytes(s.dirtyIds[k]) + weft::heapBytes(s.groupStart[k]);
    }
    for (int k = 0; k < 2; ++k) bytes += weft::heapBytes(s.around.start[k]) + weft::heapBytes(s.around.ids[k]);
  }
  return bytes;
}

std::size_t HeldContacts::heapBytes() const {
  return weft::heapBytes(contacts_) + weft::heapBytes(shares_) + weft::heapBytes(firstShare_) +
         weft::heapBytes(shareOrder_) + weft::heapBytes(released_);
}

std::size_t ContactStage::heapBytes() const {
  return weft::heapBytes(bodies_) + weft::heapBytes(clothTopology_) + weft::heapBytes(clothRest_) +
         weft::heapBytes(clothInverseMass_) + weft::heapBytes(bodyToWorldIndex_) + weft::heapBytes(pairing_) +
         weft::heapBytes(obstaclePairing_) + weft::heapBytes(clothPairing_) + held_.heapBytes() + weft::heapBytes(scratch_) +
         weft::heapBytes(heldVertices_) + obstacleCache_.heapBytes() + clothCache_.heapBytes() +
         weft::heapBytes(pairs_) + weft::heapBytes(startPairs_) + weft::heapBytes(nearPairs_) +
         weft::heapBytes(nearClothPairs_) + weft::heapBytes(records_);
}

std::size_t NonlocalStress::heapBytes() const {
  return weft::heapBytes(centroid_) + weft::heapBytes(area_) + weft::heapBytes(lip_) + weft::heapBytes(across_) + weft::heapBytes(neighbours_) +
         weft::heapBytes(scale_) + weft::heapBytes(stamp_) + weft::heapBytes(region_) + weft::heapBytes(hot_) + weft::heapBytes(pending_) + weft::heapBytes(pendingPlaces_) + weft::heapBytes(pendingMark_) +
         weft::heapBytes(needed_) + weft::heapBytes(vertexNeeded_) + weft::heapBytes(cellOf_) +
         weft::heapBytes(cellWeight_) + weft::heapBytes(cellMiddle_) + weft::heapBytes(cellReader_) +
         weft::heapBytes(readsFrom_) + weft::heapBytes(place_) +
         weft::heapBytes(changedPlaces_) + weft::heapBytes(packed_);
}

std::size_t TearSearch::heapBytes() const {
  return weft::heapBytes(triangleAt_) + weft::heapBytes(rowStart_) + weft::heapBytes(around_) +
         weft::heapBytes(walked_) + weft::heapBytes(bound_) + weft::heapBytes(best_) +
         weft::heapBytes(excluded_) + weft::heapBytes(held_) + weft::heapBytes(sharpened_) + weft::heapBytes(place_) +
         weft::heapBytes(crackVertices_) + weft::heapBytes(version_) + weft::heapBytes(waiting_) +
         weft::heapBytes(evaluatedHeap_) + weft::heapBytes(unboundedHeap_) + weft::heapBytes(rowMean_) +
         weft::heapBytes(fromRows_) + weft::heapBytes(rowPlace_) + weft::heapBytes(aroundSpan_) +
         weft::heapBytes(onBorder_) + weft::heapBytes(largestStress_) + weft::heapBytes(mature_);
}

std::size_t TearStage::heapBytes() const {
  std::size_t bytes = weft::heapBytes(localStress_) + weft::heapBytes(stress_) + weft::heapBytes(nonlocal_) +
                      weft::heapBytes(corners_) + search_.heapBytes() + weft::heapBytes(log_);
  for (const auto& tips : overshoot_) bytes += weft::heapBytes(tips);
  for (const auto& waiting : overloadedSince_) bytes += weft::heapBytes(waiting);
  return bytes;
}

std::size_t World::approximateBytes() const {
  const Impl& w = *impl_;
  return sizeof(World) + sizeof(Impl) + heapBytes(w.cloths) + heapBytes(w.obstacles) + heapBytes(w.startPositions) +
         heapBytes(w.membraneAhead) +
         sizeof(ContactStage) + w.contact->heapBytes() + sizeof(TearStage) + w.tearing->heapBytes();
}

}  // namespace weft
