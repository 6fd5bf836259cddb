#include "material_presets.h"

#include <stdexcept>
#include <system_error>

#include <nlohmann/json.hpp>

#include "scene/scene_json.h"
#include "util/atomic_file.h"

namespace weft::editor {

std::filesystem::path saveMaterialPreset(Material material, const std::string& name,
                                         const std::filesystem::path& folder) {
  const bool safe = !name.empty() && name.front() != '.' &&
                    name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-_.") == std::string::npos;
  if (!safe) throw std::invalid_argument("a preset name uses a-z, 0-9, '-', '_' and '.' only, got \"" + name + "\"");
  const std::filesystem::path file = folder / (name + ".json");
  if (std::filesystem::exists(file)) {
    throw std::invalid_argument(file.string() + " exists; choose another name (presets are not overwritten from here)");
  }
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw std::runtime_error("cannot create the folder " + folder.string() + ": " + ec.message());
  material.name = name;
  if (material.source.empty()) material.source = "made in Weft's editor";
  writeFileAtomically(file, materialToJson(material).dump(2) + "\n");
  return file;
}

std::filesystem::path suggestedPresetFolder(const std::filesystem::path& rememberedFolder,
                                            const std::filesystem::path& sceneFile) {
  if (!rememberedFolder.empty()) return rememberedFolder;
  return defaultSearchPaths(sceneFile).materialDirs.front();
}

bool sceneFindsPresetsIn(const std::filesystem::path& sceneFile, const std::filesystem::path& folder) {
  std::error_code ec;
  const std::filesystem::path wanted = std::filesystem::weakly_canonical(std::filesystem::absolute(folder), ec);
  for (const std::filesystem::path& dir : defaultSearchPaths(sceneFile).materialDirs) {
    std::error_code dirError;
    if (std::filesystem::weakly_canonical(dir, dirError) == wanted) return true;
  }
  return false;
}

}  // namespace weft::editor
