#include "contact/pair_cache.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>

#include "collision/closest_points.h"

namespace weft {
namespace {

// The longest run of uses it could have answered that the cache asks for, stepped aside, before
// building again.
constexpr int kLongestWait = 64;
// Uses a build must serve for the run asked after its step-aside to start again from one. A cloth
// that keeps jolting a third of its vertices out of their balls every few steps (layers jittering
// against each other) would otherwise pay a full build every other step, each dearer than the
// fresh search it replaces.
constexpr int kUsesToTrust = 16;
// Rounding of the distances compared, relative to the reach and skin: a pair is kept, and let
// through, when it is within this much more than the bound says.
constexpr double kRoundingSlack = 1e-9;
// Below this fraction of the reach and skin apart at the anchors, a pair's closest points give no
// direction to bound its distance along (as for the near pairs' "touching", near_pairs.h).
constexpr double kReliableApart = 1e-3;

bool pairLess(int a0, int a1, int b0, int b1) { return a0 != b0 ? a0 < b0 : a1 < b1; }

// The vertices of feature `id` of the given kind (0 vertex, 1 edge, 2 face), as a small array
// with its length.
struct FeatureVertices {
  std::array<int, 3> ids{};
  int count = 0;
};
FeatureVertices featureVertices(const CollisionMesh& mesh, int kind, int id) {
  if (kind == 0) return {{id, 0, 0}, 1};
  if (kind == 1) return {{mesh.edges[id][0], mesh.edges[id][1], 0}, 2};
  return {mesh.triangles[id], 3};
}

double largestOf(const std::vector<double>& values, const FeatureVertices& f) {
  double largest = values[f.ids[0]];
  for (int k = 1; k < f.count; ++k) largest = std::max(largest, values[f.ids[k]]);
  return largest;
}

// The gap between the shadows of feature f (its vertices at xf0 and xf1) and feature g (at xg0 and
// xg1) on the unit `axis`, f's shadow expected on the far side: a lower bound on their distance
// wherever their vertices are between those positions (a projection never lengthens a distance).
double shadowGap(const Vec3& axis, const std::vector<Vec3>& xf0, const std::vector<Vec3>& xf1, const FeatureVertices& f,
                 const std::vector<Vec3>& xg0, const std::vector<Vec3>& xg1, const FeatureVertices& g) {
  double nearestF = std::numeric_limits<double>::infinity();
  double farthestG = -std::numeric_limits<double>::infinity();
  if (&xf0 == &xf1 && &xg0 == &xg1) {  // one position each (the start of the step): half the products
    for (int k = 0; k < f.count; ++k) nearestF = std::min(nearestF, axis.dot(xf0[f.ids[k]]));
    for (int k = 0; k < g.count; ++k) farthestG = std::max(farthestG, axis.dot(xg0[g.ids[k]]));
    return nearestF - farthestG;
  }
  for (int k = 0; k < f.count; ++k) nearestF = std::min({nearestF, axis.dot(xf0[f.ids[k]]), axis.dot(xf1[f.ids[k]])});
  for (int k = 0; k < g.count; ++k) farthestG = std::max({farthestG, axis.dot(xg0[g.ids[k]]), axis.dot(xg1[g.ids[k]])});
  return nearestF - farthestG;
}

// The shadow gap on the line through the features' centroids: it costs a fraction of the closest
// points and rules out some of the in-plane neighbours that crowd a self-collision search's boxes
// (on the contact benchmark it saved a tenth of that search).
double gapAlongCentres(const std::vector<Vec3>& xf, const FeatureVertices& f, const std::vector<Vec3>& xg,
                       const FeatureVertices& g) {
  Vec3 cf = Vec3::Zero(), cg = Vec3::Zero();
  for (int k = 0; k < f.count; ++k) cf += xf[f.ids[k]];
  for (int k = 0; k < g.count; ++k) cg += xg[g.ids[k]];
  const Vec3 axis = cf / f.count - cg / g.count;
  const double length = axis.norm();
  if (!(length > 0.0)) return 0.0;
  return shadowGap(axis / length, xf, xf, f, xg, xg, g);
}

}  // namespace

void PairCache::add(const ContactPairing& pairing, double reach) {
  auto addEntry = [&](int a, int b) {
    Entry entry;
    entry.a = a;
    entry.b = b;
    entry.reach = reach;
    entries_.push_back(std::move(entry));
    const int largest = std::max(a, b);
    if (static_cast<int>(states_.size()) <= largest) states_.resize(static_cast<std::size_t>(largest) + 1);
    states_[a].involved = states_[b].involved = true;
  };
  for (const auto& [a, b] : pairing.between) addEntry(a, b);
  for (int a : pairing.self) addEntry(a, a);
  largestReach_ = std::max(largestReach_, reach);
  built_ = false;
}

const PairCache::Entry* PairCache::find(int a, int b) const {
  for (const Entry& entry : entries_) {
    if (entry.a == a && entry.b == b) return &entry;
  }
  return nullptr;
}

void PairCache::stepAside() {
  built_ = false;
  // A build that served for a while starts the runs asked for again from one; one that stepped
  // aside soon after it was made asks for a run twice as long as the last time.
  if (usesSinceBuild_ >= kUsesToTrust) backOff_ = 1;
  waitUses_ = quietNeeded_ = backOff_;
  backOff_ = std::min(2 * backOff_, kLongestWait);
}

bool PairCache::findPairs(const std::vector<ContactBody>& bodies, const ContactPairing& pairing, double reach,
                          Span span, double h, std::vector<PrimitivePair>& out, const VertexFlags* onlyTouching) {
  out.clear();
  ++stats_.uses;
  // Every body pair asked for must be cached with at least this reach.
  for (const auto& [a, b] : pairing.between) {
    const Entry* entry = find(a, b);
    if (!entry || entry->reach < reach) return false;
  }
  for (int a : pairing.self) {
    const Entry* entry = find(a, a);
    if (!entry || entry->reach < reach) return false;
  }
  if (!(skin_ > 0.0) || !refresh(bodies, span, h)) return false;
  ++stats_.served;

  // A cached pair's distance now is at least its anchored distance less how far each feature's
  // vertices drifted from their anchors: only pairs that this does not rule out are let through
  // (the callers test them exactly).
  const double limit = reach + kRoundingSlack * (largestReach_ + skin_);
  const bool wholeStep = span == Span::WholeStep;
  auto emit = [&](const Entry& entry, const std::vector<CachedPair>& pairs, bool vertexFace, bool reversed) {
    const int bodyA = reversed ? entry.b : entry.a;
    const int bodyB = reversed ? entry.a : entry.b;
    const BodyState& A = states_[bodyA];
    const BodyState& B = states_[bodyB];
    const CollisionMesh& meshA = *bodies[bodyA].topology;
    const CollisionMesh& meshB = *bodies[bodyB].topology;
    const int kindA = vertexFace ? kVertex : kEdge;
    const int kindB = vertexFace ? kFace : kEdge;
    const PairKind kind = vertexFace ? PairKind::VertexFace : PairKind::EdgeEdge;
    const std::vector<Vec3>& a0 = *bodies[bodyA].x0;
    const std::vector<Vec3>& a1 = wholeStep ? *bodies[bodyA].x1 : a0;
    const std::vector<Vec3>& b0 = *bodies[bodyB].x0;
    const std::vector<Vec3>& b1 = wholeStep ? *bodies[bodyB].x1 : b0;
    auto anyFlagged = [](const std::vector<char>& flags, const FeatureVertices& f) {
      char any = 0;
      for (int k = 0; k < f.count; ++k) any |= flags[f.ids[k]];
      return any != 0;
    };
    for (const CachedPair& p : pairs) {
      const FeatureVertices f = featureVertices(meshA, kindA, p.first);
      const FeatureVertices g = featureVertices(meshB, kindB, p.second);
      if (onlyTouching && !anyFlagged((*onlyTouching)[bodyA], f) && !anyFlagged((*onlyTouching)[bodyB], g)) continue;
      if (!(p.distance - largestOf(A.drift, f) - largestOf(B.drift, g) < limit)) continue;
      // At the anchors, the first feature lies beyond the plane through its closest point normal
      // to `apart`, the second short of the one through its own (both are convex): the gap between
      // their shadows on `apart`, over the span, bounds their distance. A vertex sliding along a
      // surface keeps this gap, where its drift alone would not.
      if (p.apart != Vec3::Zero() && !(shadowGap(p.apart, a0, a1, f, b0, b1, g) < limit)) continue;
      out.push_back({kind, bodyA, p.first, bodyB, p.second});
    }
  };
  for (const auto& [a, b] : pairing.between) {
    const Entry& entry = *find(a, b);
    emit(entry, entry.vfAB, true, false);
    emit(entry, entry.vfBA, true, true);
    emit(entry, entry.ee, false, false);
  }
  for (int a : pairing.self) {
    const Entry& entry = *find(a, a);
    emit(entry, entry.vfAB, true, false);
    emit(entry, entry.ee, false, false);
  }
  return true;
}

bool PairCache::refresh(const std::vector<ContactBody>& bodies, Span span, double h) {
  if (built_) {
    // A topology change (a tear, a cut) renumbers features: everything must be searched again,
    // which costs more than a fresh search. A tearing cloth changes again within a few steps, so
    // the cache steps aside as for fast motion, and builds again once the cloth has been left
    // whole for a while (a ball tearing through a sheet ran 3-4 times slower than the fresh
    // search when every tear was followed by a build).
    for (std::size_t s = 0; s < states_.size(); ++s) {
      if (!states_[s].involved) continue;
      if (!states_[s].builtOn.matches(*bodies[s].topology)) {
        stepAside();
        return false;
      }
    }
  }
  const bool everything = !built_;
  if (everything) {
    if (waitUses_ > 0) {
      waitUses_ = wouldHaveAnswered(bodies, span, h) ? waitUses_ - 1 : quietNeeded_;
      return false;
    }
    for (std::size_t s = 0; s < states_.size(); ++s) {
      if (!states_[s].involved) continue;
      const std::size_t n = static_cast<std::size_t>(bodies[s].topology->vertexCount);
      states_[s].builtOn = MeshStamp(*bodies[s].topology);
      states_[s].anchor.assign(n, Vec3::Zero());
      states_[s].radius.assign(n, 0.0);
    }
  }
  const long long reanchored = markDirtyVertices(bodies, span, h, everything);
  if (reanchored < 0) {
    stepAside();
    return false;
  }
  if (everything) {
    usesSinceBuild_ = 0;
  } else {
    ++usesSinceBuild_;
  }
  if (reanchored == 0 && !everything) return true;  // every vertex in its ball: the pairs stand
  updateTrees(bodies, everything);
  for (Entry& entry : entries_) search(bodies, entry, everything);
  built_ = true;
  if (everything) ++stats_.fullBuilds;
  return true;
}

bool PairCache::wouldHaveAnswered(const std::vector<ContactBody>& bodies, Span span, double h) {
  for (std::size_t s = 0; s < states_.size(); ++s) {
    BodyState& state = states_[s];
    if (!state.involved) continue;
    const ContactBody& body = bodies[s];
    if (!state.builtOn.matches(*body.topology) || state.anchor.size() != body.x0->size()) {
      // A new topology: anchors at the start positions, each moved out of its (empty) ball.
      state.builtOn = MeshStamp(*body.topology);
      state.anchor = *body.x0;
      state.radius.assign(state.anchor.size(), 0.0);
    }
  }
  return markDirtyVertices(bodies, span, h, false, true) >= 0;
}

long long PairCache::markDirtyVertices(const std::vector<ContactBody>& bodies, Span span, double h, bool everything,
                                       bool probing) {
  const double halfSkin = 0.5 * skin_;
  long long total = 0, dirty = 0;
  for (std::size_t s = 0; s < states_.size(); ++s) {
    BodyState& state = states_[s];
    if (!state.involved) continue;
    const ContactBody& body = bodies[s];
    const std::vector<Vec3>& x0 = *body.x0;
    const std::vector<Vec3>& x1 = *body.x1;
    const int n = static_cast<int>(state.anchor.size());
    std::vector<char>& dirtyVertex = state.dirty[kVertex];
    dirtyVertex.assign(static_cast<std::size_t>(n), 0);
    state.drift.resize(static_cast<std::size_t>(n));
    total += n;
    auto driftOf = [&](int i) {
      const double start = (x0[i] - state.anchor[i]).norm();
      return span == Span::Start ? start : std::max(start, (x1[i] - state.anchor[i]).norm());
    };
    for (int i = 0; i < n; ++i) {
      state.drift[i] = driftOf(i);
      if (!everything && state.drift[i] <= state.radius[i]) continue;
      dirtyVertex[i] = 1;
      ++dirty;
      if (!x0[i].allFinite() || !x1[i].allFinite()) return -1;
      // The (predicted) path of the step; the new ball holds all of it.
      const Vec3 end = span == Span::Start && body.v ? Vec3(x0[i] + h * (*body.v)[i]) : x1[i];
      const double travel = (end - x0[i]).norm();
      if (travel == 0.0) {
        // Not moving (a static obstacle, a pinned vertex): any motion at all re-anchors it, and
        // pairs with it need no room for its drift.
        state.anchor[i] = x0[i];
        state.radius[i] = 0.0;
      } else if (travel <= 2.0 * halfSkin) {
        // Half a skin ahead of the start, so that the start lies on the back of the ball: a vertex
        // still moving that way stays inside for longest. (On the contact benchmark this re-anchors
        // less often than a ball centred on the path, and both of its cases ran 13-15% faster.)
        state.anchor[i] = x0[i] + (halfSkin / travel) * (end - x0[i]);
        state.radius[i] = halfSkin;
      } else {
        // Faster than the skin: a ball around this path only, searched again next time.
        state.anchor[i] = 0.5 * (x0[i] + end);
        state.radius[i] = 0.5 * travel;
      }
      state.drift[i] = driftOf(i);
      // Rounding may leave an end a hair outside: the radius covers what was measured.
      state.radius[i] = std::max(state.radius[i], state.drift[i]);
    }
  }
  if (!everything) {
    if (static_cast<double>(dirty) > mostReanchoredShare_ * static_cast<double>(total)) return -1;
    if (!probing) stats_.reanchoredVertices += dirty;
  }
  return dirty;
}

void PairCache::updateTrees(const std::vector<ContactBody>& bodies, bool everything) {
  for (std::size_t s = 0; s < states_.size(); ++s) {
    BodyState& state = states_[s];
    if (!state.involved) continue;
    const CollisionMesh& mesh = *bodies[s].topology;
    const std::array<int, 3> counts{mesh.vertexCount, static_cast<int>(mesh.edges.size()),
                                    static_cast<int>(mesh.triangles.size())};
    markDirtyFeatures(mesh, state, everything);
    for (int kind : {kVertex, kEdge, kFace}) {
      state.boxes[kind].resize(static_cast<std::size_t>(counts[kind]));
      for (int id : state.dirtyIds[kind]) {
        // Two features within the reach now were within the reach plus both radii at the
        // anchors: boxes grown by a radius and half the largest reach overlap then.
        const FeatureVertices f = featureVertices(mesh, kind, id);
        Aabb box;
        for (int k = 0; k < f.count; ++k) box.grow(state.anchor[f.ids[k]]);
        box.inflate(largestOf(state.radius, f) + 0.5 * largestReach_);
        state.boxes[kind][id] = box;
      }
      if (everything) {
        state.trees[kind].build(state.boxes[kind]);
        state.stale[kind] = false;
      } else if (!state.dirtyIds[kind].empty()) {
        state.stale[kind] = true;  // refitted if a query needs the whole tree (fittedTree)
      }
    }
  }
}

void PairCache::markDirtyFeatures(const CollisionMesh& mesh, BodyState& state, bool everything) {
  const std::array<int, 3> counts{mesh.vertexCount, static_cast<int>(mesh.edges.size()),
                                  static_cast<int>(mesh.triangles.size())};
  for (int kind : {kVertex, kEdge, kFace}) {
    std::vector<int>& ids = state.dirtyIds[kind];
    ids.clear();
    state.groupStart[kind].clear();
    if (kind != kVertex) state.dirty[kind].assign(static_cast<std::size_t>(counts[kind]), everything ? 1 : 0);
    if (everything) {
      ids.resize(static_cast<std::size_t>(counts[kind]));
      std::iota(ids.begin(), ids.end(), 0);
    }
  }
  if (everything) {
    // The edges and faces around each vertex, for the partial updates until the next build (a
    // topology change always builds again).
    state.around.build(mesh);
    return;
  }
  // An edge or a face is re-anchored with any of its vertices.
  std::vector<char>& dirtyVertex = state.dirty[kVertex];
  for (int v = 0; v < counts[kVertex]; ++v) {
    if (!dirtyVertex[v]) continue;
    for (int kind : {kVertex, kEdge, kFace}) state.groupStart[kind].push_back(static_cast<int>(state.dirtyIds[kind].size()));
    state.dirtyIds[kVertex].push_back(v);
    for (int kind : {kEdge, kFace}) {
      std::vector<char>& dirty = state.dirty[kind];
      for (int id : state.around.of(kind, v)) {
        if (dirty[id]) continue;
        dirty[id] = 1;
        state.dirtyIds[kind].push_back(id);
      }
    }
  }
  for (int kind : {kVertex, kEdge, kFace}) state.groupStart[kind].push_back(static_cast<int>(state.dirtyIds[kind].size()));
  // (Not sorted: the pairs a search finds are sorted before they are kept.)
}

void PairCache::FeaturesAround::build(const CollisionMesh& mesh) {
  const int n = mesh.vertexCount;
  for (int kind : {kEdge, kFace}) {
    std::vector<int>& first = start[kind - 1];
    std::vector<int>& list = ids[kind - 1];
    first.assign(static_cast<std::size_t>(n) + 1, 0);
    const int count = kind == kEdge ? static_cast<int>(mesh.edges.size()) : static_cast<int>(mesh.triangles.size());
    auto forEachVertex = [&](int id, auto visit) {
      if (kind == kEdge) {
        for (int v : mesh.edges[id]) visit(v);
      } else {
        for (int v : mesh.triangles[id]) visit(v);
      }
    };
    for (int id = 0; id < count; ++id) forEachVertex(id, [&](int v) { ++first[v + 1]; });
    for (int v = 0; v < n; ++v) first[v + 1] += first[v];
    list.resize(static_cast<std::size_t>(first[n]));
    std::vector<int> next(first.begin(), first.end() - 1);
    for (int id = 0; id < count; ++id) forEachVertex(id, [&](int v) { list[next[v]++] = id; });
  }
}

const Bvh& PairCache::fittedTree(BodyState& state, int kind) {
  if (state.stale[kind]) {
    state.trees[kind].refit(state.boxes[kind]);
    state.stale[kind] = false;
  }
  return state.trees[kind];
}

void PairCache::search(const std::vector<ContactBody>& bodies, Entry& entry, bool everything) {
  const bool self = entry.a == entry.b;
  BodyState& A = states_[entry.a];
  BodyState& B = states_[entry.b];
  const CollisionMesh& meshA = *bodies[entry.a].topology;
  const CollisionMesh& meshB = *bodies[entry.b].topology;
  const double slack = kRoundingSlack * (largestReach_ + skin_);
  auto byIds = [](const CachedPair& p, const CachedPair& q) { return pairLess(p.first, p.second, q.first, q.second); };

  // Into `found`, in no particular order: the pairs of features (first of P, second of Q) with at least one
  // re-anchored feature (every pair when searching everything) whose trees' boxes overlap, that
  // `admit` lets through, and whose distance at the anchors is within the reach and both radii.
  std::vector<CachedPair>& found = foundScratch_;
  auto search = [&](BodyState& P, const CollisionMesh& meshP, int kindP, BodyState& Q,
                    const CollisionMesh& meshQ, int kindQ, auto admit) {
    found.clear();
    auto measure = [&](int i, int j) {
      if (!admit(i, j)) return;
      const FeatureVertices f = featureVertices(meshP, kindP, i);
      const FeatureVertices g = featureVertices(meshQ, kindQ, j);
      const double keep = entry.reach + largestOf(P.radius, f) + largestOf(Q.radius, g) + slack;
      // (The bound's own rounding is far below the slack.)
      if (gapAlongCentres(P.anchor, f, Q.anchor, g) > keep) return;
      double distance = 0.0;
      Vec3 difference;  // from the closest point of g to that of f
      if (kindP == kVertex) {
        const PointTriangleClosest c = closestPointOnTriangle(P.anchor[f.ids[0]], Q.anchor[g.ids[0]],
                                                              Q.anchor[g.ids[1]], Q.anchor[g.ids[2]]);
        distance = c.distance;
        difference = P.anchor[f.ids[0]] - c.point;
      } else {
        const Vec3 &p0 = P.anchor[f.ids[0]], &p1 = P.anchor[f.ids[1]];
        const Vec3 &q0 = Q.anchor[g.ids[0]], &q1 = Q.anchor[g.ids[1]];
        const SegmentSegmentClosest c = closestSegmentSegment(p0, p1, q0, q1);
        distance = c.distance;
        difference = (p0 + c.s * (p1 - p0)) - (q0 + c.t * (q1 - q0));
      }
      if (distance < keep) {
        const double length = difference.norm();
        // (Nearly touching, the direction is mostly rounding: no bound is taken from it.)
        const bool reliable = length > kReliableApart * (entry.reach + skin_);
        found.push_back({i, j, distance, reliable ? Vec3(difference / length) : Vec3::Zero()});
      }
    };
    // The trees' boxes are grown for the largest reach: a query for a smaller one (cloth on cloth,
    // the thickness, where the held vertices' reach is larger) shrinks its own box by the
    // difference. (Even a box shrunk past its size gives the right overlaps: the test compares
    // ends, which move by the same amount.)
    const double shrink = largestReach_ - entry.reach;
    auto queryBox = [&](const BodyState& state, int kind, int id) {
      Aabb box = state.boxes[kind][id];
      box.inflate(-shrink);
      return box;
    };
    if (everything) {
      P.trees[kindP].overlappingPairs(Q.trees[kindQ], measure);
    } else {
      // Each re-anchored feature's box against the other side's whole tree, a group (the
      // features around one re-anchored vertex) at a time: one descent with the group's joint box,
      // then each feature's own box against the leaves it reached. The pairs tested are the same
      // as one query per feature would test; the descents are a third as many.
      auto queryGroups = [&](BodyState& S, int kindS, const Bvh& tree, const std::vector<Aabb>& treeBoxes,
                             auto measureWith) {
        const std::vector<int>& ids = S.dirtyIds[kindS];
        const std::vector<int>& groups = S.groupStart[kindS];
        for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
          const int begin = groups[g], end = groups[g + 1];
          if (begin == end) continue;
          groupBoxes_.clear();
          Aabb joint;
          for (int k = begin; k < end; ++k) {
            groupBoxes_.push_back(queryBox(S, kindS, ids[k]));
            joint.grow(groupBoxes_.back());
          }
          if (end - begin == 1) {
            tree.overlapping(joint, [&](int other) { measureWith(ids[begin], other); });
            continue;
          }
          tree.overlapping(joint, [&](int other) {
            const Aabb& box = treeBoxes[other];
            for (int k = begin; k < end; ++k) {
              if (Bvh::overlapsBox(groupBoxes_[k - begin], box)) measureWith(ids[k], other);
            }
          });
        }
      };
      if (!P.dirtyIds[kindP].empty()) {
        queryGroups(P, kindP, fittedTree(Q, kindQ), Q.boxes[kindQ], [&](int i, int j) { measure(i, j); });
      }
      // Pairs with a re-anchored feature of Q only (those with both were found above). Against
      // itself (edges of a cloth against its edges) the query above already met every pair.
      const bool sameTree = &P == &Q && kindP == kindQ;
      if (!Q.dirtyIds[kindQ].empty() && !sameTree) {
        queryGroups(Q, kindQ, fittedTree(P, kindP), P.boxes[kindP], [&](int j, int i) {
          if (!P.dirty[kindP][i]) measure(i, j);
        });
      }
    }
  };
  // Keeps the cached pairs without a re-anchored feature and adds the ones just found (sorted
  // here: the self edge pairs are put in order first).
  auto replace = [&](std::vector<CachedPair>& cached, const BodyState& P, int kindP, const BodyState& Q, int kindQ) {
    std::sort(found.begin(), found.end(), byIds);
    if (everything) {
      cached.swap(found);
      return;
    }
    std::erase_if(cached, [&](const CachedPair& p) { return P.dirty[kindP][p.first] | Q.dirty[kindQ][p.second]; });
    if (found.empty()) return;
    // Into the scratch list, then swapped: the lists trade buffers instead of allocating one per
    // use (the edge-edge list of a draped sheet is a few hundred kilobytes).
    mergeScratch_.clear();
    mergeScratch_.reserve(cached.size() + found.size());
    std::merge(cached.begin(), cached.end(), found.begin(), found.end(), std::back_inserter(mergeScratch_), byIds);
    cached.swap(mergeScratch_);
  };

