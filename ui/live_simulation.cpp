#include "live_simulation.h"

#include <cstdio>
#include <utility>

#include "scene/scene_json.h"
#include "sim/finite_state.h"

namespace weft::ui {

LiveSimulation::LiveSimulation(std::filesystem::path sceneFile, std::vector<std::string> overrides)
    : sceneFile_(std::move(sceneFile)), overrides_(std::move(overrides)) {
  world_ = std::make_unique<World>(loadScene(sceneFile_, overrides_));
}

bool LiveSimulation::advanceFrame() { return paused_ ? false : step(stepsPerFrame(scene())); }

bool LiveSimulation::stepOnce() { return paused_ ? step(1) : false; }

bool LiveSimulation::step(int steps) {
  if (stopped_) return false;
  for (int s = 0; s < steps; ++s) world_->step();
  stopped_ = !stateIsFinite(*world_);
  return stopped_;
}

void LiveSimulation::reload() {
  // Built completely before it replaces the current world, so a bad file changes nothing.
  auto fresh = std::make_unique<World>(loadScene(sceneFile_, overrides_));
  world_ = std::move(fresh);
  stopped_ = false;
}

std::string LiveSimulation::status() const {
  char text[256];
  std::snprintf(text, sizeof text, "%s  t = %.3f s%s", scene().name.c_str(), world_->time(),
                stopped_ ? "  stopped: non-finite state (R reloads)" : paused_ ? "  paused" : "");
  return text;
}

}  // namespace weft::ui
