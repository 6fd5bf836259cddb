#pragma once
// Scene files: JSON <-> Scene, with overrides by JSON path (`--set solver.dt=0.005`).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scene/scene.h"

namespace weft {

// Folders searched for presets and assets, in order (the scene's folder, the project's presets/
// and assets/ folders, and WEFT_DATA_DIR when set).
struct SearchPaths {
  std::vector<std::filesystem::path> materialDirs;
  std::vector<std::filesystem::path> tearTableDirs;
  std::vector<std::filesystem::path> assetDirs;
};
SearchPaths defaultSearchPaths(const std::filesystem::path& sceneFile);

// Applies "a.b.c=VALUE" overrides in order. VALUE is parsed as JSON when it parses (numbers,
// true/false, arrays, objects, quoted strings), otherwise taken as a plain string. Array elements
// are addressed by index ("cloths.0.weft_angle_deg=30"). Throws InputError for a path that does
// not exist in the scene or its defaults.
void applyOverrides(nlohmann::json& scene, const std::vector<std::string>& overrides, const std::string& file);

// Parses and validates; resolves material presets and mesh files. Throws InputError.
Scene parseScene(const nlohmann::json& j, const std::filesystem::path& file, const SearchPaths& paths);
Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
// The files loading `file` reads besides itself, as the reader resolves them, in reading order:
// material and tear table presets, OBJ meshes, sharp-tag files. For whoever keeps something made
// from the scene (the editor's thumbnails): the scene file alone does not say when it is stale.
// Throws InputError as loadScene does.
std::vector<std::filesystem::path> sceneInputFiles(const std::filesystem::path& file);

}  // namespace weft
