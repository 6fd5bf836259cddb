#include "scene_listing_cache.h"

#include <sys/stat.h>

#include <system_error>

#include "editor/panels/preset_names.h"
#include "editor/thumbnail_cache.h"
#include "scene/scene_json.h"

namespace weft::editor {

namespace fs = std::filesystem;

FileStamp stampOf(const fs::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};  // follows links, as reading the file does
  const auto ns = [](const timespec& t) { return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec; };
  FileStamp stamp;
  stamp.exists = true;
  stamp.size = S_ISREG(st.st_mode) ? static_cast<std::uintmax_t>(st.st_size) : 0;
  stamp.modifiedNs = ns(st.st_mtim);
  stamp.statusChangedNs = ns(st.st_ctim);
  stamp.inode = static_cast<std::uint64_t>(st.st_ino);
  stamp.device = static_cast<std::uint64_t>(st.st_dev);
  return stamp;
}

bool SceneListingCache::unchanged(const Stamps& stamps) {
  for (const auto& [path, stamp] : stamps) {
    if (!(stampOf(path) == stamp)) return false;
  }
  return true;
}

SceneListing SceneListingCache::scene(const fs::path& sceneFile) {
  if (const auto it = scenes_.find(sceneFile); it != scenes_.end() && unchanged(it->second.stamps)) return it->second.listing;
  // Stamped before reading: a file changed while it is read is read again next time.
  Scene entry;
  entry.stamps.emplace_back(sceneFile, stampOf(sceneFile));
  const SearchPaths search = defaultSearchPaths(sceneFile);
  for (const auto* dirs : {&search.materialDirs, &search.tearTableDirs, &search.assetDirs}) {
    for (const fs::path& dir : *dirs) entry.stamps.emplace_back(dir, stampOf(dir));
  }
  std::vector<fs::path> loaded;
  entry.listing.key = ThumbnailCache::keyOf(sceneFile, &loaded).value_or("");
  for (const fs::path& file : loaded) {
    entry.stamps.emplace_back(file, stampOf(file));
    entry.stamps.emplace_back(file.parent_path(), stampOf(file.parent_path()));  // a mesh in a subfolder
  }
  entry.listing.description = sceneDescription(sceneFile);
  ++reads_;
  return scenes_.insert_or_assign(sceneFile, std::move(entry)).first->second.listing;
}

std::string SceneListingCache::presetSource(const fs::path& presetFile) {
  const FileStamp stamp = stampOf(presetFile);
  if (const auto it = presets_.find(presetFile); it != presets_.end() && it->second.stamp == stamp) return it->second.source;
  Preset entry{stamp, weft::editor::presetSource(presetFile)};
  ++reads_;
  return presets_.insert_or_assign(presetFile, std::move(entry)).first->second.source;
}

}  // namespace weft::editor
