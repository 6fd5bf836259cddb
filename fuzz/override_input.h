#pragma once
// Shared by the fuzz targets whose input is `--set` overrides on a shipped scene (scene_overrides,
// world_step). The input is text: the first line names a scene of presets/scenes/ (its file name
// without ".json"; any other line picks one by its bytes), each further line is one override, as
// after `--set`.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "scene/shape_size.h"
#include "util/json_text.h"

namespace weft::fuzz {

struct ShippedScene {
  std::filesystem::path file;
  nlohmann::json text;  // as loadScene reads it, before overrides
};

using ShippedScenes = std::map<std::string, ShippedScene>;  // by file stem

// Every scene of presets/scenes/, read once.
inline const ShippedScenes& shippedScenes() {
  static const ShippedScenes scenes = [] {
    ShippedScenes found;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(WEFT_SOURCE_DIR) / "presets" / "scenes")) {
      if (entry.path().extension() != ".json") continue;
      found[entry.path().stem().string()] = {
          entry.path(), readJsonFile(entry.path(), "the scene file", JsonTextOptions{.allowComments = true})};
    }
    return found;
  }();
  return scenes;
}

inline const ShippedScene& pickScene(std::string_view name, const ShippedScenes& scenes) {
  if (const auto it = scenes.find(std::string(name)); it != scenes.end()) return it->second;
  std::size_t sum = 0;
  for (const char c : name) sum += static_cast<unsigned char>(c);
  return std::next(scenes.begin(), static_cast<std::ptrdiff_t>(sum % scenes.size()))->second;
}

struct OverrideInput {
  std::string scene;
  std::vector<std::string> overrides;
};

// False when the input has more than maxOverrides lines of overrides (the unit is skipped).
inline bool splitInput(const std::uint8_t* data, std::size_t size, std::size_t maxOverrides, OverrideInput& out) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  std::getline(lines, out.scene);
  for (std::string line; std::getline(lines, line);) {
    if (out.overrides.size() == maxOverrides) return false;
    out.overrides.push_back(line);
  }
  return true;
}

// Grid cloth vertices and obstacle triangles the World will hold (OBJ cloths and tools are the
// small meshes of assets/ and count as nothing here).
inline std::int64_t gridVertices(const Scene& scene) {
  std::int64_t total = 0;
  for (const ClothSpec& cloth : scene.cloths) {
    if (cloth.grid) total += std::int64_t{cloth.grid->resolutionX} * cloth.grid->resolutionY;
  }
  return total;
}

inline std::int64_t obstacleTriangles(const Scene& scene) {
  std::int64_t total = 0;
  for (const ObstacleSpec& obstacle : scene.obstacles) total += shapeTriangleCount(obstacle.shape);
  return total;
}

}  // namespace weft::fuzz
