#include "collision/candidate_pairs.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <tuple>

#include <Eigen/Geometry>

namespace weft {

// Performance notes. A 64 x 64 cloth has ~8k triangles and ~65k overlapping triangle pairs per
// step, and over 80% of those pairs are neighbours (they share a corner, so their boxes always
// overlap). Hence: neighbours' feature pairs are listed once per topology
// (SweptFeatures::neighbour*) and only their boxes are tested each step; the BVH's remaining
// pairs read precomputed feature boxes in short runs; no branch depends on the outcome of a box
// test (about half pass, which no branch predictor can learn); and the final ordering is a radix
// sort rather than a comparison sort.

namespace {

// Evaluated without branches: nine comparisons are cheaper than the mispredictions of
// short-circuiting them on every triangle pair the BVH reports.
bool shareCorner(const std::array<int, 3>& s, const std::array<int, 3>& t) {
  int shared = 0;
  for (int a : s) {
    for (int b : t) shared |= a == b;
  }
  return shared != 0;
}

// Exact culling by fixed planes (FixedPlane) ------------------------------------------------------

// The side of `plane` a vertex stays on over the step: +1 or -1 when both its start and end
// positions are farther than `limit` (plus the plane's slack) on that side, 0 otherwise (and
// always 0 for a moving triangle's all-zero plane, or a non-finite position).
int sideOfPlane(const FixedPlane& plane, const SweptMesh& m, int v, double limit) {
  const double reach = limit + plane.slack;
  const double d0 = plane.normal.dot((*m.x0)[v]) - plane.offset;
  // The start-of-step pairs look at one instant (x1 is x0): half the work.
  const double d1 = m.x1 == m.x0 ? d0 : plane.normal.dot((*m.x1)[v]) - plane.offset;
  return static_cast<int>(d0 > reach && d1 > reach) - static_cast<int>(d0 < -reach && d1 < -reach);
}

// The sides of the three corners of triangle `t` of `m` against `plane`.
std::array<int, 3> cornerSides(const FixedPlane& plane, const SweptMesh& m, int t, double limit) {
  const auto& corners = m.mesh->triangles[t];
  return {sideOfPlane(plane, m, corners[0], limit), sideOfPlane(plane, m, corners[1], limit),
          sideOfPlane(plane, m, corners[2], limit)};
}

// All three on one side: the whole triangle (over the whole step) stays clear of the plane.
bool allOnOneSide(const std::array<int, 3>& sides) {
  return sides[0] != 0 && sides[0] == sides[1] && sides[1] == sides[2];
}

// The side of vertex v, a corner of `triangle`, read from that triangle's corner sides.
int sideOfCorner(const std::array<int, 3>& triangle, const std::array<int, 3>& sides, int v) {
  return sides[0] * (triangle[0] == v) + sides[1] * (triangle[1] == v) + sides[2] * (triangle[2] == v);
}

// An edge stays clear of a plane when both its ends stay clear on the same side.
int edgeClear(int sideA, int sideB) { return (sideA == sideB) & (sideA != 0); }

// The corner sides of triangle i of `a` against the plane of triangle j of `b`, and of j against
// i's, for the features the triangle pair owns.
struct PairSides {
  std::array<int, 3> ofA{};  // corners of i against j's plane
  std::array<int, 3> ofB{};  // corners of j against i's plane
  bool separated = false;    // one triangle stays clear of the other's plane (then a side may be unset)
};

PairSides pairSides(const SweptMesh& a, int i, const SweptMesh& b, int j, double limit) {
  PairSides sides;
  if (b.hasFixedPlanes) {
    sides.ofA = cornerSides(b.planes[j], a, i, limit);
    sides.separated = allOnOneSide(sides.ofA);
    if (sides.separated) return sides;
  }
  if (a.hasFixedPlanes) {
    sides.ofB = cornerSides(a.planes[i], b, j, limit);
    sides.separated = allOnOneSide(sides.ofB);
  }
  return sides;
}

// The distance below which a plane test must not cull: the margin, plus a bound on the rounding
// of a point's distance to a plane at the scale of the meshes' coordinates.
double planeLimit(const SweptMesh& a, const SweptMesh& b, double margin) {
  auto scale = [](const Bvh& bvh) {
    const Aabb& box = bvh.bounds();
    return bvh.empty() ? 0.0 : std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff());
  };
  return margin + 1e-12 * (1.0 + scale(a.bvh) + scale(b.bvh));
}

// The plane of triangle t if none of its corners moves over the step (else all zero).
FixedPlane fixedPlane(const std::array<int, 3>& corners, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  FixedPlane plane;
  for (int v : corners) {
    if (x0[v] != x1[v]) return plane;
  }
  const Vec3 normal = (x0[corners[1]] - x0[corners[0]]).cross(x0[corners[2]] - x0[corners[0]]);
  const double length = normal.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return plane;
  plane.normal = normal / length;
  plane.offset = plane.normal.dot(x0[corners[0]]);
  for (int v : corners) plane.slack = std::max(plane.slack, std::abs(plane.normal.dot(x0[v]) - plane.offset));
  return plane;
}

// The vertices (or edges) of triangle t that it owns, in corner (or side) order.
void ownedBy(int t, const std::array<int, 3>& featuresOfTriangle, const std::vector<int>& owner,
             std::vector<int>& out) {
  out.clear();
  for (int feature : featuresOfTriangle) {
    if (owner[feature] == t) out.push_back(feature);
  }
}

// Groups the vertices (or edges) by owning triangle: the topology half of OwnedFeatures.
void groupByOwner(const std::vector<std::array<int, 3>>& featuresOfTriangle, const std::vector<int>& owner,
                  OwnedFeatures& owned) {
  const int triangleCount = static_cast<int>(featuresOfTriangle.size());
  TriangleRuns<int>& runs = owned.ids;
  runs.clear(triangleCount);
  std::vector<int> mine;
  for (int t = 0; t < triangleCount; ++t) {
    ownedBy(t, featuresOfTriangle[t], owner, mine);
    runs.appendRun(t, mine);
  }
  owned.boxes.resize(runs.items.size());
}

// The self-collision candidates of triangle i with every later triangle sharing a corner: the
// features each owns against the other (a vertex against a face, an edge against an edge), except
// those touching by topology (the face's own corners, edges sharing a vertex).
void neighbourCandidatesOf(const CollisionMesh& mesh, const SweptFeatures& features, int i,
                           std::vector<int>& neighbours, std::vector<std::array<int, 2>>& vertexFace,
                           std::vector<std::array<int, 2>>& edgeEdge) {
  neighbours.clear();
  vertexFace.clear();
  edgeEdge.clear();
  for (int v : mesh.triangles[i]) {
    const std::vector<int>& around = mesh.trianglesAround[v];
    neighbours.insert(neighbours.end(), std::upper_bound(around.begin(), around.end(), i), around.end());
  }
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  const TriangleRuns<int>& vertices = features.vertices.ids;
  const TriangleRuns<int>& edges = features.edges.ids;
  for (int j : neighbours) {
    for (int s = vertices.begin[i]; s < vertices.end[i]; ++s) {
      if (!isCorner(mesh.triangles[j], vertices.items[s])) vertexFace.push_back({s, j});
    }
    for (int s = vertices.begin[j]; s < vertices.end[j]; ++s) {
      if (!isCorner(mesh.triangles[i], vertices.items[s])) vertexFace.push_back({s, i});
    }
    for (int s = edges.begin[i]; s < edges.end[i]; ++s) {
      for (int t = edges.begin[j]; t < edges.end[j]; ++t) {
        if (!shareVertex(mesh.edges[edges.items[s]], mesh.edges[edges.items[t]])) edgeEdge.push_back({s, t});
      }
    }
  }
}

// Lists the self-collision candidates of every pair of triangles sharing a corner.
void listNeighbourCandidates(const CollisionMesh& mesh, SweptFeatures& features) {
  const int triangleCount = static_cast<int>(mesh.triangles.size());
  features.neighbourVertexFace.clear(triangleCount);
  features.neighbourEdgeEdge.clear(triangleCount);
  std::vector<int> neighbours;
  std::vector<std::array<int, 2>> vertexFace, edgeEdge;
  for (int i = 0; i < triangleCount; ++i) {
    neighbourCandidatesOf(mesh, features, i, neighbours, vertexFace, edgeEdge);
    features.neighbourVertexFace.appendRun(i, vertexFace);
    features.neighbourEdgeEdge.appendRun(i, edgeEdge);
  }
}

// Collects pairs without a branch per candidate: each candidate is written to the next free slot
// and the count moves past it only when it is kept. Full batches are appended to the output.
template <class Pair>
class PairBatch {
 public:
  explicit PairBatch(std::vector<Pair>& out) : out_(out) {}
  ~PairBatch() { flush(); }
  PairBatch(const PairBatch&) = delete;
  PairBatch& operator=(const PairBatch&) = delete;

