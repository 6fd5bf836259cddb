#include "tearing/nonlocal_stress.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace weft {

namespace {

// A triangle reads the lattice when its walk's weights sum to the lattice's within this (relative):
// the walk then found every triangle of any weight the lattice reads.
constexpr double kSameWeight = 1e-9;

// The lattice may have at most this many nodes per triangle (and 2^20 whatever the count): a cloth
// whose material extent is huge beside the averaging length reads lists throughout instead.
constexpr std::size_t kNodesPerTriangle = 8;

// A neighbourhood holds at most this many triangles. The disc holds (radius / edge)^2 triangles or
// so, which a mesh much finer than the radius makes unbounded: the default 6.5 cm over a 1 m sheet
// holds about 100 at 64 x 64 but 1,700 at 256 x 256. Past the cap the list is thinned (see thin):
// the cost and memory of an average stay bounded while it still reads the whole disc.
constexpr std::size_t kMaxNeighbours = 256;
// The nearest triangles of a thinned list, kept one by one: a crack tip's singular stress is read
// at its own resolution, not spread over a group.
constexpr std::size_t kExactNeighbours = 64;

// Walks out from the triangles already in `region` (stamped), across shared edges (`across`, per
// triangle the one across each edge), adding each triangle first met that `within` accepts: the
// region grows breadth first, in a fixed order.
template <typename Within>
void walkOut(const std::vector<std::array<int, 3>>& across, std::vector<int>& region, std::vector<int>& stamp,
             int currentStamp, const Within& within) {
  for (std::size_t next = 0; next < region.size(); ++next) {
    for (int other : across[region[next]]) {
      if (other == kNone || stamp[other] == currentStamp) continue;
      stamp[other] = currentStamp;
      if (within(other)) region.push_back(other);
    }
  }
}

}  // namespace

double largestPrincipal(const Mat2& s) {
  const double mean = 0.5 * (s(0, 0) + s(1, 1));
  const double half = 0.5 * (s(0, 0) - s(1, 1));
  return mean + std::sqrt(half * half + s(0, 1) * s(0, 1));
}

void NonlocalStress::updateCentroids(const ClothMesh& mesh, const std::vector<int>& triangles) {
  const std::size_t count = mesh.tris.size();
  centroid_.resize(count, Vec2::Zero());
  area_.resize(count, 0.0);
  lip_.resize(count, 0);
  stamp_.resize(count, 0);
  neighbours_.resize(count);
  scale_.resize(count, 0.0);
  across_.resize(count, {kNone, kNone, kNone});
  readsFrom_.resize(count, ReadsFrom::Unchecked);
  place_.resize(count);
  for (int t : triangles) {
    const Triangle& tri = mesh.tris[t];
    centroid_[t] = (tri.rest[0] + tri.rest[1] + tri.rest[2]) / 3.0;
    area_[t] = std::abs(restArea(tri));
    place_[t] = kernel_.place(centroid_[t]);
    for (int k = 0; k < 3; ++k) largestSize_ = std::max(largestSize_, (tri.rest[(k + 1) % 3] - tri.rest[k]).norm());
    lip_[t] = 0;
    for (int e : tri.edge) lip_[t] = lip_[t] || (mesh.edges[e].torn && mesh.edges[e].isBoundary());
  }
}

void NonlocalStress::updateAcross(const ClothMesh& mesh, int t) {
  const Triangle& tri = mesh.tris[t];
  for (int k = 0; k < 3; ++k) {
    const Edge& edge = mesh.edges[tri.edge[k]];
    across_[t][k] = edge.tri[0] == t ? edge.tri[1] : edge.tri[0];
  }
}

template <typename Within>
void NonlocalStress::gather(int t, const Within& within) {
  ++currentStamp_;
  region_.clear();
  region_.push_back(t);
  stamp_[t] = currentStamp_;
  walkOut(across_, region_, stamp_, currentStamp_, within);
}

