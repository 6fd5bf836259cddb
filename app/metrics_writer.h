#pragma once
// metrics.json of `weft run`: what a script needs to check a run without re-simulating it.
// Every key is documented in presets/scenes/README.md ("metrics.json").
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "sim/world.h"

namespace weft::app {

// Names as written in scene files (solver.integrator, solver.linear_solver.type).
std::string integratorName(IntegratorKind kind);
std::string linearSolverName(LinearSolverKind kind);

// "0123456789abcdef": the state hash as 16 hex digits, as compared between runs.
std::string hashHex(std::uint64_t hash);

// The metrics of a finished (or stopped) run. `wallSeconds` is the time spent stepping.
nlohmann::ordered_json runMetrics(const World& world, double wallSeconds);

}  // namespace weft::app
