#pragma once
// The scene browser's model (issue 21, item 8): the scenes of a few folders (the open scene's,
// Weft's presets), each with its description and a thumbnail of how it starts. A thumbnail comes
// from the thumbnail cache (thumbnail_cache.h) when the scene file is unchanged since it was
// drawn, else it is rendered with the editor's own renderer and cached. makeNextThumbnail does at
// most one a call, and only while the browser is open: the window keeps drawing (one thumbnail a
// frame) while a folder fills in. Owns GL textures: use it in one GL context.
#include <filesystem>
#include <string>
#include <vector>

#include "editor/scene_listing_cache.h"
#include "editor/thumbnail_cache.h"
#include "scene_renderer.h"

namespace weft::editor {

struct BrowserScene {
  enum class Thumbnail { Pending, Ready, Failed };
  std::filesystem::path file;
  std::string name;         // the file's stem
  std::string description;  // the scene's "description" (empty when it has none)
  std::string key;          // ThumbnailCache::keyOf when listed (empty: unreadable)
  Thumbnail thumbnail = Thumbnail::Pending;
  unsigned texture = 0;     // GL texture of the thumbnail, when Ready
  std::string problem;      // why there is no thumbnail (the scene does not load), when Failed
};

// The folders the editor browses with `openScene` open: its folder, then Weft's presets/scenes
// (the project's, and $WEFT_DATA_DIR's when set).
std::vector<std::filesystem::path> browserFolders(const std::filesystem::path& openScene);

// A material preset as the browser lists it.
struct BrowserPreset {
  std::string name;    // the file's stem, as a scene names it
  std::string source;  // where its numbers come from (empty when the file has none)
};

class SceneBrowser {
 public:
  SceneBrowser(std::vector<std::filesystem::path> folders, ThumbnailCache cache);
  // Lists other folders (another scene was opened); a scene listed before keeps its thumbnail.
  void setFolders(std::vector<std::filesystem::path> folders);
  ~SceneBrowser();  // frees the textures: their GL context must be current
  SceneBrowser(const SceneBrowser&) = delete;
  SceneBrowser& operator=(const SceneBrowser&) = delete;

  // Lists the folders' scenes again, sorted by name, each file once; a scene whose file did not
  // change keeps its thumbnail. The material presets are listed again too. Only files that changed
  // since they were last read are read again (scene_listing_cache.h).
  void rescan();
  const std::vector<BrowserScene>& scenes() const { return scenes_; }
  // The material presets of `folders` (the open scene's search path), listed once per change of
  // folders or rescan, not every frame.
  void setMaterialFolders(std::vector<std::filesystem::path> folders);
  const std::vector<BrowserPreset>& materials() const { return materials_; }
  const ThumbnailCache& cache() const { return cache_; }
  const SceneListingCache& listings() const { return listings_; }

  // The next pending thumbnail: read from the cache, or rendered (building the scene's world)
  // and written to the cache. False when none was pending.
  bool makeNextThumbnail(ui::SceneRenderer& renderer);
  bool pending() const;
  int rendered() const { return rendered_; }      // drawn by this browser
  int fromCache() const { return fromCache_; }    // read back from the cache

 private:
  void makeThumbnail(BrowserScene& scene, ui::SceneRenderer& renderer);
  void listMaterials();

  std::vector<std::filesystem::path> folders_;
  ThumbnailCache cache_;
  SceneListingCache listings_;
  std::vector<BrowserScene> scenes_;
  std::vector<std::filesystem::path> materialFolders_;
  std::vector<BrowserPreset> materials_;
  int rendered_ = 0;
  int fromCache_ = 0;
};

}  // namespace weft::editor