double NonlocalStress::walkedKernelWeight(int t) {
  const Vec2 centre = centroid_[t];
  const double reach = kernel_.reach();
  gather(t, [&](int other) {
    const Vec2 offset = (centroid_[other] - centre).cwiseAbs();
    return offset.x() < reach && offset.y() < reach;
  });
  double weights = 0.0;
  for (int u : region_) {
    if (!lip_[u]) weights += area_[u] * kernel_.weight(centre, centroid_[u]);
  }
  return weights;
}

void NonlocalStress::thin(int t, std::vector<Neighbour>& list) {
  // Past the nearest kExactNeighbours (the walk goes out ring by ring), the disc is cut into
  // cells, kRings rings of equal area times kSectors sectors round t, and each cell's triangles are
  // read at one of them, the one nearest their weighted middle, with their summed weight: a
  // quadrature of the disc at the cells' spacing, whose reading points sit where the cells' weights
  // do, so a stress varying across the disc averages as the full list would.
  constexpr int kRings = 6, kSectors = 32, kCells = kRings * kSectors;
  static_assert(kExactNeighbours + kCells <= kMaxNeighbours);
  const Vec2 centre = centroid_[t];
  const double inverseRadius2 = 1.0 / (radius_ * radius_);
  double inner2 = 0.0;  // the exact part's reach, squared, in units of the radius
  for (std::size_t k = 0; k < kExactNeighbours; ++k) {
    inner2 = std::max(inner2, (centroid_[list[k].triangle] - centre).squaredNorm() * inverseRadius2);
  }
  inner2 = std::min(inner2, 1.0 - 1e-9);
  const double ringScale = kRings / (1.0 - inner2);
  cellOf_.resize(list.size());
  cellWeight_.assign(kCells, 0.0);
  cellMiddle_.assign(kCells, Vec2::Zero());
  cellReader_.assign(kCells, kNone);
  for (std::size_t k = kExactNeighbours; k < list.size(); ++k) {
    const Vec2 offset = centroid_[list[k].triangle] - centre;
    const int ring = std::clamp(static_cast<int>(ringScale * (offset.squaredNorm() * inverseRadius2 - inner2)), 0,
                                kRings - 1);
    // The sector from a pseudo-angle in [0, 4) that grows monotonically round the circle (the
    // diamond angle): no arc tangent per triangle, and the cells' sizes need not be equal.
    const double x = offset.x(), y = offset.y();
    const double sum = std::abs(x) + std::abs(y);
    const double p = sum > 0.0 ? (y >= 0.0 ? (x >= 0.0 ? y / sum : 2.0 - y / sum) : (x < 0.0 ? 2.0 - y / sum : 4.0 + y / sum))
                               : 0.0;
    const int sector = std::clamp(static_cast<int>(p * (kSectors / 4.0)), 0, kSectors - 1);
    const int cell = ring * kSectors + sector;
    cellOf_[k] = cell;
    cellWeight_[cell] += list[k].weight;
    cellMiddle_[cell] += list[k].weight * centroid_[list[k].triangle];
  }
  for (int cell = 0; cell < kCells; ++cell) {
    if (cellWeight_[cell] > 0.0) cellMiddle_[cell] /= cellWeight_[cell];
  }
  for (std::size_t k = kExactNeighbours; k < list.size(); ++k) {
    const int u = list[k].triangle;
    const int cell = cellOf_[k];
    if (cellReader_[cell] == kNone || (centroid_[u] - cellMiddle_[cell]).squaredNorm() <
                                          (centroid_[cellReader_[cell]] - cellMiddle_[cell]).squaredNorm()) {
      cellReader_[cell] = u;
    }
  }
  std::vector<Neighbour> thinned(list.begin(), list.begin() + kExactNeighbours);
  for (int cell = 0; cell < kCells; ++cell) {
    if (cellReader_[cell] != kNone) thinned.push_back({cellReader_[cell], cellWeight_[cell]});
  }
  list = std::move(thinned);  // a list of its own length: the cap is about memory
}

