#pragma once
// The tearing stage of a step (thesis §3.5, after collision response): for each cloth with a tear
// table, the tensile stress of its triangles at the end of the step, then, while some vertex has a
// line with omega > 1:
//   1. search: the best line (tear_search.h), among the vertices not yet refused this step;
//   2. surgery: tear along it (tear_mesh.h); when the mesh refuses, the vertex's next best line,
//      then the next vertex (no stall: a refused line never stops the cloth from tearing);
//   3. relax (with `propagate`): the stress around the new crack ends relaxed locally
//      (crack_relaxation.h), so the next search sees the stress the crack shed onto its tip.
// A crack therefore grows as far within a step as its tips' omega stays above 1, each tip up to
// crack_speed * dt (a crack through an interior vertex has two, each with its own budget:
// tear_stage.cpp's CrackFronts): its speed is a material length per second, not one element per step,
// so crack growth does not depend on the mesh's resolution. Without `propagate` the stage tears
// the thesis' way: up to tears_per_step lines per step from one stress evaluation, the next step's
// dynamics relaxing the rest (its §3.2).
// With `incubation_s` a crack starts only at a vertex whose omega has stayed above 1 for that long
// (each step of it, as the step's search offered the vertex); the tips of existing cracks run on at
// once. This is the incubation-time criterion of dynamic fracture in its simplest form (Petrov &
// Morozov 1994, "On the incubation time criterion of fracture"): a stress must act for a time before
// it breaks the material, so short spikes do not. Why it is needed: when a crack crosses a pulled
// sheet in a few steps, the ligament it has not cut yet carries the whole load and reads omega > 1
// far from the tip for those steps, and a strip that tore free whips into its clamp; without a
// delay each spike started a crack of its own, where and whether depending on the mesh (measured:
// the pulled sheet tore 1.3 / 2.4 / 2.3 m at 32 / 48 / 64^2; with 0.04 s, 1.00 m at each).
// With `initiation_every` k > 1, new cracks are looked for in every k-th step only (a sample); in
// between, only a torn cloth's crack tips are offered (TearSearch's tips-only start): cracks run
// on every step as with k = 1, while the whole sheet's start and incubation questions, which cost
// a loaded sheet a search of every vertex a step, are asked k times less often. The incubation clocks read a vertex's overload at
// the samples, so a crack starts up to k - 1 steps later than with k = 1.
// Every cache of the cloth is updated locally; the integrators and the contact stage are told by
// the world, with what changed, and patch what depends on the topology.
#include <unordered_map>
#include <vector>

#include "forces/membrane_ahead.h"
#include "mesh/topology_change.h"
#include "scene/scene.h"
#include "sim/stage_profile.h"
#include "tearing/crack_relaxation.h"
#include "tearing/incubation_clocks.h"
#include "tearing/nonlocal_stress.h"
#include "tearing/tear_candidates.h"
#include "tearing/tear_record.h"
#include "tearing/tear_search.h"
#include "util/scratch.h"
#include "util/types.h"

namespace weft {

struct Cloth;

class TearStage {
 public:
  explicit TearStage(const Scene& scene);
  // After a live edit of the cloths' materials: whether the stage runs follows their tear tables
  // (the log, the statistics and the per-cloth caches are kept).
  void materialsChanged(const Scene& scene);
  // The scene has a cloth with a tear table and tearing is on.
  bool runs() const { return runs_; }
  // Tears what must tear in a step of length dt ending at `time`; returns, per cloth, what all its
  // tears of this step changed together (empty when it did not tear).
  // `ahead`: per cloth, its membrane evaluated at the current positions (forces/membrane_ahead.h),
  // whose stresses are read instead of evaluated again (may be empty or hold stale entries).
  // `threads`: the stage's per-triangle passes (the averaged stress) run on that many threads; the
  // result does not depend on it.
  std::vector<TopologyChange> run(std::vector<Cloth>& cloths, const std::vector<MembraneAhead>& ahead, double time,
                                  double dt, int threads, StageProfile& profile);
  std::vector<TopologyChange> run(std::vector<Cloth>& cloths, double time, double dt, StageProfile& profile) {
    return run(cloths, {}, time, dt, 1, profile);
  }
  const std::vector<TearRecord>& log() const { return log_; }
  const TearStats& stats() const { return stats_; }
  std::size_t heapBytes() const;  // util/heap_bytes.h (defined in sim/world_memory.cpp)

 private:
  // One cloth's step; returns what it changed.
  // `tipsOnly`: a step between samples (above): only crack tips are offered.
  TopologyChange tearCloth(Cloth& cloth, int clothIndex, const MembraneAhead* ahead, double time, double dt,
                           int threads, bool tipsOnly, StageProfile& profile);
  // Whether the vertex has been overloaded for the incubation time at the end of this step.
  bool incubated(const Incubating& vertex, double time, double dt) const;
  // The vertices still incubating whose omega stays above 1 are kept in `now` and held from
  // starting a crack this step, at the cost of one line each where their load barely moved (not a
  // search of their whole fan, as offering them would cost).
  void holdIncubating(const Cloth& cloth, const std::vector<TriangleCorners>& corners,
                      const IncubationClocks& before, double time, double dt, IncubationClocks& now);

  TearingSpec spec_;
  TearSearchSettings searchSettings_;
  CrackRelaxationSettings relaxation_;
  bool runs_ = false;
  long long steps_ = 0;             // the steps this stage has run (its samples are multiples of k)
  std::vector<Mat2> localStress_;  // sigma+ per triangle, as tensile_stress.h gives it
  std::vector<Mat2> stress_;       // what the search reads: localStress_, averaged when stress_length > 0
  std::vector<NonlocalStress> nonlocal_;  // per cloth: its neighbourhoods are its mesh's, patched after each tear
  std::vector<std::vector<TriangleCorners>> corners_;  // per cloth, patched after each tear
  TearSearch search_;
  int searchedCloth_ = -1;  // the cloth search_ last searched: its rows are kept for that cloth only
  std::vector<IncubationClocks> overloadedSince_;  // per cloth
  Scratch<IncubationClocks> overloadedNow_;       // this step's, becomes the cloth's at its end
  std::vector<std::unordered_map<int, double>> overshoot_;  // per cloth: crack tip -> metres run past its
                                                            // last step's reach, owed to the next
  std::vector<TearRecord> log_;
  TearStats stats_;
};

}  // namespace weft
