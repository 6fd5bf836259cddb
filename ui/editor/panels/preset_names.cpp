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

namespace {

// A top-level string field of a JSON file; empty when it is missing or the file does not read.
std::string topLevelString(const std::filesystem::path& file, const char* key) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  std::ostringstream text;
  text << in.rdbuf();
  try {
    const nlohmann::json j = parseJsonText(text.str(), file.string(), JsonTextOptions{.allowComments = true});
    const auto it = j.is_object() ? j.find(key) : j.end();
    return it != j.end() && it->is_string() ? it->get<std::string>() : "";
  } catch (const std::exception&) {
    return "";
  }
}

}  // namespace

std::string sceneDescription(const std::filesystem::path& sceneFile) { return topLevelString(sceneFile, "description"); }

std::string presetSource(const std::filesystem::path& presetFile) { return topLevelString(presetFile, "source"); }

}  // namespace weft::editor