  // Call before adding up to `count` candidates.
  void reserve(int count) {
    if (size_ + count > kCapacity) flush();
  }
  void add(int keep, const Pair& pair) {
    slots_[size_] = pair;
    size_ += keep;
  }
  void flush() {
    out_.insert(out_.end(), slots_.begin(), slots_.begin() + size_);
    size_ = 0;
  }

 private:
  static constexpr int kCapacity = 256;
  std::array<Pair, kCapacity> slots_;
  int size_ = 0;
  std::vector<Pair>& out_;
};

// The vertices triangle `owner` of `vertices` owns against face `face` of `faces`: the
// vertex-face candidates of that triangle pair, less those whose vertex stays clear of the face's
// plane (`ownerSides`: the owner's corners against it). (No exclusion: in self collision this is
// only called for triangles that share no corner.)
void addVertexFacePairs(const SweptMesh& vertices, int owner, const SweptMesh& faces, int face, double margin,
                        const std::array<int, 3>& ownerSides, PairBatch<VertexFacePair>& out) {
  const OwnedFeatures& owned = vertices.features.vertices;
  const Aabb& faceBox = faces.triangleBoxes[face];
  const auto& corners = vertices.mesh->triangles[owner];
  out.reserve(3);
  for (int s = owned.ids.begin[owner]; s < owned.ids.end[owner]; ++s) {
    const int v = owned.ids.items[s];
    out.add(grownOverlap(owned.boxes[s], boxGrowth(margin), faceBox, 0.0) & (sideOfCorner(corners, ownerSides, v) == 0),
            {v, face});
  }
}

// The edges triangle i of `a` owns against the edges triangle j of `b` owns, less the pairs where
// one edge stays clear of the plane of the other's triangle. `kOrdered` (self collision) stores
// each pair as (smaller, larger) id; a template parameter, so that the inner loop carries no
// runtime flag.
template <bool kOrdered>
void addEdgeEdgePairs(const SweptMesh& a, int i, const SweptMesh& b, int j, double margin, const PairSides& sides,
                      PairBatch<EdgeEdgePair>& out) {
  const OwnedFeatures& ownedA = a.features.edges;
  const OwnedFeatures& ownedB = b.features.edges;
  const int beginB = ownedB.ids.begin[j], endB = ownedB.ids.end[j];
  if (beginB == endB) return;
  out.reserve(9);
  const Aabb& triangleBoxB = b.triangleBoxes[j];
  const auto& cornersA = a.mesh->triangles[i];
  const auto& cornersB = b.mesh->triangles[j];
  for (int s = ownedA.ids.begin[i]; s < ownedA.ids.end[i]; ++s) {
    const Aabb& boxA = ownedA.boxes[s];
    const int ea = ownedA.ids.items[s];
    const auto& endsA = a.mesh->edges[ea];
    // An edge of i that misses triangle j's box, or stays clear of its plane, misses all of j's edges.
    if (!grownOverlap(boxA, boxGrowth(margin), triangleBoxB, 0.0) ||
        edgeClear(sideOfCorner(cornersA, sides.ofA, endsA[0]), sideOfCorner(cornersA, sides.ofA, endsA[1]))) {
      continue;
    }
    for (int t = beginB; t < endB; ++t) {
      const int eb = ownedB.ids.items[t];
      const auto& endsB = b.mesh->edges[eb];
      const int keep = grownOverlap(boxA, boxGrowth(margin), ownedB.boxes[t], boxGrowth(margin)) &
                       (edgeClear(sideOfCorner(cornersB, sides.ofB, endsB[0]),
                                  sideOfCorner(cornersB, sides.ofB, endsB[1])) == 0);
      out.add(keep, kOrdered ? EdgeEdgePair{std::min(ea, eb), std::max(ea, eb)} : EdgeEdgePair{ea, eb});
    }
  }
}

int bitsFor(int count) {
  int bits = 0;
  while (bits < 31 && (1 << bits) < count) ++bits;
  return bits;
}

// Sorts pairs by (first, second) and drops repeats: a least-significant-digit radix sort on the
// pair packed into one integer (first << bits of second | second). Linear in the number of pairs;
// a comparison sort was the most expensive stage of the search. One scratch copy per call (after
// the first step the allocator hands back the same memory without new pages).
template <class Pair, class First, class Second>
void sortPairs(std::vector<Pair>& pairs, int secondCount, First first, Second second) {
  const int shift = bitsFor(secondCount);
  auto key = [&](const Pair& p) {
    return (static_cast<std::uint64_t>(first(p)) << shift) | static_cast<std::uint64_t>(second(p));
  };
  std::uint64_t largest = 0;
  for (const Pair& p : pairs) largest = std::max(largest, key(p));
  constexpr int kDigitBits = 11;
  constexpr std::uint64_t kDigitMask = (std::uint64_t{1} << kDigitBits) - 1;
  std::vector<Pair> scratch(pairs.size());
  for (int low = 0; low < 64 && (largest >> low) != 0; low += kDigitBits) {
    std::array<int, (1 << kDigitBits) + 1> offsets{};
    for (const Pair& p : pairs) ++offsets[((key(p) >> low) & kDigitMask) + 1];
    for (size_t d = 1; d < offsets.size(); ++d) offsets[d] += offsets[d - 1];
    for (const Pair& p : pairs) scratch[offsets[(key(p) >> low) & kDigitMask]++] = p;
    pairs.swap(scratch);
  }
  // Ownership emits every pair once, so unique removes nothing unless that invariant breaks.
  const auto end =
      std::unique(pairs.begin(), pairs.end(), [&](const Pair& p, const Pair& q) { return key(p) == key(q); });
  assert(end == pairs.end() && "a primitive pair was emitted twice");
  pairs.erase(end, pairs.end());
}

void sortVertexFacePairs(std::vector<VertexFacePair>& pairs, int faceCount) {
  sortPairs(pairs, faceCount, [](const VertexFacePair& p) { return p.vertex; },
            [](const VertexFacePair& p) { return p.face; });
}

void sortEdgeEdgePairs(std::vector<EdgeEdgePair>& pairs, int edgeCountB) {
  sortPairs(pairs, edgeCountB, [](const EdgeEdgePair& p) { return p.edgeA; },
            [](const EdgeEdgePair& p) { return p.edgeB; });
}

// The highest certified node above each triangle's leaf (-1 when none): two triangles with the
// same one lie in one certified node.
std::vector<int> highestCertifiedNodes(const SweptMesh& swept, const std::vector<char>& certified) {
  const Bvh& tree = swept.bvh;
  const std::vector<int>& parent = swept.features.patches.parent;
  std::vector<int> highest(certified.size(), -1);
  for (int n = 0; n < tree.nodeCount(); ++n) {  // parents first
    const int above = parent[n] >= 0 ? highest[parent[n]] : -1;
    highest[n] = above >= 0 ? above : (certified[n] ? n : -1);
  }
  std::vector<int> perTriangle(swept.mesh->triangles.size(), -1);
  for (std::size_t t = 0; t < perTriangle.size(); ++t) perTriangle[t] = highest[tree.leafOf(static_cast<int>(t))];
  return perTriangle;
}

int triangleCount(const SweptMesh& swept) { return static_cast<int>(swept.mesh->triangles.size()); }
int edgeCount(const SweptMesh& swept) { return static_cast<int>(swept.mesh->edges.size()); }

bool isUpToDate(const SweptMesh& swept) {
  return swept.bvh.leafCount() == triangleCount(swept) && swept.features.triangles == swept.mesh->triangles;
}

// Built for a mesh of `triangleCount` triangles (patchSweptMesh: the count before the edit).
bool isUpToDate(const SweptMesh& swept, int triangleCount) {
  return swept.bvh.leafCount() == triangleCount && static_cast<int>(swept.features.triangles.size()) == triangleCount;
}

}  // namespace

