#pragma once
// A skin list ("Verlet list", Verlet 1967) of the primitive pairs near each other, kept from step
// to step, so that a cloth resting on an obstacle or on itself is not searched afresh several
// times a step.
//
// Each vertex has an anchor and a ball around it (radius: half the skin; none for a vertex that
// does not move; half its path for one faster than the skin). The cache holds every pair of
// features (vertex-face, edge-edge) whose distance, with all their vertices at their anchors, is
// below the body pair's reach plus both features' radii. While every vertex's start and end of
// step stay in its ball, so does every point of its path (a ball is convex), and a pair that
// comes within the reach anywhere in the step is in the cache: it is exact, not a heuristic.
// Each use lets through the pairs that two lower bounds on their distance cannot rule out: the
// anchored distance less how far their vertices drifted from their anchors, and the gap between
// the features' shadows on the direction between their anchored closest points.
//
// A vertex that leaves its ball is re-anchored, and only the pairs of the features around it are
// searched again (each such feature against the other body's tree of anchored feature boxes).
// When too many vertices move at once (a falling cloth, a fast tool), or the topology changes (a
// tear, a cut), the cache steps aside and the callers search afresh (findPrimitivePairs). Aside,
// it keeps moving its anchors as it would when built (a pass over the vertices, no search), and
// builds again only after a run of uses it would have answered; the run it asks for doubles each
// time a build is abandoned soon after it was made, so a cloth that keeps jolting (layers
// jittering in a fold) does not pay for builds that cannot last.
//
// The pairs come out in the order findPrimitivePairs gives them (body pairs in pairing order; in
// each, vertex-face pairs by vertex then face, then face-vertex pairs, then edge-edge pairs), so
// the passes meet the colliding pairs in the same order either way.
#include <span>
#include <utility>
#include <vector>

#include "collision/bvh.h"
#include "collision/candidate_pairs.h"
#include "contact/contact_body.h"
#include "contact/contact_pairs.h"

namespace weft {

struct PairCacheStats {
  long long uses = 0;             // calls of findPairs
  long long served = 0;           // ... that the cache answered
  long long fullBuilds = 0;       // times every pair was searched afresh into the cache
  long long reanchoredVertices = 0;  // vertices re-anchored (and their features searched again) in partial updates

  // Counts added or taken field by field (two caches' sums, a span of uses).
  PairCacheStats& operator+=(const PairCacheStats& o) {
    uses += o.uses;
    served += o.served;
    fullBuilds += o.fullBuilds;
    reanchoredVertices += o.reanchoredVertices;
    return *this;
  }
  friend PairCacheStats operator-(PairCacheStats a, const PairCacheStats& b) {
    a.uses -= b.uses;
    a.served -= b.served;
    a.fullBuilds -= b.fullBuilds;
    a.reanchoredVertices -= b.reanchoredVertices;
    return a;
  }
};

class PairCache {
 public:
  // skin (m) > 0: twice the radius of a moving vertex's ball. mostReanchoredShare: above this share
  // of the vertices re-anchored in one use, the cache steps aside (a partial update would cost
  // about what a fresh search does).
  static constexpr double kDefaultMostReanchoredShare = 0.3;
  explicit PairCache(double skin = 0.0, double mostReanchoredShare = kDefaultMostReanchoredShare)
      : skin_(skin), mostReanchoredShare_(mostReanchoredShare) {}

  // The body pairs of `pairing` will be asked for pairs within up to `reach` (m).
  void add(const ContactPairing& pairing, double reach);

  // When, in the step, the bodies' positions are read.
  enum class Span {
    Start,     // at the start only (x0). Anchors are placed along a predicted path: to x0 + h v for a
               // cloth, to x1 for an obstacle (its end pose is known before the solve)
    WholeStep  // over the step, x0 to x1
  };

  // Every pair of `pairing` (added with a reach >= `reach`) whose features come within `reach`
  // over `span`, possibly with others farther apart (their feature boxes are within `reach`), in
  // findPrimitivePairs' order. Returns false, with `out` empty, when the cache cannot answer this
  // time: then search with findPrimitivePairs. With `onlyTouching`, only the pairs with a flagged
  // vertex come out (the same pairs in the same order as the whole answer, less the others).
  bool findPairs(const std::vector<ContactBody>& bodies, const ContactPairing& pairing, double reach, Span span,
                 double h, std::vector<PrimitivePair>& out, const VertexFlags* onlyTouching = nullptr);

  const PairCacheStats& stats() const { return stats_; }
  std::size_t heapBytes() const;  // util/heap_bytes.h (defined in sim/world_memory.cpp)

