#include "default_scene.h"

#include <cstdlib>
#include <string>

namespace weft::app {

namespace {

std::filesystem::path presetScene(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path relative = fs::path("presets") / "scenes" / (name + ".json");
  if (const char* data = std::getenv("WEFT_DATA_DIR"); data != nullptr && *data != '\0') {
    const fs::path candidate = fs::path(data) / relative;
    if (fs::is_regular_file(candidate)) return candidate;
  }
  return fs::path(WEFT_SOURCE_DIR) / relative;
}

}  // namespace

std::filesystem::path defaultScenePath() { return presetScene("hanging-sheet"); }

std::filesystem::path defaultEditorScenePath() { return presetScene("ball-into-sheet-table4.1-cloth2"); }

}  // namespace weft::app
