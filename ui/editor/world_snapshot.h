#pragma once
// What the editor shows of a world, copied out of it between steps: the meshes to draw and the
// numbers the panels print. The simulation steps on a worker thread (step_worker.h); the window
// draws and the panels read this copy, so they never wait for a step or read a world mid-step.
// Plain data, no GL and no ImGui.
#include <memory>
#include <string>
#include <vector>

#include "mesh/cloth_mesh.h"
#include "render_view.h"
#include "sim/stage_profile.h"
#include "sim/world.h"

namespace weft::editor {

struct WorldSnapshot {
  double time = 0.0;        // s
  long long stepCount = 0;
  std::vector<ClothMesh> cloths;  // copies of the world's cloths; render's cloth views point here
  ui::RenderView render;          // what the viewport draws
  StageProfile profile;           // total ms by stage since the start
  SolverStats solver;
  long long tears = 0;
  std::vector<std::string> stagesRun;
  // Energies cost a force evaluation: refreshed every kMetricsEverySteps steps, not every step.
  WorldMetrics metrics;
  long long metricsStep = -1;  // the step the metrics are from
  static constexpr long long kMetricsEverySteps = 30;

  WorldSnapshot() = default;
  // The render view points into this object's own meshes: not copied or moved, only shared.
  WorldSnapshot(const WorldSnapshot&) = delete;
  WorldSnapshot& operator=(const WorldSnapshot&) = delete;
};

// The world as it is now. The metrics come along from `previous` while they are recent enough.
// Call only while nothing steps the world.
std::shared_ptr<const WorldSnapshot> snapshotOf(const World& world, const WorldSnapshot* previous = nullptr);

}  // namespace weft::editor
