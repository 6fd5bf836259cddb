#include "preset_names.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "util/json_text.h"

namespace weft::editor {

std::vector<std::string> presetNames(const std::vector<std::filesystem::path>& folders) {
  std::vector<std::string> names;
  for (const auto& folder : folders) {
    std::error_code missing;  // a folder that does not exist offers nothing
    for (const auto& entry : std::filesystem::directory_iterator(folder, missing)) {
      if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

std::string sceneDescription(const std::filesystem::path& sceneFile) {
  std::ifstream in(sceneFile, std::ios::binary);
  if (!in) return "";
  std::ostringstream text;
  text << in.rdbuf();
  try {
    const nlohmann::json scene = parseJsonText(text.str(), sceneFile.string(), JsonTextOptions{.allowComments = true});
    const auto it = scene.is_object() ? scene.find("description") : scene.end();
    return it != scene.end() && it->is_string() ? it->get<std::string>() : "";
  } catch (const std::exception&) {
    return "";
  }
}

}  // namespace weft::editor