namespace {

void updateTriangle(SweptMesh& swept, std::size_t t, double margin) {
  const auto& corners = swept.mesh->triangles[t];
  Aabb box = sweptBox(swept, corners);
  box.inflate(boxGrowth(margin));
  swept.triangleBoxes[t] = box;
  swept.planes[t] = fixedPlane(corners, *swept.x0, *swept.x1);
}

void updateVertexSlot(SweptMesh& swept, std::size_t s) {
  OwnedFeatures& vertices = swept.features.vertices;
  vertices.boxes[s] = sweptBox(swept, std::array<int, 1>{vertices.ids.items[s]});
}

void updateEdgeSlot(SweptMesh& swept, std::size_t s) {
  OwnedFeatures& edges = swept.features.edges;
  edges.boxes[s] = sweptBox(swept, swept.mesh->edges[edges.ids.items[s]]);
}

bool anyFixedPlane(const std::vector<FixedPlane>& planes) {
  return std::any_of(planes.begin(), planes.end(), [](const FixedPlane& p) { return p.normal != Vec3::Zero(); });
}

}  // namespace

void updateSweptMesh(SweptMesh& swept, double margin) {
  assert(swept.mesh && swept.x0 && swept.x1);
  const CollisionMesh& mesh = *swept.mesh;
  const size_t count = mesh.triangles.size();
  swept.triangleBoxes.resize(count);
  swept.planes.resize(count);
  for (size_t t = 0; t < count; ++t) updateTriangle(swept, t, margin);
  swept.hasFixedPlanes = anyFixedPlane(swept.planes);
  swept.boxesMargin = margin;
  swept.boxesX0 = swept.x0;
  swept.boxesX1 = swept.x1;

  // Any topology change, including one that keeps the triangle count, invalidates the ownership
  // groups and neighbour lists (and the tree's shape, which was chosen for the old triangles'
  // neighbourhoods). Comparing the triangle lists costs about a memcmp of them.
  SweptFeatures& features = swept.features;
  if (!isUpToDate(swept)) {
    if (swept.rest && swept.rest->size() == count) {
      swept.bvh.build(swept.triangleBoxes, materialBoxes(*swept.rest));
      buildMaterialPatches(swept.bvh, mesh, *swept.rest, features.patches);
    } else {
      swept.bvh.build(swept.triangleBoxes);
      features.patches = MaterialPatches();
    }
    features.triangles = mesh.triangles;
    groupByOwner(mesh.triangles, mesh.vertexOwner, features.vertices);
    groupByOwner(mesh.triangleEdges, mesh.edgeOwner, features.edges);
    listNeighbourCandidates(mesh, features);
  } else {
    swept.bvh.refit(swept.triangleBoxes);
  }

  // Every slot, stale ones included (they hold valid ids): one plain loop, no run bookkeeping.
  for (size_t s = 0; s < features.vertices.ids.items.size(); ++s) updateVertexSlot(swept, s);
  for (size_t s = 0; s < features.edges.ids.items.size(); ++s) updateEdgeSlot(swept, s);
}

