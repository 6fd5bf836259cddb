// libFuzzer target: `--set PATH=VALUE` overrides on a shipped scene, then the World a run builds
// from it (`weft run` up to its first step: scene/scene_json.h's applyOverrides and parseScene,
// then sim/world.h's World). The scenes in presets/ are valid; overrides push any of their values
// to the edge of what validation accepts, or past it, in any combination. Any input must give an
// InputError with a short message, or a World holding the scene's cloths and obstacles in a
// finite state. Anything else (a crash, a sanitizer report, std::bad_alloc or another exception, a
// hang) is a finding. Nothing is stepped: the step's own bounds are the health check's (issue 19).
//
// The input is text: the first line names a scene of presets/scenes/ (its file name without
// ".json"; any other line picks one by its bytes), each further line is one override, as after
// `--set`. Overrides that would name a file outside the search folders are skipped
// (search_paths_guard.h).
//
// Work bound: under the sanitizers a unit on a shipped scene (about a thousand cloth vertices)
// takes about 15 ms, so one at validation's limits (a million cloth vertices, a box of 256 x 256
// cells a face; 8 s and 0.9 GB in the release build) would take minutes. Inputs asking for more
// than kMaxFuzzedVertices cloth vertices or kMaxFuzzedTriangles obstacle triangles are skipped to
// keep the campaign at tens of units a second; the limits themselves are tested by tests/scene
// (the refusals) and were built in full by hand (README, "Keep it fixed").
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/shape_size.h"
#include "scene/scene_json.h"
#include "search_paths_guard.h"
#include "sim/world.h"
#include "util/input_error.h"
#include "util/json_text.h"

namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kMaxFuzzedVertices = 1 << 14;  // 128 x 128: four times the shipped sheets
constexpr std::int64_t kMaxFuzzedTriangles = 1 << 17;
constexpr std::size_t kMaxOverrides = 16;

struct ShippedScene {
  fs::path file;
  nlohmann::json text;  // as loadScene reads it, before overrides
};

// Every scene of presets/scenes/, read once, by file stem.
const std::map<std::string, ShippedScene>& shippedScenes() {
  static const std::map<std::string, ShippedScene> scenes = [] {
    std::map<std::string, ShippedScene> found;
    for (const auto& entry : fs::directory_iterator(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes")) {
      if (entry.path().extension() != ".json") continue;
      found[entry.path().stem().string()] = {
          entry.path(), weft::readJsonFile(entry.path(), "the scene file", weft::JsonTextOptions{.allowComments = true})};
    }
    return found;
  }();
  return scenes;
}

const ShippedScene& pickScene(std::string_view name) {
  const auto& scenes = shippedScenes();
  if (const auto it = scenes.find(std::string(name)); it != scenes.end()) return it->second;
  std::size_t sum = 0;
  for (const char c : name) sum += static_cast<unsigned char>(c);
  return std::next(scenes.begin(), static_cast<std::ptrdiff_t>(sum % scenes.size()))->second;
}

// Cloth vertices and obstacle triangles the World will hold (OBJ cloths and tools are the small
// meshes of assets/ and count as nothing).
std::int64_t clothVertices(const weft::Scene& scene) {
  std::int64_t total = 0;
  for (const weft::ClothSpec& cloth : scene.cloths) {
    if (cloth.grid) total += std::int64_t{cloth.grid->resolutionX} * cloth.grid->resolutionY;
  }
  return total;
}

std::int64_t obstacleTriangles(const weft::Scene& scene) {
  std::int64_t total = 0;
  for (const weft::ObstacleSpec& obstacle : scene.obstacles) {
    total += weft::shapeTriangleCount(obstacle.shape);
  }
  return total;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  unsetenv("WEFT_DATA_DIR");
  (void)shippedScenes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  std::string name;
  std::getline(lines, name);
  std::vector<std::string> overrides;
  for (std::string line; std::getline(lines, line);) {
    if (overrides.size() == kMaxOverrides) return -1;
    overrides.push_back(line);
  }
  const ShippedScene& shipped = pickScene(name);
  const weft::SearchPaths paths = weft::defaultSearchPaths(shipped.file);
  try {
    nlohmann::json j = shipped.text;
    weft::applyOverrides(j, overrides, shipped.file.string());
    if (weft::fuzz::leavesSearchPaths(j)) return -1;
    const weft::Scene scene = weft::parseScene(j, shipped.file, paths);
    if (clothVertices(scene) > kMaxFuzzedVertices || obstacleTriangles(scene) > kMaxFuzzedTriangles) return -1;
    const weft::World world(scene);
    if (world.clothCount() != static_cast<int>(scene.cloths.size())) std::abort();
    if (world.obstacleCount() != static_cast<int>(scene.obstacles.size())) std::abort();
    if (!world.metrics().finite) std::abort();
    for (int i = 0; i < world.obstacleCount(); ++i) {
      for (const weft::Vec3& p : world.obstacleVertices(i)) {
        if (!p.allFinite()) std::abort();
      }
    }
  } catch (const weft::InputError& e) {
    if (std::string_view(e.what()).size() > 2000) std::abort();
  }
  return 0;
}
