#include "tearing/tear_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <utility>

#include "tearing/crack_tip_stress.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

bool holds(const ClothMesh& mesh, int triangle, int vertex) {
  return triangle != kNone && triangle < mesh.triangleCount() && cornerOf(mesh.tris[triangle], vertex) != kNone;
}

// Where a vertex stands on the cracks of the cloth. A crack's tip is where a slit ends: its two
// bounding border edges are the two lips of one opened edge, so their far ends are the same
// material point. A lip is any other vertex on a torn or cut edge (its fan is bounded by the
// crack's flank).
CrackPlace crackPlaceOf(const ClothMesh& mesh, const VertexFan& fan) {
  if (fan.closed || fan.triangles.empty()) return CrackPlace::None;
  const Triangle& first = mesh.tris[fan.triangles.front()];
  const Triangle& last = mesh.tris[fan.triangles.back()];
  const Edge& clockwise = mesh.edges[first.edge[fan.corners.front()]];
  const Edge& counterClockwise = mesh.edges[last.edge[(fan.corners.back() + 2) % 3]];
  const bool onCrack = clockwise.torn || clockwise.cut || counterClockwise.torn || counterClockwise.cut;
  if (!onCrack) return CrackPlace::None;
  const Vec2 clockwiseEnd = first.rest[(fan.corners.front() + 1) % 3];
  const Vec2 counterClockwiseEnd = last.rest[(fan.corners.back() + 2) % 3];
  const bool slit = (clockwise.torn || clockwise.cut) && (counterClockwise.torn || counterClockwise.cut) &&
                    (clockwiseEnd - counterClockwiseEnd).norm() <= 1e-9;
  return slit ? CrackPlace::Tip : CrackPlace::Lip;
}

// The line across the fan's mean largest principal stress: where an isotropic fabric tears, so the
// first line to try when asking whether a vertex is overloaded at all.
double principalLineAngleOf(const Mat2& weighted) {
  // The largest principal direction is at 0.5 atan2(2 s01, s00 - s11); the line runs across it.
  return 0.5 * std::atan2(2.0 * weighted(0, 1), weighted(0, 0) - weighted(1, 1)) + 0.5 * std::numbers::pi;
}

double principalLineAngle(const StressFan& fan) {
  Mat2 mean = Mat2::Zero();
  for (const FanSector& sector : fan.sectors) mean += sector.stress * sector.span;
  return principalLineAngleOf(mean);
}

// Heap order: the larger key first, then the lower vertex (ties go to the lower vertex id).
struct HeapOrder {
  template <typename E>
  bool operator()(const E& a, const E& b) const {
    return a.key != b.key ? a.key < b.key : a.vertex > b.vertex;
  }
};

template <typename E>
void pushEntry(std::vector<E>& heap, const E& entry) {
  heap.push_back(entry);
  std::push_heap(heap.begin(), heap.end(), HeapOrder{});
}

template <typename E>
void popEntry(std::vector<E>& heap) {
  std::pop_heap(heap.begin(), heap.end(), HeapOrder{});
  heap.pop_back();
}

}  // namespace

void TearSearch::start(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                       const std::vector<Mat2>& stress, const TearTable& table, double weftAngleRad,
                       const TearSearchSettings& settings, TearSearchCounts& counts, bool tipsOnly) {
  table_ = &table;
  tipsOnly_ = tipsOnly;
  weftAngleRad_ = weftAngleRad;
  settings_ = settings;
  const int n = mesh.vertexCount();
  if (!rowsValid_ || rowsVertices_ != mesh.x.size() || rowsTriangles_ != mesh.tris.size()) buildRows(mesh, corners);
  walked_.assign(n, 0);
  fromRows_.assign(n, 0);
  rowMean_.resize(n);
  bound_.assign(n, 0.0);
  best_.resize(n);  // read only for a heap entry, which is made after its vertex's best_
  excluded_.assign(n, 0);
  held_.assign(n, 0);
  sharpened_.assign(n, 0);
  gated_ = false;
  mature_.clear();
  newlyOverloaded_.clear();
  place_.assign(n, CrackPlace::None);
  version_.resize(n, 0);  // the heaps are emptied: the versions only grow from here
  crackVertices_.clear();
  crackCellsStale_ = true;
  waiting_.clear();
  waitingIsHeap_ = false;
  evaluatedHeap_.clear();
  unboundedHeap_.clear();
  screenAndLookAtAll(mesh, corners, stress, counts);
}

