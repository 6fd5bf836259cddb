#include "thumbnail_cache.h"
#include "editor/environment_variable.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace weft::editor {

namespace fs = std::filesystem;

fs::path defaultThumbnailFolder() {
  if (const std::string dir = environmentVariable("WEFT_CACHE_DIR"); !dir.empty()) return fs::path(dir) / "thumbnails";
  if (const std::string cache = environmentVariable("XDG_CACHE_HOME"); !cache.empty()) return fs::path(cache) / "weft" / "thumbnails";
  if (const std::string home = environmentVariable("HOME"); !home.empty()) return fs::path(home) / ".cache" / "weft" / "thumbnails";
  return fs::temp_directory_path() / "weft-thumbnails";
}

std::string fnv1aHex(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

std::optional<std::string> ThumbnailCache::keyOf(const fs::path& sceneFile) {
  std::ifstream in(sceneFile, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return fnv1aHex(std::string(kThumbnailStyle) + '\n' + bytes.str());
}

}  // namespace weft::editor
