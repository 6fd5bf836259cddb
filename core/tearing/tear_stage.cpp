#include "tearing/tear_stage.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <optional>
#include <unordered_map>

#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "tearing/tear_mesh.h"
#include "tearing/tensile_stress.h"
#include "tearing/vertex_fan.h"

namespace weft {

namespace {

// How far each copy of a separated vertex moves into its own side (m). The copies start at one
// point, so the two lips of a fresh tear touch exactly: self-collision could not tell which side
// is which and would treat the seam as a collision in every step (ARCSim nudges its copies apart
// too). A micrometre is far below any contact thickness: the proximity pass then sees two lips
// in contact with a well-defined normal, as it would after any fold.
constexpr double kCopySeparation = 1e-6;

// A bound on the work of one step: no cloth tears more often than this in one step, whatever the
// crack speed (a 64 x 64 sheet torn apart along both diagonals takes about 250).
constexpr int kMaxTearsPerStep = 4096;

// With propagation, a crack that tore this step runs on from its new tips while they read at
// least this fraction of the strength they need, until it has run crack_speed * dt. The stress a
// new tip reads is the step's, from before the crack reached it: it lacks the concentration the
// running crack brings with it (a tip concentrates the load it took off its lips), which the next
// step's solve restores. Half the strength is the far field a crack runs on through, as a tip
// concentrating the load at least twofold would see it.
constexpr double kRunOnRatio = 0.5;

// Whether the cloth has been torn (its cracks' tips may run on between initiation samples).
bool hasCracks(const ClothMesh& mesh) {
  return std::any_of(mesh.edges.begin(), mesh.edges.end(), [](const Edge& edge) { return edge.torn; });
}

// Moves each copy of a separated vertex (and its original) towards the middle of its own
// triangles, so the lips of the tear no longer coincide. Velocities are not touched (momentum is
// kept); the masses do not move by more than a micrometre. Each vertex's triangles are walked from
// one the change touched (a pass over every triangle per tear was a tenth of the stage's time),
// and summed in ascending id order, as that pass summed them.
void nudgeCopiesApart(ClothMesh& mesh, const TopologyChange& change) {
  if (change.vertexCopies.empty()) return;
  std::vector<int> moved;
  for (const auto& [original, copy] : change.vertexCopies) {
    moved.push_back(original);
    moved.push_back(copy);
  }
  // Every copy lies in a changed triangle; its original on a changed edge (the opened lip's own).
  std::vector<int> touched = change.changedTriangles;
  for (int e : change.changedEdges) {
    for (int t : mesh.edges[e].tri) {
      if (t != kNone) touched.push_back(t);
    }
  }
  std::vector<Vec3> towards(moved.size(), Vec3::Zero());
  for (std::size_t k = 0; k < moved.size(); ++k) {
    const int vertex = moved[k];
    const auto start = std::find_if(touched.begin(), touched.end(), [&](int t) {
      return cornerOf(mesh.tris[t], vertex) != kNone;
    });
    const int from = start != touched.end() ? *start : findTriangleAt(mesh, vertex);
    if (from == kNone) continue;
    std::vector<int> triangles = walkFan(mesh, vertex, from).triangles;
    std::sort(triangles.begin(), triangles.end());
    for (int t : triangles) {
      const Triangle& tri = mesh.tris[t];
      towards[k] += (mesh.x[tri.v[0]] + mesh.x[tri.v[1]] + mesh.x[tri.v[2]]) / 3.0 - mesh.x[vertex];
    }
  }
  for (std::size_t k = 0; k < moved.size(); ++k) {
    const double length = towards[k].norm();
    if (length > 0.0 && std::isfinite(length)) mesh.x[moved[k]] += (kCopySeparation / length) * towards[k];
  }
}

// Rest length of an edge (m), from a triangle that holds it.
double restLength(const ClothMesh& mesh, int e) {
  const Edge& edge = mesh.edges[e];
  const Triangle& t = mesh.tris[edge.tri[0]];
  return (t.rest[cornerOf(t, edge.v[0])] - t.rest[cornerOf(t, edge.v[1])]).norm();
}

// How far each crack tip of this step has run: a tear at a vertex that is not the end of a crack
// made this step starts a new front (or continues, from an earlier step, a tip with its carried
// overshoot); a tear at such an end continues it. A tear through an interior vertex opens two tips,
// each its own front from there on with half the torn length run: crack_speed is a tip's speed, as
// a crack in a sheet runs from each of its ends at once, so a crack started inside the sheet grows
// twice as fast as one from the border (a shared budget made each of its tips half as fast, and how
// far a crack got then hung on where its first tear fell).
struct CrackFronts {
  std::unordered_map<int, int> frontAt;  // crack end made this step -> its front
  std::vector<double> advanced;          // per front: how far its tip has run (m)

