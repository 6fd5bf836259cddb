#include "scene_listing_cache.h"

#include <system_error>

#include "editor/panels/preset_names.h"
#include "editor/thumbnail_cache.h"
#include "scene/scene_json.h"

namespace weft::editor {

namespace fs = std::filesystem;

FileStamp stampOf(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return {};
  FileStamp stamp;
  stamp.exists = true;
  stamp.size = fs::is_regular_file(status) ? fs::file_size(path, ec) : 0;
  stamp.modified = fs::last_write_time(path, ec);
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