void TearSearch::buildRows(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners) {
  const int n = mesh.vertexCount();
  triangleAt_.assign(n, kNone);
  rowStart_.assign(n + 1, 0);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    for (int v : mesh.tris[t].v) {
      triangleAt_[v] = t;
      ++rowStart_[v + 1];
    }
  }
  for (int v = 0; v < n; ++v) rowStart_[v + 1] += rowStart_[v];
  around_.resize(rowStart_[n]);
  aroundSpan_.resize(rowStart_[n]);
  std::vector<int> fill(rowStart_.begin(), rowStart_.end() - 1);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.tris[t].v[k];
      aroundSpan_[fill[v]] = corners[t][k].span;
      around_[fill[v]++] = t;
    }
  }
  rowPlace_.assign(n, kUnknownPlace);
  onBorder_.assign(n, 0);
  for (const Edge& edge : mesh.edges) {
    if (edge.isBoundary()) onBorder_[edge.v[0]] = onBorder_[edge.v[1]] = 1;
  }
  rowsValid_ = true;
  rowsVertices_ = mesh.x.size();
  rowsTriangles_ = mesh.tris.size();
}

void TearSearch::screenAndLookAtAll(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                                    const std::vector<Mat2>& stress, TearSearchCounts& counts) {
  const int n = mesh.vertexCount();
  // An interior vertex's fan bound is at most its arcs' (separationStrengthBound: a quarter of the
  // sum of each triangle's largest principal stress times its corner's angle), which needs neither
  // the fan's sectors nor their mean: most vertices of a loaded sheet are settled by it, in one
  // pass over the triangles around them (a vertex on a border, which may be on a crack, is always
  // looked at). The same sum in the same order as the bound's, so a vertex it skips has a bound
  // below 1 too.
  largestStress_.resize(stress.size());
  if (!tipsOnly_ && !settings_.closedFanAsOne) {
    for (std::size_t t = 0; t < stress.size(); ++t) largestStress_[t] = spectralNorm(stress[t]);
  }
  const double screen = (1.0 + 1e-9) / weakestStrength(*table_);
  for (int v = 0; v < n; ++v) {
    if (tipsOnly_ && !onBorder_[v]) continue;  // no crack there: nothing it could be asked
    if (settings_.skipByBound && !onBorder_[v] && rowStart_[v] < rowStart_[v + 1] && settings_.closedFanAsOne) {
      // A closed fan read as its mean stress S: no line has more than S's largest principal stress
      // (separationStrengthBound of a uniform fan); the mean from the rows, without the fan.
      Mat2 sum = Mat2::Zero();
      double spans = 0.0;
      for (int i = rowStart_[v]; i < rowStart_[v + 1]; ++i) {
        sum += aroundSpan_[i] * stress[around_[i]];
        spans += aroundSpan_[i];
      }
      ++counts.vertices;
      ++version_[v];
      sharpened_[v] = 0;
      if (spans > 0.0) {
        rowMean_[v] = sum / spans;  // as meanStress of the fan stressFan builds from the rows
        fromRows_[v] = 1;
      }
      bound_[v] = spans > 0.0 ? omegaCeiling(spectralNorm(rowMean_[v]), 1.0, lowestMultiplierAt(mesh, v)) : 0.0;
      if (bound_[v] < 1.0) {
        ++counts.skipped;
      } else {
        wait(Entry{bound_[v], v, version_[v]});
      }
      continue;
    }
    if (settings_.skipByBound && !onBorder_[v] && rowStart_[v] < rowStart_[v + 1]) {
      double weighted = 0.0;
      for (int i = rowStart_[v]; i < rowStart_[v + 1]; ++i) weighted += largestStress_[around_[i]] * aroundSpan_[i];
      const double lowest = lowestMultiplierAt(mesh, v);
      ++counts.vertices;
      if (0.25 * weighted * screen < lowest) {
        ++counts.skipped;
        continue;
      }
      // Not settled by its arcs: its whole bound, as lookAt would find it (a closed fan, so no
      // crack place and no propagation factor), from the rows without building the fan.
      const std::span<const int> triangles(around_.data() + rowStart_[v], around_.data() + rowStart_[v + 1]);
      const std::span<const double> spans(aroundSpan_.data() + rowStart_[v], aroundSpan_.data() + rowStart_[v + 1]);
      ++version_[v];
      sharpened_[v] = 0;
      bound_[v] = omegaCeiling(closedFanStrengthBound(triangles, spans, stress, largestStress_), 1.0, lowest);
      if (bound_[v] < 1.0) {
        ++counts.skipped;
      } else {
        wait(Entry{bound_[v], v, version_[v]});
      }
      continue;
    }
    lookAt(mesh, corners, stress, v, counts);
  }
}

