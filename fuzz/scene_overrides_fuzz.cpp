// libFuzzer target: `--set PATH=VALUE` overrides on a shipped scene, then the World a run builds
// from it (`weft run` up to its first step: scene/scene_json.h's applyOverrides and parseScene,
// then sim/world.h's World). The scenes in presets/ are valid; overrides push any of their values
// to the edge of what validation accepts, or past it, in any combination. Any input must give an
// InputError with a short message, or a World holding the scene's cloths and obstacles in a
// finite state. Anything else (a crash, a sanitizer report, std::bad_alloc or another exception, a
// hang) is a finding. Nothing is stepped: the step's own bounds are the health check's (issue 19).
//
// The input is text (override_input.h): the first line names a scene of presets/scenes/, each
// further line is one override, as after `--set`. Overrides that would name a file outside the search folders are skipped
// (search_paths_guard.h).
//
// Work bound: under the sanitizers a unit on a shipped scene (about a thousand cloth vertices)
// takes about 15 ms, so one at validation's limits (a million cloth vertices, a box of 256 x 256
// cells a face; 8 s and 0.9 GB in the release build) would take minutes. Inputs asking for more
// than kMaxFuzzedVertices cloth vertices or kMaxFuzzedTriangles obstacle triangles are skipped to
// keep the campaign at tens of units a second; the limits themselves are tested by tests/scene
// (the refusals) and were built in full by hand (README, "Keep it fixed").
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