void updateSweptMeshAround(SweptMesh& swept, double margin, const std::vector<char>& moved) {
  const CollisionMesh& mesh = *swept.mesh;
  // (The topology is checked by its counts only: the caller vouches that it did not change either.)
  if (!(swept.boxesMargin == margin) || swept.boxesX0 != swept.x0 || swept.boxesX1 != swept.x1 ||
      !isUpToDate(swept, static_cast<int>(mesh.triangles.size())) ||
      moved.size() != static_cast<std::size_t>(mesh.vertexCount)) {
    updateSweptMesh(swept, margin);
    return;
  }
  // Every vertex is owned by a triangle around it, and every edge by a triangle holding it, so the
  // owned runs of the triangles around the moved vertices hold every feature that moved. (Stale
  // slots, which no run reads, are left as they were.)
  const SweptFeatures& features = swept.features;
  bool anyMoved = false;
  for (int v = 0; v < mesh.vertexCount; ++v) {
    if (!moved[v]) continue;
    anyMoved = true;
    for (int t : mesh.trianglesAround[v]) {
      updateTriangle(swept, static_cast<std::size_t>(t), margin);
      for (int s = features.vertices.ids.begin[t]; s < features.vertices.ids.end[t]; ++s) updateVertexSlot(swept, s);
      for (int s = features.edges.ids.begin[t]; s < features.edges.ids.end[t]; ++s) updateEdgeSlot(swept, s);
    }
  }
  if (!anyMoved) return;
  swept.hasFixedPlanes = anyFixedPlane(swept.planes);
  swept.bvh.refit(swept.triangleBoxes);
}

