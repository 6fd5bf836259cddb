#include "editor/editor_settings.h"

#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

#include "util/atomic_file.h"
#include "editor/environment_variable.h"

namespace weft::editor {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path defaultSettingsFile() {
  if (const std::string dir = environmentVariable("WEFT_CONFIG_DIR"); !dir.empty()) return fs::path(dir) / "editor.json";
  if (const std::string config = environmentVariable("XDG_CONFIG_HOME"); !config.empty())
    return fs::path(config) / "weft" / "editor.json";
  if (const std::string home = environmentVariable("HOME"); !home.empty()) return fs::path(home) / ".config" / "weft" / "editor.json";
  return fs::temp_directory_path() / "weft-editor.json";
}

EditorSettings loadEditorSettings(const fs::path& file) {
  EditorSettings settings;
  std::ifstream in(file, std::ios::binary);
  if (!in) return settings;
  const json j = json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return settings;
  if (const auto it = j.find("material_preset_folder"); it != j.end() && it->is_string())
    settings.materialPresetFolder = it->get<std::string>();
  return settings;
}

void saveEditorSettings(const EditorSettings& settings, const fs::path& file) {
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  const json j = {{"material_preset_folder", settings.materialPresetFolder.string()}};
  writeFileAtomically(file, j.dump(2) + "\n");
}

}  // namespace weft::editor