void NonlocalStress::buildNeighbours(int t) {
  const Vec2 centre = centroid_[t];
  const double radius2 = radius_ * radius_;
  std::vector<Neighbour>& list = neighbours_[t];
  list.clear();
  double weights = 0.0;
  const double inverseRadius2 = 1.0 / radius2;
  // Each triangle the walk takes (lips too: the walk goes through them) joins the list as it is
  // taken, so the list keeps the walk's order.
  auto take = [&](int u, double distance2) {
    if (lip_[u]) return;
    const double d2 = distance2 * inverseRadius2;
    const double bell = (1.0 - d2) * (1.0 - d2);
    const double w = area_[u] * bell;
    if (!(w > 0.0)) return;  // adds nothing to the average: the list is what it reads
    list.push_back({u, w});
    weights += w;
  };
  take(t, 0.0);
  gather(t, [&](int other) {
    const double distance2 = (centroid_[other] - centre).squaredNorm();
    if (!(distance2 <= radius2)) return false;
    take(other, distance2);
    return true;
  });
  if (list.size() > kMaxNeighbours) thin(t, list);
  // Stored as shares of the sum, then the sum of the rounded shares: the average is an exact
  // weighted mean of its list (a uniform stress is itself).
  double shares = 0.0;
  for (Neighbour& n : list) {
    n.weight /= weights;
    shares += n.weight;
  }
  scale_[t] = shares > 0.0 ? 1.0 / shares : 0.0;
}

NonlocalStress::PackedStress NonlocalStress::packed(const Mat2& s) { return {Double2{s(0, 0), s(1, 1)}, s(0, 1), 0.0}; }

void NonlocalStress::pack(const std::vector<Mat2>& local) {
  packed_.resize(local.size());
  for (std::size_t t = 0; t < local.size(); ++t) packed_[t] = packed(local[t]);
}

Mat2 NonlocalStress::averageAt(const std::vector<Mat2>& local, int t) const {
  if (scale_[t] == 0.0) return local[t];
  // This loop is most of a list's averaging, over about 100 neighbours a triangle at 64^2. Four partial
  // sums per component, each over every fourth neighbour: one running sum would wait on each
  // addition before the next (four cycles a neighbour); four independent ones let the additions
  // overlap. The order is fixed, so a cached average still equals a fresh one. The sums are those
  // of plain scalar code, lane by lane, in two-wide vectors: xx and yy of one neighbour together,
  // xy of two neighbours together (half the loads and arithmetic instructions of scalar code, the
  // same bits).
  const std::vector<Neighbour>& list = neighbours_[t];
  Double2 xxyy[4] = {Double2{0.0, 0.0}, Double2{0.0, 0.0}, Double2{0.0, 0.0}, Double2{0.0, 0.0}};
  Double2 xy01 = Double2{0.0, 0.0}, xy23 = Double2{0.0, 0.0};  // the xy partial sums 0, 1 and 2, 3
  const Neighbour* n = list.data();
  const std::size_t size = list.size();
  std::size_t i = 0;
  for (; i + 4 <= size; i += 4) {
    const PackedStress& s0 = packed_[n[i].triangle];
    const PackedStress& s1 = packed_[n[i + 1].triangle];
    const PackedStress& s2 = packed_[n[i + 2].triangle];
    const PackedStress& s3 = packed_[n[i + 3].triangle];
    const double w0 = n[i].weight, w1 = n[i + 1].weight, w2 = n[i + 2].weight, w3 = n[i + 3].weight;
    xxyy[0] += Double2{w0, w0} * s0.xxyy;
    xxyy[1] += Double2{w1, w1} * s1.xxyy;
    xxyy[2] += Double2{w2, w2} * s2.xxyy;
    xxyy[3] += Double2{w3, w3} * s3.xxyy;
    xy01 += Double2{w0, w1} * Double2{s0.xy, s1.xy};
    xy23 += Double2{w2, w3} * Double2{s2.xy, s3.xy};
  }
  double xy[4] = {xy01[0], xy01[1], xy23[0], xy23[1]};
  for (int k = 0; i < size; ++i, ++k) {
    const PackedStress& s = packed_[n[i].triangle];
    const double w = n[i].weight;
    xxyy[k] += Double2{w, w} * s.xxyy;
    xy[k] += w * s.xy;
  }
  const double sumXX = (xxyy[0][0] + xxyy[1][0]) + (xxyy[2][0] + xxyy[3][0]);
  const double sumYY = (xxyy[0][1] + xxyy[1][1]) + (xxyy[2][1] + xxyy[3][1]);
  const double sumXY = (xy[0] + xy[1]) + (xy[2] + xy[3]);
  Mat2 average;
  average << scale_[t] * sumXX, scale_[t] * sumXY, scale_[t] * sumXY, scale_[t] * sumYY;
  return average;
}