void patchSweptMesh(SweptMesh& swept, const CollisionMeshChange& change) {
  SweptFeatures& features = swept.features;
  if (!isUpToDate(swept, change.oldTriangleCount) || swept.bvh.empty()) return;  // the next update builds
  const CollisionMesh& mesh = *swept.mesh;
  const int triangleCount = static_cast<int>(mesh.triangles.size());

  // The triangles whose own runs change: the changed ones and those whose ownership changed.
  std::vector<int> regrouped;
  std::set_union(change.changedTriangles.begin(), change.changedTriangles.end(), change.regroupedTriangles.begin(),
                 change.regroupedTriangles.end(), std::back_inserter(regrouped));
  // Neighbour runs hold pairs (i, j > i) and read both triangles' corners and owned slots, so
  // every triangle that shares a corner with a regrouped one, before or after the change, is
  // redone. A triangle that used an old corner and no longer does is a changed one itself, so the
  // triangles around each old and new corner now, plus the changed ones, cover them all.
  std::vector<int> corners;
  for (size_t k = 0; k < change.changedTriangles.size(); ++k) {
    for (int v : change.oldCorners[k]) {
      if (v >= 0) corners.push_back(v);
    }
  }
  for (int t : regrouped) corners.insert(corners.end(), mesh.triangles[t].begin(), mesh.triangles[t].end());
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  std::vector<int> redo = regrouped;
  for (int v : corners) redo.insert(redo.end(), mesh.trianglesAround[v].begin(), mesh.trianglesAround[v].end());
  std::sort(redo.begin(), redo.end());
  redo.erase(std::unique(redo.begin(), redo.end()), redo.end());

  // The BVH: appended triangles join the leaf of an older neighbour (the lowest one sharing a
  // corner: the triangle split to make it, or one next to it).
  for (int t = change.oldTriangleCount; t < triangleCount; ++t) {
    int near = change.oldTriangleCount;
    for (int v : mesh.triangles[t]) near = std::min(near, mesh.trianglesAround[v].front());
    swept.bvh.insert(near < change.oldTriangleCount ? near : 0);  // (no older neighbour: any leaf is correct)
  }

  features.triangles.resize(triangleCount);
  for (int t : change.changedTriangles) {
    features.triangles[t] = mesh.triangles[t];
    forgetPatchesAbove(swept.bvh, t, features.patches);
  }
  std::vector<int> mine;
  for (auto [owned, featuresOfTriangle, owner] :
       {std::tuple{&features.vertices, &mesh.triangles, &mesh.vertexOwner},
        std::tuple{&features.edges, &mesh.triangleEdges, &mesh.edgeOwner}}) {
    owned->ids.resize(triangleCount);
    for (int t : regrouped) {
      ownedBy(t, (*featuresOfTriangle)[t], *owner, mine);
      owned->ids.replace(t, mine);
    }
    owned->boxes.resize(owned->ids.items.size());  // filled by the next updateSweptMesh
  }
  features.neighbourVertexFace.resize(triangleCount);
  features.neighbourEdgeEdge.resize(triangleCount);
  std::vector<int> neighbours;
  std::vector<std::array<int, 2>> vertexFace, edgeEdge;
  for (int i : redo) {
    neighbourCandidatesOf(mesh, features, i, neighbours, vertexFace, edgeEdge);
    features.neighbourVertexFace.replace(i, vertexFace);
    features.neighbourEdgeEdge.replace(i, edgeEdge);
  }

  // Past these bounds a fresh build is worth its cost: forgetting what was built makes the next
  // updateSweptMesh build everything from scratch.
  if (swept.bvh.needsRebuild() || features.vertices.ids.sparse() || features.edges.ids.sparse() ||
      features.neighbourVertexFace.sparse() || features.neighbourEdgeEdge.sparse()) {
    features.triangles.clear();
  }
}