void TearSearch::refresh(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                         const std::vector<Mat2>& stress, const std::vector<int>& triangles,
                         const std::vector<int>& extraVertices, TearSearchCounts& counts) {
  rowsValid_ = false;  // the tear changed the mesh: the next start builds the rows anew
  crackCellsStale_ = true;
  const std::size_t n = static_cast<std::size_t>(mesh.vertexCount());
  triangleAt_.resize(n, kNone);
  bound_.resize(n, 0.0);
  best_.resize(n);
  excluded_.resize(n, 0);
  held_.resize(n, 0);
  sharpened_.resize(n, 0);
  if (gated_) mature_.resize(n, 0);  // a copy made by a tear is a new vertex: it waits
  place_.resize(n, CrackPlace::None);
  version_.resize(n, 0);
  walked_.resize(n, 1);
  fromRows_.resize(n, 0);
  rowMean_.resize(n);
  rowPlace_.resize(n, kUnknownPlace);
  std::vector<int> vertices(extraVertices);
  for (int t : triangles) {
    for (int v : mesh.tris[t].v) {
      triangleAt_[v] = t;
      vertices.push_back(v);
    }
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (int v : vertices) {
    walked_[v] = 1;
    lookAt(mesh, corners, stress, v, counts);
  }
}

void TearSearch::exclude(int vertex) {
  if (vertex >= 0 && vertex < static_cast<int>(excluded_.size())) excluded_[vertex] = 1;
}

void TearSearch::gateStarts(std::vector<char> mature) {
  mature_ = std::move(mature);
  mature_.resize(bound_.size(), 0);
  gated_ = true;
}

void TearSearch::hold(int vertex) {
  if (vertex >= 0 && vertex < static_cast<int>(held_.size())) held_[vertex] = 1;
}

void TearSearch::wait(const Entry& entry) {
  if (waitingIsHeap_) {
    pushEntry(waiting_, entry);
  } else {
    waiting_.push_back(entry);
  }
}

void TearSearch::heapWaiting() {
  if (waitingIsHeap_) return;
  // An entry not offerable now never becomes offerable this step (holds, exclusions and versions
  // only grow): dropped here rather than popped one by one. The heap's order is total (the vertex
  // id breaks ties), so the pops come in the same order however it was built.
  std::erase_if(waiting_, [&](const Entry& entry) { return !offerable(entry); });
  std::make_heap(waiting_.begin(), waiting_.end(), HeapOrder{});
  waitingIsHeap_ = true;
}

bool TearSearch::offerable(const Entry& entry) const {
  const int v = entry.vertex;
  return entry.version == version_[v] && !excluded_[v] && !(held_[v] && place_[v] != CrackPlace::Tip);
}

bool TearSearch::overloadedAsStart(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                                   const std::vector<Mat2>& stress, int vertex, double hintAngle, double& angle,
                                   TearSearchCounts& counts) {
  if (vertex < 0 || vertex >= static_cast<int>(bound_.size()) || bound_[vertex] < 1.0) return false;
  if (place_[vertex] == CrackPlace::Tip) return false;
  if (readsMeanFromRows(vertex) && std::isfinite(hintAngle)) {
    // Last step's line, on the mean the screen summed: most held vertices are settled by it
    // without building their fans (the same value the fan's reading gives).
    if (meanLineAboveOne(mesh, vertex, hintAngle, counts)) {
      angle = hintAngle;
      return true;
    }
    hintAngle = std::numeric_limits<double>::quiet_NaN();  // tried: the fan's search skips it
  }
  fanOf(mesh, corners, stress, vertex, fan_);
  return anyLineAboveOneAt(fan_, *table_, weftAngleRad_, hintAngle, angle, counts,
                           scaleAt(mesh, vertex, 1.0, !fan_.closed));
}

bool TearSearch::meanLineAboveOne(const ClothMesh& mesh, int vertex, double angle, TearSearchCounts& counts) const {
  ++counts.linesEvaluated;
  // As anyLineAboveOneAt reads a line on a closed uniform fan.
  return tractionAcross(rowMean_[vertex], angle) /
             (scaleAt(mesh, vertex, 1.0, false).of(angle) *
              requiredStrength(*table_, angleFromWarpDeg(angle, weftAngleRad_))) >
         1.0;
}

CrackPlace TearSearch::fanOf(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                       const std::vector<Mat2>& stress, int vertex, StressFan& fan) {
  if (!walked_[vertex]) {
    const std::span<const int> triangles(around_.data() + rowStart_[vertex], around_.data() + rowStart_[vertex + 1]);
    stressFan(mesh, vertex, triangles, corners, stress, fan);
    if (settings_.closedFanAsOne && fan.closed) makeUniform(fan, meanStress(fan));
    // Only a vertex on a border can be on a crack: walk those (few) fans to look at their edges,
    // once while the rows hold.
    if (fan.closed) return CrackPlace::None;
    if (rowPlace_[vertex] == kUnknownPlace) {
      rowPlace_[vertex] = static_cast<signed char>(crackPlaceOf(mesh, walkFan(mesh, vertex, triangleAt_[vertex])));
    }
    return static_cast<CrackPlace>(rowPlace_[vertex]);
  }
  const VertexFan walked = walkFan(mesh, vertex, triangleAt_[vertex]);
  stressFan(mesh, vertex, std::span<const int>(walked.triangles), corners, stress, fan);
  if (settings_.closedFanAsOne && fan.closed) makeUniform(fan, meanStress(fan));
  return crackPlaceOf(mesh, walked);
}

void TearSearch::lookAt(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                        const std::vector<Mat2>& stress, int vertex, TearSearchCounts& counts) {
  bound_[vertex] = 0.0;
  ++version_[vertex];
  sharpened_[vertex] = 0;
  boundAt(mesh, corners, stress, vertex, counts);
  if (bound_[vertex] >= 1.0) wait(Entry{bound_[vertex], vertex, version_[vertex]});
}

void TearSearch::boundAt(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                         const std::vector<Mat2>& stress, int vertex, TearSearchCounts& counts) {
  if (!holds(mesh, triangleAt_[vertex], vertex)) {
    // A separated vertex's triangle may have gone to its copy: find one it still holds.
    triangleAt_[vertex] = findTriangleAt(mesh, vertex);
    crackCellsStale_ = true;  // nearCrack's index reads triangleAt_
    if (triangleAt_[vertex] == kNone) return;
  }
  ++counts.vertices;
  const CrackPlace place = fanOf(mesh, corners, stress, vertex, fan_);
  if (place != CrackPlace::None && place_[vertex] == CrackPlace::None) crackVertices_.push_back(vertex);
  place_[vertex] = place;
  if (place == CrackPlace::Lip && !settings_.branchFromLips) return;  // cracks grow at their tips
  if (tipsOnly_ && place != CrackPlace::Tip) return;
  if (place == CrackPlace::Tip && settings_.tipLength > 0.0) {
    // The tip reads the material ahead of it, not its fan: no bound from the fan (tips are few).
    bound_[vertex] = std::numeric_limits<double>::infinity();
    return;
  }
  const double scale = place == CrackPlace::Tip ? table_->propagationFactor : 1.0;
  bound_[vertex] = settings_.skipByBound ? omegaCeiling(separationStrengthBound(fan_), scale, lowestMultiplierAt(mesh, vertex))
                                         : std::numeric_limits<double>::infinity();
  if (bound_[vertex] < 1.0) ++counts.skipped;
}

TearCandidate TearSearch::candidateAt(const ClothMesh& mesh, int vertex, const StressFan& fan, CrackPlace place,
                                      TearCandidate line) const {
  line.vertex = vertex;
  line.crackTip = place == CrackPlace::Tip;
  const Triangle& t = mesh.tris[triangleAt_[vertex]];
  line.restPosition = t.rest[cornerOf(t, vertex)];
  line.ray = !fan.closed;
  return line;
}

std::optional<TearCandidate> TearSearch::best(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                                              const std::vector<Mat2>& stress, TearSearchCounts& counts) {
  auto dropStale = [&](std::vector<Entry>& heap) {
    while (!heap.empty() && !offerable(heap.front())) popEntry(heap);
  };
  // Branch and bound: the waiting vertices in order of decreasing bound, until none left can beat
  // the best line found (ties are still evaluated, so the lower vertex id wins).
  while (true) {
    heapWaiting();
    dropStale(waiting_);
    dropStale(evaluatedHeap_);
    dropStale(unboundedHeap_);
    if (waiting_.empty()) break;
    const Entry next = waiting_.front();
    const bool unbounded = next.key == std::numeric_limits<double>::infinity();
    // Crack tips (read ahead of them, so unbounded: they come first) tear before any new crack
    // starts: the stress around a tip is its own concentration, which its running relieves.
    // (Without the bound every vertex is unbounded: then the best of them all wins.)
    if (!unbounded && !unboundedHeap_.empty() && unboundedHeap_.front().key > 1.0) break;
    const double leading = std::max(unboundedHeap_.empty() ? 0.0 : unboundedHeap_.front().key,
                                    evaluatedHeap_.empty() ? 0.0 : evaluatedHeap_.front().key);
    if (next.key < leading) break;  // no waiting vertex can beat it
    popEntry(waiting_);
    const int v = next.vertex;
    // An interior vertex the screen read from the rows needs its fan only if it is searched: its
    // incubation question reads the mean first.
    const bool fromRows = readsMeanFromRows(v);
    bool fanBuilt = !fromRows;
    const CrackPlace place = fromRows ? CrackPlace::None : fanOf(mesh, corners, stress, v, fan_);
    auto buildFan = [&] {
      if (!fanBuilt) fanOf(mesh, corners, stress, v, fan_);
      fanBuilt = true;
    };
    if (settings_.startClearance > 0.0 && place != CrackPlace::Tip) {
      // A start this close to a crack is refused (tear_stage.cpp); cracks only grow within a step,
      // so it stays refused: held, not searched (it may still tear as a tip, if a crack reaches it).
      const Triangle& t = mesh.tris[triangleAt_[v]];
      if (nearCrack(mesh, t.rest[cornerOf(t, v)], settings_.startClearance)) {
        held_[v] = 1;
        continue;
      }
    }
    if (gated_ && !mature_[v] && place != CrackPlace::Tip) {
      double angle = 0.0;
      bool overloaded = false;
      if (fromRows) {
        // The line across the mean's largest principal stress first, as the fan would try it
        // (the mean weighted by the rows' spans, in the fan's order).
        Mat2 weighted = Mat2::Zero();
        for (int i = rowStart_[v]; i < rowStart_[v + 1]; ++i) weighted += rowMean_[v] * aroundSpan_[i];
        const double first = principalLineAngleOf(weighted);
        overloaded = meanLineAboveOne(mesh, v, first, counts);
        if (overloaded) {
          angle = first;
        } else {
          buildFan();
          overloaded = anyLineAboveOneAt(fan_, *table_, weftAngleRad_, std::numeric_limits<double>::quiet_NaN(),
                                         angle, counts, scaleAt(mesh, v, 1.0, !fan_.closed));
        }
      } else {
        overloaded = anyLineAboveOneAt(fan_, *table_, weftAngleRad_, principalLineAngle(fan_), angle, counts,
                                       scaleAt(mesh, v, 1.0, !fan_.closed));
      }
      if (overloaded) {
        newlyOverloaded_.push_back(Overloaded{v, angle});
        held_[v] = 1;
      }
      continue;
    }
    buildFan();
    if (!unbounded && !sharpened_[v] && place != CrackPlace::Tip) {
      // Before searching the whole fan, the cheaper piecewise bound: most vertices of a loaded
      // sheet that pass the fan's bound are settled by it (they stay below 1), and the others wait
      // again behind the leader if it already beats them.
      sharpened_[v] = 1;
      bound_[v] = std::min(bound_[v], omegaBoundAt(fan_, *table_, weftAngleRad_, scaleAt(mesh, v, 1.0, !fan_.closed), counts));
      if (bound_[v] < 1.0) continue;
      if (bound_[v] < leading) {
        pushEntry(waiting_, Entry{bound_[v], v, version_[v]});
        continue;
      }
    }
    best_[v] = candidateAt(mesh, v, fan_, place, bestLineOf(mesh, stress, v, place, counts));
    const double ratio = best_[v].ratio >= 0.0 ? best_[v].ratio : 0.0;  // NaN never leads
    pushEntry(unbounded ? unboundedHeap_ : evaluatedHeap_, Entry{ratio, v, version_[v]});
  }
  // An unbounded vertex above 1 wins (the tips rule above); otherwise the better of the two leaders.
  const Entry* tip = unboundedHeap_.empty() ? nullptr : &unboundedHeap_.front();
  const Entry* other = evaluatedHeap_.empty() ? nullptr : &evaluatedHeap_.front();
  const Entry* winner = tip == nullptr || (other != nullptr && tip->key <= 1.0 && HeapOrder{}(*tip, *other)) ? other : tip;
  if (winner == nullptr || !(winner->key > 1.0)) return std::nullopt;
  return best_[winner->vertex];
}

TearCandidate TearSearch::bestLineOf(const ClothMesh& mesh, const std::vector<Mat2>& stress, int vertex,
                                     CrackPlace place, TearSearchCounts& counts) {
  if (place != CrackPlace::Tip) {
    return bestLineAt(fan_, *table_, weftAngleRad_, settings_, scaleAt(mesh, vertex, 1.0, !fan_.closed), counts);
  }
  if (!(settings_.tipLength > 0.0)) {
    return bestLineAt(fan_, *table_, weftAngleRad_, settings_,
                      scaleAt(mesh, vertex, table_->propagationFactor, !fan_.closed), counts, settings_.maxKinkRad);
  }
  counts.linesEvaluated += settings_.tipDirections;
  return bestTipLine(mesh, walkFan(mesh, vertex, triangleAt_[vertex]), stress, *table_, weftAngleRad_,
                     scaleAt(mesh, vertex, table_->propagationFactor, true), settings_.tipLength,
                     settings_.tipDirections);
}

TearCandidate TearSearch::tipLineAt(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                                    const std::vector<Mat2>& stress, int vertex, TearSearchCounts& counts) {
  if (vertex < 0 || vertex >= static_cast<int>(excluded_.size()) || excluded_[vertex]) return TearCandidate{};
  if (!holds(mesh, triangleAt_[vertex], vertex)) {
    triangleAt_[vertex] = findTriangleAt(mesh, vertex);
    crackCellsStale_ = true;  // nearCrack's index reads triangleAt_
  }
  if (triangleAt_[vertex] == kNone) return TearCandidate{};
  const CrackPlace place = fanOf(mesh, corners, stress, vertex, fan_);
  if (place != CrackPlace::Tip) return TearCandidate{};
  return candidateAt(mesh, vertex, fan_, place, bestLineOf(mesh, stress, vertex, place, counts));
}

StrengthScale TearSearch::scaleAt(const ClothMesh& mesh, int vertex, double factor, bool ray) const {
  if (map_ == nullptr && region_ == nullptr) return StrengthScale(factor);
  const Triangle& t = mesh.tris[triangleAt_[vertex]];
  return StrengthScale(factor, map_, region_, table_, weftAngleRad_, t.rest[cornerOf(t, vertex)], ray);
}

double TearSearch::lowestMultiplierAt(const ClothMesh& mesh, int vertex) const {
  if (map_ == nullptr && region_ == nullptr) return 1.0;
  // As a multiplier on the table's weakest strength (what omegaCeiling and the arc screen scale);
  // the lowest does not depend on `ray`.
  return scaleAt(mesh, vertex, 1.0, false).lowestStrength(*table_) / weakestStrength(*table_);
}

double TearSearch::omegaCeiling(double zetaBound, double scale, double lowestMultiplier) const {
  // The margin covers the rounding of the bound itself, so the skip never changes a result.
  return zetaBound * (1.0 + 1e-9) / (scale * lowestMultiplier * weakestStrength(*table_));
}

std::int64_t TearSearch::crackCellKey(std::int64_t cx, std::int64_t cy) { return (cx << 32) ^ (cy & 0xffffffff); }

std::int64_t TearSearch::crackCellCoordinate(double c) const {
  return static_cast<std::int64_t>(std::floor(c / crackCellSize_));
}

bool TearSearch::nearCrack(const ClothMesh& mesh, const Vec2& restPosition, double radius) {
  if (!(radius > 0.0) || !std::isfinite(restPosition.x()) || !std::isfinite(restPosition.y())) return false;
  auto restOf = [&](int v) {
    const Triangle& t = mesh.tris[triangleAt_[v]];
    return t.rest[cornerOf(t, v)];
  };
  if (crackCellsStale_ || radius != crackCellSize_) {
    crackCells_.clear();
    crackCellSize_ = radius;
    crackIndexed_ = 0;
    crackCellsStale_ = false;
  }
  for (; crackIndexed_ < crackVertices_.size(); ++crackIndexed_) {
    const int v = crackVertices_[crackIndexed_];
    // A vertex that holds no triangle now is skipped by the query anyway; one that does is
    // indexed where it lies now (a later tear rebuilds the index).
    if (!holds(mesh, triangleAt_[v], v)) continue;
    const Vec2 rest = restOf(v);
    crackCells_[crackCellKey(crackCellCoordinate(rest.x()), crackCellCoordinate(rest.y()))].push_back(v);
  }
  // Every crack vertex within `radius` lies in the query's cell or one of its eight neighbours.
  const std::int64_t cx = crackCellCoordinate(restPosition.x()), cy = crackCellCoordinate(restPosition.y());
  for (std::int64_t dx = -1; dx <= 1; ++dx) {
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      const auto found = crackCells_.find(crackCellKey(cx + dx, cy + dy));
      if (found == crackCells_.end()) continue;
      for (int v : found->second) {
        if (place_[v] == CrackPlace::None || !holds(mesh, triangleAt_[v], v)) continue;
        if ((restOf(v) - restPosition).norm() < radius) return true;
      }
    }
  }
  return false;
}

std::vector<TearCandidate> TearSearch::linesAt(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                                               const std::vector<Mat2>& stress, int vertex) {
  const CrackPlace place = fanOf(mesh, corners, stress, vertex, fan_);
  std::vector<TearCandidate> lines =
      place == CrackPlace::Tip && settings_.tipLength > 0.0
          ? tipLinesAboveOne(mesh, walkFan(mesh, vertex, triangleAt_[vertex]), stress, *table_, weftAngleRad_,
                             scaleAt(mesh, vertex, table_->propagationFactor, true), settings_.tipLength,
                             settings_.tipDirections)
          : linesAboveOneAt(fan_, *table_, weftAngleRad_, settings_,
                            scaleAt(mesh, vertex, place == CrackPlace::Tip ? table_->propagationFactor : 1.0,
                                    !fan_.closed),
                            place == CrackPlace::Tip ? settings_.maxKinkRad : kNoTurnLimit);
  for (TearCandidate& line : lines) line = candidateAt(mesh, vertex, fan_, place, line);
  return lines;
}

}  // namespace weft
