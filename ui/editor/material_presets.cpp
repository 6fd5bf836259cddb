#include "material_presets.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

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
  material.name = name;
  if (material.source.empty()) material.source = "made in Weft's editor";
  writeFileAtomically(file, materialToJson(material).dump(2) + "\n");
  return file;
}

}  // namespace weft::editor
