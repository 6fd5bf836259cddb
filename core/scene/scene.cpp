#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace weft {

// A frame spans 1/fps seconds; the solver covers it in whole steps of dt. Rounding (rather than
// truncating) keeps 1/30 s frames at exactly 2 steps when dt = 1/60 is written as 0.016666.
// At least one step per frame, so a dt longer than a frame still advances the simulation.
// The count is 64-bit and the scene reader bounds it (scene_limits.h); it is clamped here too so
// that a Scene built in code cannot overflow it either.
std::int64_t stepsPerFrame(const Scene& scene) {
  const double steps = 1.0 / (scene.output.fps * scene.solver.dt);
  if (!std::isfinite(steps)) return 1;
  return std::clamp<std::int64_t>(std::llround(std::min(steps, 4e18)), 1, std::int64_t{1} << 62);
}

}  // namespace weft
