#include "world_snapshot.h"

namespace weft::editor {

std::shared_ptr<const WorldSnapshot> snapshotOf(const World& world, const WorldSnapshot* previous) {
  auto snapshot = std::make_shared<WorldSnapshot>();
  snapshot->time = world.time();
  snapshot->stepCount = world.stepCount();
  snapshot->render = ui::renderViewOf(world);
  snapshot->cloths.reserve(static_cast<std::size_t>(world.clothCount()));
  for (int i = 0; i < world.clothCount(); ++i) snapshot->cloths.push_back(world.cloth(i));
  for (std::size_t i = 0; i < snapshot->cloths.size() && i < snapshot->render.cloths.size(); ++i) {
    snapshot->render.cloths[i].mesh = &snapshot->cloths[i];
  }
  snapshot->profile = world.profile();
  snapshot->solver = world.solverStats();
  snapshot->tears = world.tearStats().tears;
  snapshot->stagesRun = world.stagesRun();
  const bool recent = previous != nullptr && previous->metricsStep >= 0 && snapshot->stepCount >= previous->metricsStep &&
                      snapshot->stepCount - previous->metricsStep < WorldSnapshot::kMetricsEverySteps;
  if (recent) {
    snapshot->metrics = previous->metrics;
    snapshot->metricsStep = previous->metricsStep;
  } else {
    snapshot->metrics = world.metrics();
    snapshot->metricsStep = snapshot->stepCount;
  }
  return snapshot;
}

}  // namespace weft::editor
