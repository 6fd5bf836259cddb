#include "default_scene.h"

#include <cstdlib>

namespace weft::app {

std::filesystem::path defaultScenePath() {
  namespace fs = std::filesystem;
  const fs::path relative = fs::path("presets") / "scenes" / "hanging-sheet.json";
  if (const char* data = std::getenv("WEFT_DATA_DIR"); data != nullptr && *data != '\0') {
    const fs::path candidate = fs::path(data) / relative;
    if (fs::is_regular_file(candidate)) return candidate;
  }
  return fs::path(WEFT_SOURCE_DIR) / relative;
}

}  // namespace weft::app