  int frontOf(int vertex, const std::unordered_map<int, double>& carried) {
    const auto found = frontAt.find(vertex);
    if (found != frontAt.end()) return found->second;
    const auto carry = carried.find(vertex);
    advanced.push_back(carry != carried.end() ? carry->second : 0.0);
    return static_cast<int>(advanced.size()) - 1;
  }

  // A tear at `front`'s tip of `tornLength` (m) that left `ends`: each end runs on from the tip's
  // distance plus its share of the torn length, the first on the tip's front, others on new ones.
  void advance(int front, double tornLength, const std::vector<int>& ends) {
    const double run = advanced[front] + tornLength / static_cast<double>(std::max<std::size_t>(1, ends.size()));
    advanced[front] = run;
    for (std::size_t k = 0; k < ends.size(); ++k) {
      if (k > 0) advanced.push_back(run);
      frontAt[ends[k]] = k > 0 ? static_cast<int>(advanced.size()) - 1 : front;
    }
  }
};

}  // namespace

TearStage::TearStage(const Scene& scene) : spec_(scene.tearing) {
  searchSettings_.lines = spec_.denseLines ? CandidateLines::Dense : CandidateLines::Thesis;
  searchSettings_.denseDirections = spec_.denseDirections;
  searchSettings_.skipByBound = spec_.skipByBound;
  searchSettings_.branchFromLips = spec_.branchFromLips;
  // With averaged stress a fan's sectors differ only by the shift of their discs, a fraction of an
  // element against a radius of several: read as one (tear_search.h).
  searchSettings_.closedFanAsOne = spec_.stressLength > 0.0;
  // With averaged stress a tip reads its own fan (the average already spans the material ahead).
  searchSettings_.tipLength = spec_.propagate && spec_.stressLength == 0.0 ? spec_.crackTipLength : 0.0;
  // The largest kink of the maximum hoop stress criterion (Erdogan & Sih 1963), as crack_tip_stress.h.
  if (spec_.propagate) searchSettings_.maxKinkRad = 70.5 * std::numbers::pi / 180.0;
  const double tipReach = spec_.stressLength > 0.0 ? spec_.stressLength : searchSettings_.tipLength;
  if (spec_.propagate && tipReach > 0.0) searchSettings_.startClearance = 2.0 * tipReach;
  relaxation_.rings = spec_.relaxRings;
  relaxation_.sweeps = spec_.relaxSweeps;
  materialsChanged(scene);
}

void TearStage::materialsChanged(const Scene& scene) {
  bool anyTable = false;
  for (const ClothSpec& cloth : scene.cloths) anyTable = anyTable || cloth.material.tearTable.has_value();
  runs_ = scene.stages.tearing && anyTable;
}

bool TearStage::incubated(const Incubating& vertex, double time, double dt) const {
  return time - vertex.since >= spec_.incubation - 1e-9 * dt;
}

void TearStage::holdIncubating(const Cloth& cloth, const std::vector<TriangleCorners>& corners,
                               const IncubationClocks& before, double time, double dt, IncubationClocks& now) {
  for (int vertex : before.vertices()) {
    Incubating incubating = before.at(vertex);
    if (incubated(incubating, time, dt)) continue;  // offered as usual: it may start a crack now
    if (!search_.overloadedAsStart(cloth.mesh, corners, stress_, vertex, incubating.angle, incubating.angle,
                                   stats_.search)) {
      continue;  // its omega fell to 1 or below: its clock stops
    }
    now.set(vertex, incubating);
    search_.hold(vertex);
  }
}

std::vector<TopologyChange> TearStage::run(std::vector<Cloth>& cloths, const std::vector<MembraneAhead>& ahead,
                                           double time, double dt, int threads, StageProfile& profile) {
  std::vector<TopologyChange> changed(cloths.size());
  if (!runs_) return changed;
  if (corners_.size() != cloths.size()) corners_.resize(cloths.size());
  if (nonlocal_.size() != cloths.size()) nonlocal_.resize(cloths.size());
  const bool sample = steps_ % spec_.initiationEvery == 0;
  ++steps_;
  for (std::size_t c = 0; c < cloths.size(); ++c) {
    if (!cloths[c].material.tearTable) continue;
    if (!sample && !hasCracks(cloths[c].mesh)) continue;  // no tip to run on, and no new crack looked for
    changed[c] = tearCloth(cloths[c], static_cast<int>(c), c < ahead.size() ? &ahead[c] : nullptr, time, dt, threads,
                           !sample, profile);
  }
  return changed;
}

TopologyChange TearStage::tearCloth(Cloth& cloth, int clothIndex, const MembraneAhead* ahead, double time, double dt,
                                   int threads, bool tipsOnly, StageProfile& profile) {
  TopologyChange changed;
  const TearTable& table = *cloth.material.tearTable;
  TearGuards guards;
  guards.minEdgeLength = spec_.minEdgeLength;
  guards.minAngleDeg = spec_.minAngleDeg;
  guards.snapAngleDeg = spec_.snapAngleDeg;
  std::vector<TriangleCorners>& corners = corners_[clothIndex];
  if (corners.size() != cloth.mesh.tris.size()) corners = triangleCorners(cloth.mesh);
  if (overshoot_.size() != corners_.size()) overshoot_.resize(corners_.size());
  if (overloadedSince_.size() != corners_.size()) overloadedSince_.resize(corners_.size());
  const IncubationClocks& overloadedBefore = overloadedSince_[clothIndex];
  // The vertices overloaded this step: held while incubating, offered once mature, or found newly
  // above 1.
  IncubationClocks& overloadedNow = overloadedNow_.value;
  overloadedNow.clear();
  {
    StageTimer timer(profile, "tear_stress");
    tensileStresses(cloth, ahead, localStress_);
    if (spec_.stressLength > 0.0) {
      // Only where some triangle could reach a run-on tip's share of the weakest strength (the
      // largest principal stress bounds zeta within pi: separation_strength.h's bound).
      const double threshold =
          kRunOnRatio * std::min(1.0, table.propagationFactor) * weakestStrength(table) / std::numbers::pi *
          (cloth.tearStrengthMap ? std::min(1.0, cloth.tearStrengthMap->smallest) : 1.0) *
          (cloth.tearRegion ? lowestRegionFactor(*cloth.tearRegion, table) : 1.0);
      nonlocal_[clothIndex].average(cloth.mesh, localStress_, spec_.stressLength, threshold, stress_, threads);
    } else {
      stress_ = localStress_;
    }
  }
  {
    StageTimer timer(profile, "tear_search");
    search_.setStrengthMap(cloth.tearStrengthMap ? &*cloth.tearStrengthMap : nullptr);
    search_.setTearRegion(cloth.tearRegion ? &*cloth.tearRegion : nullptr);
    if (clothIndex != searchedCloth_) search_.forgetMesh();
    searchedCloth_ = clothIndex;
    search_.start(cloth.mesh, corners, stress_, table, cloth.weftAngleRad, searchSettings_, stats_.search, tipsOnly);
    if (!tipsOnly && spec_.incubation > 0.0 && !incubated(Incubating{time - dt, 0.0}, time, dt)) {
      // Only vertices that have waited long enough are offered as crack starts; the others are
      // asked only whether they are (still) overloaded.
      std::vector<char> mature(cloth.mesh.x.size(), 0);
      for (int vertex : overloadedBefore.vertices()) mature[vertex] = incubated(overloadedBefore.at(vertex), time, dt);
      search_.gateStarts(std::move(mature));
      holdIncubating(cloth, corners, overloadedBefore, time, dt, overloadedNow);
    }
  }
  // A crack tip runs at most this far per step (m); without propagation the stage stops after
  // maxTearsPerStep tears instead.
  const double reach = spec_.propagate ? spec_.crackSpeed * dt : std::numeric_limits<double>::infinity();
  const int maxTears = spec_.propagate ? kMaxTearsPerStep : spec_.maxTearsPerStep;
  CrackFronts fronts;
  std::unordered_map<int, double> stillOwed;
  std::vector<Vec2> started;  // where this step's tears were, for the spacing of new cracks
  int tears = 0;
  int crackStarts = 0;
  std::deque<int> running;  // tips of this step's cracks, in the order they were made
  std::vector<std::vector<int>> hingeChanges;  // each tear's changed edges: the hinges, after the loop
  for (int pass = 0; pass < 4 * kMaxTearsPerStep && tears < maxTears; ++pass) {
    std::optional<TearCandidate> best;
    {
      StageTimer timer(profile, "tear_search");
      while (!running.empty() && !best) {
        const TearCandidate line = search_.tipLineAt(cloth.mesh, corners, stress_, running.front(), stats_.search);
        running.pop_front();
        if (line.vertex != kNone && line.ratio >= kRunOnRatio) best = line;
      }
      if (!best) best = search_.best(cloth.mesh, corners, stress_, stats_.search);
    }
    if (!best) break;
    const int vertex = best->vertex;
    // A tear that does not continue a crack of this step keeps its distance from this step's
    // tears: the stress around them is stale until the cloth moves (their neighbours still read
    // the load the crack took off them), so cracks started beside them would be false.
    // With propagation, at most tears_per_step new cracks start per step (the thesis' one): a
    // crack that starts relieves its neighbours only as the cloth moves, so several started at
    // once along an evenly loaded border would all run, side by side.
    const bool continues = fronts.frontAt.contains(vertex);
    const bool starts = !continues && !best->crackTip;
    if (starts && tipsOnly) {  // a lip with branch_from_lips: it starts a crack, at the next sample
      search_.exclude(vertex);
      continue;
    }
    if (starts && spec_.incubation > 0.0) {
      // Held vertices are never offered as starts: this one has waited long enough, or its omega
      // has just gone above 1.
      const Incubating* since = overloadedBefore.find(vertex);
      overloadedNow.set(vertex, Incubating{since != nullptr ? since->since : time - dt, best->angle});
      if (!incubated(*overloadedNow.find(vertex), time, dt)) {
        search_.exclude(vertex);
        continue;
      }
    }
    // Within a crack tip's reach the stress is the tip's own (its concentration): the tip decides
    // there, or every tip would grow a fringe of parallel cracks beside it. Beside a crack's lips
    // the stress is the opening's: the row of triangles along a lip takes up the lip's sliding as
    // shear, which read as a load would start cracks across the first one.
    const double tipReach = spec_.stressLength > 0.0 ? spec_.stressLength : searchSettings_.tipLength;
    if ((starts && spec_.propagate && tipReach > 0.0 && search_.nearCrack(cloth.mesh, best->restPosition, 2.0 * tipReach)) ||
        (starts && spec_.propagate && crackStarts >= spec_.maxTearsPerStep) ||
        (!continues && std::any_of(started.begin(), started.end(), [&](const Vec2& p) {
          return (p - best->restPosition).norm() < spec_.minSpacing;
        }))) {
      search_.exclude(vertex);
      continue;
    }
    const int front = fronts.frontOf(vertex, overshoot_[clothIndex]);
    if (fronts.advanced[front] >= reach) {
      if (!continues) stillOwed[vertex] = fronts.advanced[front] - reach;  // a tip still paying off
      ++stats_.stoppedBySpeed;
      search_.exclude(vertex);
      continue;
    }

    // 2. The surgery: the best line, then the vertex's other lines above 1.
    std::optional<StageTimer> surgeryTimer(std::in_place, profile, "tear_surgery");
    const Vec3 position = cloth.mesh.x[vertex];
    TopologyChange change;
    std::optional<TearCandidate> torn;
    auto tryLine = [&](const TearCandidate& line) {
      if (tearThroughVertex(cloth.mesh, vertex, Vec2(std::cos(line.angle), std::sin(line.angle)), guards,
                            cloth.material.areaDensity, change)) {
        torn = line;
        return true;
      }
      ++stats_.refused;
      return false;
    };
    if (!tryLine(*best)) {
      for (const TearCandidate& line : search_.linesAt(cloth.mesh, corners, stress_, vertex)) {
        if (std::abs(line.angle - best->angle) < 1e-12) continue;
        if (tryLine(line)) break;
      }
    }
    if (!torn) {
      surgeryTimer.reset();
      search_.exclude(vertex);
      continue;
    }
    applyTopologyChangeButHinges(cloth, change);
    hingeChanges.push_back(change.changedEdges);
    updateTriangleCorners(cloth.mesh, change.changedTriangles, corners);
    nudgeCopiesApart(cloth.mesh, change);
    accumulateTopologyChange(changed, change);
    ++stats_.tears;
    ++tears;
    if (starts) ++crackStarts;
    started.push_back(torn->restPosition);

    TearRecord record;
    record.time = time;
    record.cloth = clothIndex;
    record.vertex = vertex;
    record.position = position;
    record.restPosition = torn->restPosition;
    record.angleDeg = torn->angle * 180.0 / std::numbers::pi;
    record.alphaDeg = torn->alphaDeg;
    record.ray = torn->ray;
    record.separation = torn->separation;
    record.required = torn->required;
    record.ratio = torn->ratio;
    log_.push_back(record);

    // Each tip of the crack advanced by its share of the torn length (an interior tear opens two).
    double tornLength = 0.0;
    for (int e : change.tornEdges) tornLength += 0.5 * restLength(cloth.mesh, e);
    fronts.advance(front, tornLength, change.crackEnds);
    if (spec_.propagate) running.insert(running.end(), change.crackEnds.begin(), change.crackEnds.end());
    surgeryTimer.reset();

    // 3. The stress after the tear: the changed triangles at the current positions, then (with
    // propagation) the patch around the crack ends relaxed.
    std::vector<int> restressed = change.changedTriangles;
    {
      StageTimer timer(profile, "tear_relax");
      tensileStresses(cloth, change.changedTriangles, localStress_);
      if (spec_.propagate && spec_.relaxSweeps > 0) {
        std::vector<int> ends = change.crackEnds;
        ends.push_back(vertex);
        const std::vector<int> patch = relaxAroundCrack(cloth, ends, relaxation_, localStress_);
        restressed.insert(restressed.end(), patch.begin(), patch.end());
      }
      if (spec_.stressLength > 0.0) {
        // The averages that read a changed triangle, on both sides of the new lips (an opened
        // edge's other side keeps its triangles; only the edge changed).
        std::vector<int> seeds = restressed;
        for (int e : change.changedEdges) {
          for (int t : cloth.mesh.edges[e].tri) {
            if (t != kNone) seeds.push_back(t);
          }
        }
        std::sort(seeds.begin(), seeds.end());
        seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
        restressed = nonlocal_[clothIndex].patch(cloth.mesh, localStress_, seeds, stress_);
      } else {
        stress_.resize(localStress_.size());
        for (int t : restressed) stress_[t] = localStress_[t];
      }
    }
    StageTimer timer(profile, "tear_search");
    std::vector<int> vertices = change.massChangedVertices;
    vertices.insert(vertices.end(), change.crackEnds.begin(), change.crackEnds.end());
    vertices.push_back(vertex);
    search_.refresh(cloth.mesh, corners, stress_, restressed, vertices, stats_.search);
  }
  if (!hingeChanges.empty()) {
    StageTimer timer(profile, "tear_surgery");
    refreshHingesAfter(cloth, hingeChanges);
  }
  // A vertex not offered this step dropped below omega = 1, unless the step stopped before offering
  // everything above 1 (its tear budget ran out): then the vertices of the last step keep waiting.
  // Between samples no vertex was asked: the clocks wait for the next sample as they are.
  if (spec_.incubation > 0.0 && !tipsOnly) {
    // The vertices whose omega went above 1 this step start their clocks.
    for (const TearSearch::Overloaded& found : search_.newlyOverloaded()) {
      overloadedNow.add(found.vertex, Incubating{time - dt, found.angle});
    }
    if (tears >= maxTears) {
      for (int vertex : overloadedBefore.vertices()) overloadedNow.add(vertex, overloadedBefore.at(vertex));
    }
    std::swap(overloadedSince_[clothIndex], overloadedNow);
  }
  // A tip that ran past its reach (a tear opens a whole edge) owes the excess to the next step, so
  // that on average no tip runs faster than crack_speed, whatever the element size.
  std::unordered_map<int, double>& owed = overshoot_[clothIndex];
  owed = std::move(stillOwed);
  if (spec_.propagate) {
    for (const auto& [end, front] : fronts.frontAt) {
      if (fronts.advanced[front] > reach) owed[end] = fronts.advanced[front] - reach;
    }
  }
  return changed;
}

}  // namespace weft