void findCandidatePairs(const SweptMesh& a, const SweptMesh& b, double margin, CandidatePairs& out) {
  assert(isUpToDate(a) && isUpToDate(b) && "call updateSweptMesh after a topology change");
  out.clear();
  const double limit = planeLimit(a, b, margin);
  {
    PairBatch<VertexFacePair> vfAB(out.vfAB), vfBA(out.vfBA);
    PairBatch<EdgeEdgePair> ee(out.ee);
    // Triangle pair (i, j) emits the vertex-face pairs of the vertices each one owns against the
    // other, and the edge-edge pairs of the edges both own: every primitive pair has exactly one
    // owning triangle pair, so none is emitted twice. A triangle that stays clear of the other's
    // plane has no feature that can come near the other's.
    a.bvh.overlappingPairs(b.bvh, [&](int i, int j) {
      const PairSides sides = pairSides(a, i, b, j, limit);
      if (sides.separated) return;
      addVertexFacePairs(a, i, b, j, margin, sides.ofA, vfAB);
      addVertexFacePairs(b, j, a, i, margin, sides.ofB, vfBA);
      addEdgeEdgePairs<false>(a, i, b, j, margin, sides, ee);
    });
  }
  sortVertexFacePairs(out.vfAB, triangleCount(b));
  sortVertexFacePairs(out.vfBA, triangleCount(a));
  sortEdgeEdgePairs(out.ee, edgeCount(b));
}