void NonlocalStress::rebuild(const ClothMesh& mesh, double radius) {
  radius_ = radius;
  kernel_ = StressKernel(radius);
  largestSize_ = 0.0;
  pending_.clear();
  pendingPlaces_.clear();
  changedPlaces_.clear();
  pendingMark_.assign(mesh.tris.size(), 0);
  centroid_.clear();
  area_.clear();
  lip_.clear();
  neighbours_.clear();
  scale_.clear();
  across_.clear();
  readsFrom_.clear();
  stamp_.assign(mesh.tris.size(), 0);
  currentStamp_ = 0;
  std::vector<int> all(mesh.tris.size());
  for (int t = 0; t < mesh.triangleCount(); ++t) all[t] = t;
  updateCentroids(mesh, all);
  for (int t = 0; t < mesh.triangleCount(); ++t) updateAcross(mesh, t);
  cachedTriangles_ = mesh.tris.size();
  built_ = true;
}

bool NonlocalStress::buildLattice(const std::vector<Mat2>& local, int threads, StressLattice& lattice) const {
  const std::size_t count = centroid_.size();
  if (count == 0) return false;
  long lowI = place_[0].x.node, highI = lowI, lowJ = place_[0].y.node, highJ = lowJ;
  for (const StressKernel::Place& place : place_) {
    lowI = std::min(lowI, place.x.node);
    highI = std::max(highI, place.x.node);
    lowJ = std::min(lowJ, place.y.node);
    highJ = std::max(highJ, place.y.node);
  }
  // A list's disc (radius r) is within this many nodes of its triangle's along each axis, give or
  // take the node a point lies past: hotNear covers it.
  const int hotReach = static_cast<int>(std::ceil(radius_ / kernel_.spacing())) + 1;
  if (!lattice.reset(lowI, highI, lowJ, highJ, std::max<std::size_t>(std::size_t{1} << 20, kNodesPerTriangle * count),
                     hotReach)) {
    return false;
  }
  for (std::size_t t = 0; t < count; ++t) {
    if (!lip_[t]) lattice.splat(place_[t], area_[t], local[t], hot_[t]);
  }
  lattice.blur(threads);
  return true;
}

