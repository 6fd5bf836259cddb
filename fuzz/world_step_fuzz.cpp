// libFuzzer target: the step. `--set` overrides on a shipped scene (as scene_overrides_fuzz.cpp),
// and for a scene the loader accepts, the World it builds stepped a few steps the way `weft run`
// steps it (app/run_command.cpp): the health check after every step, stopping at its first failure,
// then the state's finiteness. Whatever the overrides ask for (dt = 1 s, gravity 1000 m/s^2, wind
// at 340 m/s, a tool at 340 m/s, a contact thickness of 10 cm, a degenerate tear table), the run
// must end in one of the two outcomes `weft run` reports:
//  - healthy (exit 0): every cloth position and velocity, every obstacle's pose, velocities and
//    vertices finite, and the metrics written to metrics.json (strain, energies) finite numbers;
//  - unhealthy (exit 3): the health check failed with one of its documented checks, naming a stage
//    and giving a one-line message, or the state is not finite ("non-finite").
// A crash, a sanitizer report, an exception out of the step (`weft run` would exit 1, "internal
// error"), a healthy report on a non-finite state, or a hang is a finding.
//
// Work bound. The shipped scenes are read with their grids coarsened to at most kGridSide
// vertices a side (pins select by corners and rest boxes, which hold at any resolution); an
// override may raise it, up to kMaxVertices cloth vertices (grid or OBJ) and kMaxTriangles
// obstacle triangles (generated or OBJ tools; a sphere subdivided 4 times has 5,120), above which
// the unit is skipped. What repeats the work of a step is clamped after validation to values a
// step of that size needs: substeps to kMaxSubsteps, Newton iterations to 10, CG iterations to
// 1,000, contact's CCD and impact zone iterations to their defaults (8, 50), threads to 1 (one
// core per fuzzing process; results do not depend on threads). Then kSteps steps: under the
// sanitizers a shipped scene takes 20-200 ms; a step long enough to make nearly every contact pair
// a candidate (dt = 1 s, a ball at 340 m/s) takes seconds, 66 s of wall time at worst in the first
// campaign on a loaded machine (docs/testing.md).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <memory>
#include <set>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "override_input.h"
#include "scene/scene_json.h"
#include "search_paths_guard.h"
#include "sim/finite_state.h"
#include "sim/health_check.h"
#include "sim/world.h"
#include "util/input_error.h"
#include "world_checks.h"

