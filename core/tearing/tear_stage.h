#pragma once
// The tearing stage of a step (thesis §3.5, after collision response): for each cloth with a tear
// table, the tensile stress of its triangles at the end of the step, the best fracture line of
// each vertex, the selection, and the mesh surgery, with every cache of the cloth updated locally.
// The integrators and the contact stage are told by the world, with what changed, and patch what
// depends on the topology.
#include <vector>

#include "mesh/topology_change.h"
#include "scene/scene.h"
#include "sim/stage_profile.h"
#include "tearing/tear_candidates.h"
#include "tearing/tear_selection.h"
#include "util/types.h"

namespace weft {

struct Cloth;

// One tear, as the tear log of metrics.json lists it.
struct TearRecord {
  double time = 0.0;        // s, end of the step that tore
  int cloth = 0;
  int vertex = kNone;       // the vertex the line went through (before the split)
  Vec3 position = Vec3::Zero();  // world position of that vertex (m)
  Vec2 restPosition = Vec2::Zero();  // its material-space position (m)
  double angleDeg = 0.0;    // the line's direction in material space, degrees from material x
  double alphaDeg = 0.0;    // from the warp direction V (Eq. 3.1-3.3)
  bool ray = false;         // opened from a border or an earlier tear (one side only)
  double separation = 0.0;  // zeta (N/m)
  double required = 0.0;    // R(alpha) (N/m)
  double ratio = 0.0;       // omega
};

struct TearStats {
  long long tears = 0;
  long long refused = 0;     // selected lines the mesh guards refused (the cloth stays whole there)
  TearSearchCounts search;
};

class TearStage {
 public:
  explicit TearStage(const Scene& scene);
  // After a live edit of the cloths' materials: whether the stage runs follows their tear tables
  // (the log, the statistics and the per-cloth caches are kept).
  void materialsChanged(const Scene& scene);
  // The scene has a cloth with a tear table and tearing is on.
  bool runs() const { return runs_; }
  // Tears what must tear; returns, per cloth, what all its tears of this step changed together
  // (empty when it did not tear).
  std::vector<TopologyChange> run(std::vector<Cloth>& cloths, double time, StageProfile& profile);
  const std::vector<TearRecord>& log() const { return log_; }
  const TearStats& stats() const { return stats_; }

 private:
  TearingSpec spec_;
  TearSearchSettings search_;
  TearSelectionSettings selection_;
  bool runs_ = false;
  std::vector<Mat2> stress_;
  std::vector<std::vector<TriangleCorners>> corners_;  // per cloth, patched after each tear
  std::vector<TearCandidate> candidates_;
  std::vector<TearRecord> log_;
  TearStats stats_;
};

}  // namespace weft
