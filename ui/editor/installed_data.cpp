#include "editor/installed_data.h"

#include <cstdlib>
#include <system_error>
#include <vector>

namespace weft::editor {

namespace fs = std::filesystem;

namespace {

fs::path canonicalOf(const fs::path& path) {
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path), ec);
  return ec ? fs::absolute(path).lexically_normal() : resolved;
}

bool isInside(const fs::path& file, const fs::path& folder) {
  const fs::path relative = canonicalOf(file).lexically_relative(canonicalOf(folder));
  return !relative.empty() && *relative.begin() != "..";
}

}  // namespace

bool isInstalledData(const fs::path& file) {
  std::vector<fs::path> folders = {fs::path(WEFT_SOURCE_DIR) / "presets", fs::path(WEFT_SOURCE_DIR) / "assets"};
  if (const char* data = std::getenv("WEFT_DATA_DIR"); data != nullptr && *data != '\0') {
    folders.push_back(fs::path(data) / "presets");
    folders.push_back(fs::path(data) / "assets");
  }
  for (const fs::path& folder : folders) {
    if (isInside(file, folder)) return true;
  }
  return false;
}

fs::path suggestedSceneCopy(const fs::path& file) {
  const char* home = std::getenv("HOME");
  const fs::path root = home != nullptr && *home != '\0' ? fs::path(home) : fs::current_path();
  return root / "weft" / "scenes" / file.filename();
}

}  // namespace weft::editor