 private:
  // What identifies a mesh's topology: an edit (a tear, a cut) bumps the revision; a mesh made
  // afresh for a cloth has other counts (the contact stage makes one only when they change).
  struct MeshStamp {
    const CollisionMesh* mesh = nullptr;
    long long revision = -1;
    int vertices = -1;
    std::size_t triangles = 0, edges = 0;
    MeshStamp() = default;
    explicit MeshStamp(const CollisionMesh& m)
        : mesh(&m), revision(m.revision), vertices(m.vertexCount), triangles(m.triangles.size()), edges(m.edges.size()) {}
    bool matches(const CollisionMesh& m) const { return *this == MeshStamp(m); }
    bool operator==(const MeshStamp&) const = default;
  };
  // Features of a mesh, by kind: vertices, edges, faces (CollisionMesh ids).
  static constexpr int kVertex = 0, kEdge = 1, kFace = 2;
  // The edges and faces around each vertex (compressed rows), so that a re-anchored vertex flags
  // its features directly.
  struct FeaturesAround {
    std::array<std::vector<int>, 2> start, ids;  // [0] edges, [1] faces; start has a vertex count + 1 entries
    void build(const CollisionMesh& mesh);
    std::span<const int> of(int kind, int v) const {
      const std::vector<int>& first = start[kind - 1];
      return {ids[kind - 1].data() + first[v], static_cast<std::size_t>(first[v + 1] - first[v])};
    }
  };
  struct BodyState {
    bool involved = false;
    std::vector<Vec3> anchor;     // per vertex
    std::vector<double> radius;   // per vertex: how far from its anchor it may go (half the skin, or more for a fast one)
    std::vector<double> drift;    // per vertex: how far from its anchor it is over the current span
    MeshStamp builtOn;                          // the topology the anchors and pairs are for
    std::array<std::vector<Aabb>, 3> boxes;     // anchored feature boxes, grown for the trees
    std::array<Bvh, 3> trees;
    std::array<bool, 3> stale{};                // boxes changed since the tree was fitted (refit when queried)
    std::array<std::vector<char>, 3> dirty;     // features with a vertex re-anchored in this use
    std::array<std::vector<int>, 3> dirtyIds;
    // dirtyIds[kind] in groups, one per re-anchored vertex (its features not already listed by an
    // earlier one): group g is [groupStart[kind][g], groupStart[kind][g + 1]). A group's features
    // surround one vertex, so one query of their joint box finds every candidate of each.
    std::array<std::vector<int>, 3> groupStart;
    FeaturesAround around;
  };
  // A cached pair: vertex and face, or two edges; their distance at the anchors, and the unit
  // direction from the second's closest point to the first's (zero when they touch there).
  struct CachedPair {
    int first = 0, second = 0;
    double distance = 0.0;
    Vec3 apart = Vec3::Zero();
  };
  struct Entry {
    int a = 0, b = 0;  // bodies; a == b: self
    double reach = 0.0;
    std::vector<CachedPair> vfAB, vfBA;  // vfBA stays empty for self
    std::vector<CachedPair> ee;
  };

  bool refresh(const std::vector<ContactBody>& bodies, Span span, double h);
  // Re-anchors the vertices that left their balls (every vertex when `everything`); returns how
  // many, or -1 when the cache cannot answer (a non-finite position, or too many vertices on the
  // move).
  // `probing`: while stepped aside, the anchors only follow the motion (nothing is counted).
  long long markDirtyVertices(const std::vector<ContactBody>& bodies, Span span, double h, bool everything,
                              bool probing = false);
  // While stepped aside: moves the anchors as a built cache would and says whether it would have
  // answered this use (few enough vertices left their balls).
  bool wouldHaveAnswered(const std::vector<ContactBody>& bodies, Span span, double h);
  void updateTrees(const std::vector<ContactBody>& bodies, bool everything);
  // The edges and faces with a re-anchored vertex (every feature when `everything`), flagged and
  // listed (in no particular order), with the re-anchored vertices' list.
  static void markDirtyFeatures(const CollisionMesh& mesh, BodyState& state, bool everything);
  void search(const std::vector<ContactBody>& bodies, Entry& entry, bool everything);
  // The tree of a body's features of one kind, refitted first if its boxes changed.
  static const Bvh& fittedTree(BodyState& state, int kind);
  void stepAside();
  const Entry* find(int a, int b) const;

  std::vector<CachedPair> foundScratch_, mergeScratch_;  // search's lists, kept to reuse their buffers
  std::vector<Aabb> groupBoxes_;  // search's query boxes of one group of re-anchored features
  double skin_ = 0.0;
  double mostReanchoredShare_ = kDefaultMostReanchoredShare;
  double largestReach_ = 0.0;
  std::vector<Entry> entries_;
  std::vector<BodyState> states_;
  bool built_ = false;
  int waitUses_ = 0;   // answerable uses in a row still needed before building again
  int quietNeeded_ = 0;  // ... all of them, since the last step aside
  int backOff_ = 1;    // the next wait
  int usesSinceBuild_ = 0;  // uses served since the last build
  PairCacheStats stats_;
};

}  // namespace weft
