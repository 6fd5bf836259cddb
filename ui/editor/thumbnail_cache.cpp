#include "thumbnail_cache.h"
#include "editor/environment_variable.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "scene/scene_json.h"
#include "util/input_error.h"

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

namespace {

std::optional<std::string> bytesOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return bytes.str();
}

}  // namespace

// The files the scene loads come from the scene reader itself (sceneInputFiles), not from a hash
// of the parsed Scene: a Scene holds a mesh's path, not its triangles, and a hash of every field
// would go stale the day a field is added. Each file is named (a preset found in another folder
// is another preset) and its bytes follow, with their length, so no two lists run together.
std::optional<std::string> ThumbnailCache::keyOf(const fs::path& sceneFile, std::vector<fs::path>* loaded) {
  const std::optional<std::string> scene = bytesOf(sceneFile);
  if (!scene) return std::nullopt;
  std::string keyed = std::string(kThumbnailStyle) + '\n' + std::to_string(scene->size()) + '\n' + *scene;
  try {
    for (const fs::path& file : sceneInputFiles(sceneFile)) {
      const std::optional<std::string> bytes = bytesOf(file);
      keyed += '\n' + file.string() + '\n' + (bytes ? std::to_string(bytes->size()) + '\n' + *bytes : "unreadable");
      if (loaded != nullptr) loaded->push_back(file);
    }
  } catch (const InputError& e) {  // the scene's own name left out: copies of a file share a key
    keyed += "\ndoes not load: " + (e.file() == sceneFile.string() ? std::string() : e.file()) + ' ' + e.field() + ' ' +
             e.message();
  } catch (const std::exception& e) {
    keyed += std::string("\ndoes not load: ") + e.what();
  }
  return fnv1aHex(keyed);
}

}  // namespace weft::editor