void findSelfCandidatePairs(const SweptMesh& a, double margin, CandidatePairs& out) {
  assert(isUpToDate(a) && "call updateSweptMesh after a topology change");
  out.clear();
  const SweptFeatures& features = a.features;
  const std::vector<std::array<int, 3>>& triangles = a.mesh->triangles;
  {
    PairBatch<VertexFacePair> vf(out.vfAB);
    PairBatch<EdgeEdgePair> ee(out.ee);
    // Triangle pairs from the BVH, which reports each unordered pair {i, j} once, so both
    // directions are emitted. Pairs sharing a corner are dropped here (their candidates are
    // listed, below); the remaining "distant" pairs' features never touch by topology. (A
    // triangle is never paired with itself and needs not be: its own features are all adjacent.)
    // The BVH's pairs are first filtered into a small buffer without a branch, as over 80% of
    // them are neighbours in a cloth, and then processed in one loop.
    std::array<std::pair<int, int>, 256> distant;
    int distantCount = 0;
    const double limit = planeLimit(a, a, margin);
    auto processDistant = [&] {
      for (int k = 0; k < distantCount; ++k) {
        const auto [i, j] = distant[k];
        const PairSides sides = pairSides(a, i, a, j, limit);
        if (sides.separated) continue;
        addVertexFacePairs(a, i, a, j, margin, sides.ofA, vf);
        addVertexFacePairs(a, j, a, i, margin, sides.ofB, vf);
        addEdgeEdgePairs<true>(a, i, a, j, margin, sides, ee);
      }
      distantCount = 0;
    };
    // Nodes certified for this margin over the step hold no pair that can come within it: the
    // tree skips their insides, and the neighbour lists the triangles whose neighbours all lie in
    // the same certified node.
    const bool culling = a.rest != nullptr && !features.patches.empty();
    std::vector<char> certified;
    if (culling) certifyPatches(features.patches, a.bvh, *a.mesh, *a.x0, *a.x1, margin, certified);
    a.bvh.selfOverlappingPairs(
        [&](int i, int j) {
          distant[distantCount] = {i, j};
          distantCount += shareCorner(triangles[i], triangles[j]) ? 0 : 1;
          if (distantCount == static_cast<int>(distant.size())) processDistant();
        },
        culling ? &certified : nullptr);
    processDistant();
    // A triangle whose corners' triangles all share its highest certified node has every
    // neighbour pair inside that node.
    std::vector<int> certifiedAbove, cornerNode;  // per triangle / per vertex (-1: none, or mixed)
    if (culling) {
      certifiedAbove = highestCertifiedNodes(a, certified);
      cornerNode.assign(static_cast<std::size_t>(a.mesh->vertexCount), -1);
      for (int v = 0; v < a.mesh->vertexCount; ++v) {
        const std::vector<int>& around = a.mesh->trianglesAround[v];
        if (around.empty()) continue;
        const int node = certifiedAbove[around.front()];
        bool shared = true;
        for (int j : around) shared = shared && certifiedAbove[j] == node;
        cornerNode[v] = shared ? node : -1;
      }
    }
    auto insideOneCertifiedNode = [&](int i) {
      const int node = certifiedAbove[i];
      const auto& c = triangles[i];
      return node >= 0 && cornerNode[c[0]] == node && cornerNode[c[1]] == node && cornerNode[c[2]] == node;
    };
    // Triangles sharing a corner: their candidates are listed, only the boxes are tested. (Plane
    // tests would cull few of them: in a smooth sheet neighbours lie in nearly the same plane.)
    const TriangleRuns<std::array<int, 2>>& vertexFace = features.neighbourVertexFace;
    const TriangleRuns<std::array<int, 2>>& edgeEdge = features.neighbourEdgeEdge;
    for (size_t i = 0; i < triangles.size(); ++i) {
      if (culling && insideOneCertifiedNode(static_cast<int>(i))) continue;
      for (int k = vertexFace.begin[i]; k < vertexFace.end[i]; ++k) {
        const auto [slot, face] = vertexFace.items[k];
        vf.reserve(1);
        vf.add(grownOverlap(features.vertices.boxes[slot], boxGrowth(margin), a.triangleBoxes[face], 0.0),
               {features.vertices.ids.items[slot], face});
      }
      for (int k = edgeEdge.begin[i]; k < edgeEdge.end[i]; ++k) {
        const auto [slotA, slotB] = edgeEdge.items[k];
        ee.reserve(1);
        const int ea = features.edges.ids.items[slotA], eb = features.edges.ids.items[slotB];
        ee.add(grownOverlap(features.edges.boxes[slotA], boxGrowth(margin), features.edges.boxes[slotB], boxGrowth(margin)),
               {std::min(ea, eb), std::max(ea, eb)});
      }
    }
  }
  sortVertexFacePairs(out.vfAB, triangleCount(a));
  sortEdgeEdgePairs(out.ee, edgeCount(a));
}

}  // namespace weft
