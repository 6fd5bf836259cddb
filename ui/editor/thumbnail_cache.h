#pragma once
// Where the scene browser keeps its thumbnails between runs (issue 21, item 8): one PNG per scene
// file content, so a thumbnail is rendered once, and again only when the file changes.
// Plain files, no GL and no ImGui.
//
// The folder: $WEFT_CACHE_DIR/thumbnails, else $XDG_CACHE_HOME/weft/thumbnails, else
// ~/.cache/weft/thumbnails. The file name is the key: a hash of the scene file's bytes, of the
// bytes of every file loading it reads (material and tear table presets, meshes, sharp tags: a
// scene naming a preset looks different when the preset changes), and of how the thumbnail is
// drawn (kThumbnailStyle, its size), so a changed scene, a changed file it loads or a changed
// picture never shows an old image. Deleting the folder is always safe.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace weft::editor {

// Thumbnails are this size (pixels, 4:3, the editor shows them at this size).
constexpr int kThumbnailWidth = 192;
constexpr int kThumbnailHeight = 144;
// Part of every key: change it when the thumbnail's look changes (renderer, camera, size), and
// every cached thumbnail is drawn again.
constexpr const char* kThumbnailStyle = "t0-scene-camera-192x144-v1";

std::filesystem::path defaultThumbnailFolder();

// 64-bit FNV-1a of `text` (offset basis 14695981039346656037, prime 1099511628211, as its
// authors publish them), as 16 hex digits.
std::string fnv1aHex(const std::string& text);

class ThumbnailCache {
 public:
  explicit ThumbnailCache(std::filesystem::path folder = defaultThumbnailFolder()) : folder_(std::move(folder)) {}
  const std::filesystem::path& folder() const { return folder_; }
  // The key of a scene file as its bytes and those of the files it loads are now; none when the
  // scene file cannot be read. A scene that does not load is keyed by its bytes and the reader's
  // message, so it is tried again once the file it misses appears.
  // `loaded`, when given, receives the files the scene loads (those hashed after it).
  static std::optional<std::string> keyOf(const std::filesystem::path& sceneFile,
                                          std::vector<std::filesystem::path>* loaded = nullptr);
  std::filesystem::path pathFor(const std::string& key) const { return folder_ / (key + ".png"); }

 private:
  std::filesystem::path folder_;
};

}  // namespace weft::editor