void NonlocalStress::resolveReadings(const ClothMesh& mesh, const StressLattice* lattice) {
  const int count = static_cast<int>(centroid_.size());
  bool anyUnchecked = false;
  for (int t = 0; t < count && !anyUnchecked; ++t) anyUnchecked = readsFrom_[t] == ReadsFrom::Unchecked;
  if (!anyUnchecked && changedPlaces_.empty()) return;
  // A triangle the walk could miss lies beyond a border from t, within the kernel's reach: a
  // border triangle's centroid then lies within that reach plus a triangle's size. Near a crack's
  // lips a triangle reads a list (the lattice would read across the crack); near the cloth's own
  // border it reads the lattice if its walk finds all that the lattice reads.
  std::vector<Vec2> lipCentroids, borderCentroids;
  for (int t = 0; t < count; ++t) {
    if (lip_[t]) {
      lipCentroids.push_back(centroid_[t]);
      continue;
    }
    for (int e : mesh.tris[t].edge) {
      if (mesh.edges[e].isBoundary()) {
        borderCentroids.push_back(centroid_[t]);
        break;
      }
    }
  }
  const std::size_t maxCells = kNodesPerTriangle * centroid_.size() + 1024;
  BoxCounts lips, borders, changed;
  lips.build(lipCentroids, kernel_.spacing(), maxCells);
  borders.build(borderCentroids, kernel_.spacing(), maxCells);
  // Since the last call, tears changed the mesh around these places. A list can change only if a
  // changed triangle lies (or lay) within its disc: its walk goes through the disc only, so a cut
  // that changes which triangles it reaches runs through changed triangles within the disc too. A
  // triangle that read the lattice needs a list if a crack's lip came within its reach (a tear
  // adds borders only as lips).
  changed.build(changedPlaces_, kernel_.spacing(), maxCells);
  // The box above is widened to whole lattice cells (up to 1.9 times the disc's area): a list it
  // lets through is rebuilt only if a changed place lies within the disc itself, which is what
  // can change it (the same test as the walk's).
  PointsNear changedInDisc;
  changedInDisc.build(changedPlaces_, radius_);
  changedPlaces_.clear();
  const double near = kernel_.reach() + largestSize_;
  for (int t = 0; t < count; ++t) {
    switch (readsFrom_[t]) {
      case ReadsFrom::List:
        if (changed.anyWithin(centroid_[t], radius_) && changedInDisc.anyWithin(centroid_[t])) buildNeighbours(t);
        continue;
      case ReadsFrom::Lattice:
        if (changed.anyWithin(centroid_[t], near) && lips.anyWithin(centroid_[t], near)) {
          readsFrom_[t] = ReadsFrom::List;
          buildNeighbours(t);
        }
        continue;
      case ReadsFrom::Unchecked:
        break;
    }
    bool fromLattice = lattice != nullptr && !lips.anyWithin(centroid_[t], near);
    if (fromLattice && borders.anyWithin(centroid_[t], near)) {
      const double read = lattice->read(place_[t]).weight;
      fromLattice = std::abs(read - walkedKernelWeight(t)) <= kSameWeight * read;
    }
    if (fromLattice) {
      readsFrom_[t] = ReadsFrom::Lattice;
      std::vector<Neighbour>().swap(neighbours_[t]);
      scale_[t] = 0.0;
    } else {
      readsFrom_[t] = ReadsFrom::List;
      buildNeighbours(t);
    }
  }
}

void NonlocalStress::average(const ClothMesh& mesh, const std::vector<Mat2>& local, double radius, double threshold,
                             std::vector<Mat2>& out, int threads) {
  if (built_ && radius == radius_ && mesh.tris.size() == cachedTriangles_) collectChangedPlaces();
  if (!built_ || radius != radius_ || mesh.tris.size() != cachedTriangles_) rebuild(mesh, radius);
  out = local;
  pack(local);
  const int count = mesh.triangleCount();
  hot_.assign(count, 0);
  bool anyHot = false;
  for (int t = 0; t < count; ++t) {
    hot_[t] = largestPrincipal(local[t]) >= threshold;
    anyHot = anyHot || hot_[t];
  }
  if (!anyHot) return;
  // resolveReadings reads the lattice where a border is near.
  StressLattice& lattice = lattice_.value;
  const bool latticeUsable = buildLattice(local, threads, lattice);
  resolveReadings(mesh, latticeUsable ? &lattice : nullptr);
  // A triangle's average reads only what lies within its reach (its list, or the lattice's
  // sources there), so unless that holds a hot triangle the average stays below the threshold, as
  // the local stress does. A lip is not in its own list: a hot one is averaged, or it would keep
  // the stretch its average leaves out.
  needed_.assign(count, 0);
  std::vector<Mat2>& latticeAverage = latticeAverage_.value;
  latticeAverage.resize(count);
#pragma omp parallel for num_threads(std::max(1, threads)) schedule(static)
  for (int t = 0; t < count; ++t) {
    bool need = hot_[t];
    if (readsFrom_[t] == ReadsFrom::Lattice) {
      const StressLattice::Reading reading = lattice.read(place_[t]);
      latticeAverage[t] = reading.weight > 0.0 ? Mat2(reading.weightedStress / reading.weight) : local[t];
      need = need || reading.hot;
    } else if (need || !latticeUsable || lattice.read(place_[t]).hotNear) {
      // Where the lattice counts no hot triangle within the disc's reach, the list has none (and
      // is not read at all: after a crack has relieved the cloth round it, most are cold).
      for (const Neighbour& n : neighbours_[t]) {
        if (need) break;
        need = hot_[n.triangle];
      }
    }
    needed_[t] = need;
  }
  // Their vertex neighbours too: a fan that holds a needed triangle reads its other triangles'
  // averages.
  vertexNeeded_.assign(mesh.x.size(), 0);
  for (int t = 0; t < count; ++t) {
    if (!needed_[t]) continue;
    for (int v : mesh.tris[t].v) vertexNeeded_[v] = 1;
  }
#pragma omp parallel for num_threads(std::max(1, threads)) schedule(static)
  for (int t = 0; t < count; ++t) {
    const Triangle& tri = mesh.tris[t];
    if (!(needed_[t] || vertexNeeded_[tri.v[0]] || vertexNeeded_[tri.v[1]] || vertexNeeded_[tri.v[2]])) continue;
    out[t] = readsFrom_[t] == ReadsFrom::List ? averageAt(local, t) : latticeAverage[t];
  }
}

