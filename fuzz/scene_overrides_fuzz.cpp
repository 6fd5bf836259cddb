// libFuzzer target: `--set PATH=VALUE` overrides on a shipped scene, then the World a run builds
// from it (`weft run` up to its first step: scene/scene_json.h's applyOverrides and parseScene,
// then sim/world.h's World). The scenes in presets/ are valid; overrides push any of their values
// to the edge of what validation accepts, or past it, in any combination. Any input must give an
// InputError with a short message, or a World holding the scene's cloths and obstacles in a
// finite state (world_checks.h). Anything else (a crash, a sanitizer report, std::bad_alloc or
// another exception, a hang) is a finding. Nothing is stepped here: world_step_fuzz.cpp steps the
// World of the same inputs.
//
// The input is text (override_input.h): the first line names a scene of presets/scenes/, each
// further line is one override, as after `--set`. Overrides that would name a file outside the
// search folders are skipped (search_paths_guard.h).
//
// Where a unit's time goes (perf, 3,000 mutations from a fixed corpus, December 2026): building
// the World (the cloth's grid, edges, hinges and elements; the obstacles' meshes, mass properties
// and collision topology) and parseScene's own grid for the pin checks, about 60 %; libFuzzer's
// bookkeeping of the features a unit covers, about 30 %; the comparison hooks of the coverage
// instrumentation are spread through all of it. Reading presets and assets was a tenth: the
// asset files are read once per process (asset_cache.cpp), the presets (1.5 %) still every time.
// World::metrics(), used before for the finiteness check, was a fifth (an elastic evaluation).
// Most units fail validation within a millisecond; a valid one on a shipped scene (about a
// thousand cloth vertices) takes 15-30 ms of CPU under the sanitizers.
//
// Work bound: a unit at validation's limits (a million cloth vertices, a box of 256 x 256 cells
// a face; 8 s and 0.9 GB in the release build) would take minutes. Inputs asking for more than
// kMaxFuzzedVertices cloth vertices or kMaxFuzzedTriangles obstacle triangles are skipped; the
// corpus shows such inputs are rare (none of the 420 units of a first corpus took half a second of
// wall time on the loaded machine; the slowest were shipped scenes with no override at all), so
// the caps are not what sets the rate. The limits themselves are tested by tests/scene (the
// refusals) and were built in full by hand (docs/testing.md, "Hostile input").
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "override_input.h"
#include "scene/scene_json.h"
#include "search_paths_guard.h"
#include "sim/world.h"
#include "util/input_error.h"
#include "world_checks.h"

namespace {

constexpr std::int64_t kMaxFuzzedVertices = 1 << 14;  // 128 x 128: four times the shipped sheets
constexpr std::int64_t kMaxFuzzedTriangles = 1 << 17;
constexpr std::size_t kMaxOverrides = 16;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  unsetenv("WEFT_DATA_DIR");
  (void)weft::fuzz::shippedScenes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  weft::fuzz::OverrideInput input;
  if (!weft::fuzz::splitInput(data, size, kMaxOverrides, input)) return -1;
  const weft::fuzz::ShippedScene& shipped = weft::fuzz::pickScene(input.scene, weft::fuzz::shippedScenes());
  const weft::SearchPaths paths = weft::defaultSearchPaths(shipped.file);
  try {
    nlohmann::json j = shipped.text;
    weft::applyOverrides(j, input.overrides, shipped.file.string());
    if (weft::fuzz::leavesSearchPaths(j)) return -1;
    const weft::Scene scene = weft::parseScene(j, shipped.file, paths);
    if (weft::fuzz::gridVertices(scene) > kMaxFuzzedVertices ||
        weft::fuzz::obstacleTriangles(scene) > kMaxFuzzedTriangles) {
      return -1;
    }
    const weft::World world(scene);
    if (world.clothCount() != static_cast<int>(scene.cloths.size())) std::abort();
    if (world.obstacleCount() != static_cast<int>(scene.obstacles.size())) std::abort();
    if (!weft::fuzz::worldStateFinite(world)) std::abort();
  } catch (const weft::InputError& e) {
    if (std::string_view(e.what()).size() > 2000) std::abort();
  }
  return 0;
}