  const auto anyPair = [](int, int) { return true; };
  if (!self) {
    search(A, meshA, kVertex, B, meshB, kFace, anyPair);
    replace(entry.vfAB, A, kVertex, B, kFace);
    search(B, meshB, kVertex, A, meshA, kFace, anyPair);
    replace(entry.vfBA, B, kVertex, A, kFace);
    search(A, meshA, kEdge, B, meshB, kEdge, anyPair);
    replace(entry.ee, A, kEdge, B, kEdge);
    return;
  }
  // Self: a vertex against the faces it is no corner of.
  search(A, meshA, kVertex, A, meshA, kFace, [&](int v, int f) { return !isCorner(meshA.triangles[f], v); });
  replace(entry.vfAB, A, kVertex, A, kFace);
  // Self: each unordered pair of edges that share no vertex, once, as (smaller, larger). A pair of
  // two re-anchored edges is met twice and kept from the smaller.
  search(A, meshA, kEdge, A, meshA, kEdge, [&](int e, int f) {
    if (shareVertex(meshA.edges[e], meshA.edges[f])) return false;
    return (everything || A.dirty[kEdge][f]) ? e < f : true;
  });
  for (CachedPair& p : found) {
    if (p.first > p.second) {
      std::swap(p.first, p.second);
      p.apart = -p.apart;  // still from the second's closest point to the first's
    }
  }
  replace(entry.ee, A, kEdge, A, kEdge);
}

}  // namespace weft