std::vector<int> NonlocalStress::patch(const ClothMesh& mesh, const std::vector<Mat2>& local,
                                       const std::vector<int>& changed, std::vector<Mat2>& out) {
  out.resize(mesh.tris.size(), Mat2::Zero());
  // Triangles the tear added are changed ones too, whether or not the caller listed them.
  std::vector<int> seeds = changed;
  for (std::size_t t = cachedTriangles_; t < mesh.tris.size(); ++t) seeds.push_back(static_cast<int>(t));
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  // Where each changed triangle was before the step's first tear touched it (a triangle a tear
  // added was nowhere): the triangles that read it there are checked again at the next average.
  pendingMark_.resize(mesh.tris.size(), 0);
  for (int t : seeds) {
    if (pendingMark_[t]) continue;
    pendingMark_[t] = 1;
    pending_.push_back(t);
    if (static_cast<std::size_t>(t) < cachedTriangles_) pendingPlaces_.push_back(centroid_[t]);
  }
  // A triangle's neighbours across its edges change when it or the one across an edge changed: the
  // seeds, the triangles across their edges before the tear (an edge the tear opened no longer
  // joins them) and after it (an edge the tear split now leads to a new triangle).
  std::vector<int> rejoined;
  for (int t : seeds) {
    if (static_cast<std::size_t>(t) >= cachedTriangles_) continue;
    for (int other : across_[t]) {
      if (other != kNone) rejoined.push_back(other);
    }
  }
  updateCentroids(mesh, seeds);
  for (int t : seeds) {
    rejoined.push_back(t);
    for (int e : mesh.tris[t].edge) {
      for (int other : mesh.edges[e].tri) {
        if (other != kNone) rejoined.push_back(other);
      }
    }
  }
  for (int t : rejoined) updateAcross(mesh, t);
  // The changed triangles' stresses (and new ones) into the packed copy the averages read, and
  // their own neighbourhoods and averages on the torn mesh: they lie on the crack, so they read
  // lists (the lattice holds the step's stresses on the mesh before the tear).
  packed_.resize(local.size());
  for (int t : seeds) packed_[t] = packed(local[t]);
  for (int t : seeds) {
    buildNeighbours(t);
    readsFrom_[t] = ReadsFrom::List;  // beside a lip
    out[t] = averageAt(local, t);
  }
  cachedTriangles_ = mesh.tris.size();
  return seeds;
}

void NonlocalStress::collectChangedPlaces() {
  if (pending_.empty()) return;
  changedPlaces_.insert(changedPlaces_.end(), pendingPlaces_.begin(), pendingPlaces_.end());
  for (int t : pending_) changedPlaces_.push_back(centroid_[t]);
  for (int t : pending_) pendingMark_[t] = 0;
  pending_.clear();
  pendingPlaces_.clear();
}

}  // namespace weft