namespace {

constexpr int kGridSide = 8;
constexpr int kSphereSubdivisions = 2;
constexpr std::int64_t kMaxVertices = 320;  // assets/meshes/square_sheet.obj has 289
constexpr std::int64_t kMaxTriangles = 4096;  // sheet-over-columns: two tools of 1,344
constexpr int kMaxSubsteps = 2;
constexpr std::size_t kMaxOverrides = 16;
constexpr int kSteps = 4;

// The shipped scenes with every grid at most kGridSide vertices a side and every sphere subdivided
// at most kSphereSubdivisions times.
const weft::fuzz::ShippedScenes& coarseScenes() {
  static const weft::fuzz::ShippedScenes scenes = [] {
    weft::fuzz::ShippedScenes coarse = weft::fuzz::shippedScenes();
    for (auto& [name, scene] : coarse) {
      for (nlohmann::json& cloth : scene.text.at("cloths")) {
        nlohmann::json& mesh = cloth.at("mesh");
        if (!mesh.contains("grid")) continue;
        nlohmann::json& grid = mesh.at("grid");
        nlohmann::json resolution = grid.value("resolution", nlohmann::json::array({32, 32}));
        for (nlohmann::json& n : resolution) n = std::min(n.get<int>(), kGridSide);
        grid["resolution"] = resolution;
      }
      if (!scene.text.contains("obstacles")) continue;
      for (nlohmann::json& obstacle : scene.text.at("obstacles")) {
        nlohmann::json& shape = obstacle.at("shape");
        if (shape.contains("sphere") && shape["sphere"].contains("subdivisions")) {
          shape["sphere"]["subdivisions"] = std::min(shape["sphere"]["subdivisions"].get<int>(), kSphereSubdivisions);
        }
      }
    }
    return coarse;
  }();
  return scenes;
}

// Clamps what multiplies the work of a step (see the top of the file); every value stays one
// validation accepts.
void boundWork(weft::Scene& scene) {
  weft::SolverSpec& solver = scene.solver;
  solver.substeps = std::min(solver.substeps, kMaxSubsteps);
  solver.newtonMaxIterations = std::min(solver.newtonMaxIterations, 10);
  solver.linearMaxIterations = std::min(solver.linearMaxIterations, 1000);
  solver.threads = 1;
  scene.contact.ccdIterations = std::min(scene.contact.ccdIterations, 8);
  scene.contact.impactZoneIterations = std::min(scene.contact.impactZoneIterations, 50);
}

bool finiteMetrics(const weft::WorldMetrics& m) {
  return m.finite && std::isfinite(m.maxStrain) && std::isfinite(m.kineticEnergy) && std::isfinite(m.elasticEnergy) &&
         std::isfinite(m.gravityEnergy);
}

// A failure as metrics.json's "health" and the warning line report it.
void checkFailure(const weft::HealthFailure& failure, std::int64_t steps) {
  static const std::set<std::string> checks{"non-finite", "strain", "energy", "speed", "contact", "linear-solve",
                                            "newton"};
  if (checks.count(failure.check) == 0) std::abort();
  if (failure.step < 1 || failure.step > steps) std::abort();
  if (failure.stage.empty() || failure.message.empty() || failure.message.size() > 400) std::abort();
  if (weft::healthWarning(failure).size() > 600) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  unsetenv("WEFT_DATA_DIR");
  (void)coarseScenes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  weft::fuzz::OverrideInput input;
  if (!weft::fuzz::splitInput(data, size, kMaxOverrides, input)) return -1;
  const weft::fuzz::ShippedScene& shipped = weft::fuzz::pickScene(input.scene, coarseScenes());
  const weft::SearchPaths paths = weft::defaultSearchPaths(shipped.file);
  std::unique_ptr<weft::World> world;
  try {
    nlohmann::json j = shipped.text;
    weft::applyOverrides(j, input.overrides, shipped.file.string());
    if (weft::fuzz::leavesSearchPaths(j)) return -1;
    weft::Scene scene = weft::parseScene(j, shipped.file, paths);
    if (weft::fuzz::gridVertices(scene) > kMaxVertices || weft::fuzz::obstacleTriangles(scene) > kMaxTriangles) {
      return -1;
    }
    boundWork(scene);
    world = std::make_unique<weft::World>(scene);
  } catch (const weft::InputError& e) {
    if (std::string_view(e.what()).size() > 2000) std::abort();
    return 0;
  }
  // The same bounds on what was built, OBJ cloths and tools included.
  std::int64_t vertices = 0;
  for (int c = 0; c < world->clothCount(); ++c) vertices += world->cloth(c).vertexCount();
  std::int64_t triangles = 0;
  for (int i = 0; i < world->obstacleCount(); ++i) triangles += std::ssize(world->obstacle(i).topology.triangles);
  if (vertices > kMaxVertices || triangles > kMaxTriangles) return -1;
  if (!weft::fuzz::worldStateFinite(*world)) std::abort();

  // As `weft run` does, with every step a frame: the per-frame checks (strain, energy, speed) run
  // after every step. No exception is caught: one out of the step is a finding.
  weft::HealthCheck health(*world, 1);
  for (int s = 0; s < kSteps; ++s) {
    world->step();
    if (!health.afterStep(*world)) break;
  }
  const bool finite = weft::stateIsFinite(*world);
  if (finite) health.checkNow(*world);

  if (finite && health.healthy()) {
    // Reported as a good run: it must be one, obstacles included.
    if (!weft::fuzz::worldStateFinite(*world)) std::abort();
    if (!finiteMetrics(world->metrics())) std::abort();
  }
  if (const auto& failure = health.failure()) checkFailure(*failure, world->stepCount());
  // WEFT_FUZZ_VERBOSE=1 with inputs given as files says how each run ended.
  static const bool verbose = std::getenv("WEFT_FUZZ_VERBOSE") != nullptr;
  if (verbose) {
    const auto& failure = health.failure();
    std::fprintf(stderr, "world_step: %s\n",
                 failure ? weft::healthWarning(*failure).c_str() : finite ? "healthy" : "non-finite, health check passed");
  }
  return 0;
}
