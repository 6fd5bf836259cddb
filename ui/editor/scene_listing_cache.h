#pragma once
// What the scene browser reads of each file it lists (issue 21, item 8), kept between rescans:
// a scene's description and thumbnail key (thumbnail_cache.h: the key hashes the scene file and
// every file it loads, meshes included), a material preset's source. Opening the browser again
// rescans its folders, but a file is read again only when it changed: each answer is stored with
// the stamp (FileStamp: size, times, inode) of every file it was read from, and of the folders the scene
// searches for presets and meshes (a preset added to an earlier folder changes what the scene
// loads), and reused while they all stat the same. Plain files, no GL and no ImGui.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace weft::editor {

// A file or folder as stat sees it; a missing one has exists = false.
//
// Size and modification time alone miss what artists do to files: a same-size edit (a digit
// changed) restored to its old time by `cp -p`, `tar x`, `rsync -t` or `touch -d`, and a file put
// back by `git checkout` or an editor's save-by-rename. So the stamp also holds the inode (a
// replaced file is a new one) and the status-change time, which the kernel sets on every write,
// rename and time change and which no tool can set back; times are kept to the nanosecond. What
// still slips through: a same-size write in place within the kernel's timestamp tick (a few ms)
// of the browser's own look at the file. Then the browser shows an old description or thumbnail
// until the file changes again; opening the scene reads the file itself, so no edit is ever lost,
// and hashing every listed file (meshes included) on each rescan to close that gap would undo
// what this cache is for.
struct FileStamp {
  bool exists = false;
  std::uintmax_t size = 0;            // 0 for a folder
  std::int64_t modifiedNs = 0;        // st_mtim, ns since the epoch
  std::int64_t statusChangedNs = 0;   // st_ctim, ns since the epoch
  std::uint64_t inode = 0;
  std::uint64_t device = 0;
  friend bool operator==(const FileStamp&, const FileStamp&) = default;
};
FileStamp stampOf(const std::filesystem::path& path);

struct SceneListing {
  std::string description;  // the scene's "description", empty when it has none
  std::string key;          // ThumbnailCache::keyOf, empty when the file cannot be read
};

class SceneListingCache {
 public:
  SceneListing scene(const std::filesystem::path& sceneFile);
  std::string presetSource(const std::filesystem::path& presetFile);
  // Files read (a scene: it and the files it loads, once; a preset, once) since constructed.
  int reads() const { return reads_; }

 private:
  using Stamps = std::vector<std::pair<std::filesystem::path, FileStamp>>;
  static bool unchanged(const Stamps& stamps);
  struct Scene {
    Stamps stamps;
    SceneListing listing;
  };
  struct Preset {
    FileStamp stamp;
    std::string source;
  };
  std::map<std::filesystem::path, Scene> scenes_;
  std::map<std::filesystem::path, Preset> presets_;
  int reads_ = 0;
};

}  // namespace weft::editor
