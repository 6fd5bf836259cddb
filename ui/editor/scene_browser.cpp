#include "scene_browser.h"

#include <GL/gl.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <map>
#include <set>
#include <system_error>
#include <utility>

#include "editor/panels/preset_names.h"
#include "png_reader.h"
#include "png_writer.h"
#include "scene/scene_json.h"
#include "scene_thumbnail.h"

namespace weft::editor {

namespace fs = std::filesystem;

namespace {

unsigned makeTexture(const std::vector<std::uint8_t>& rgba, int width, int height) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

void freeTexture(unsigned& texture) {
  if (texture == 0) return;
  const GLuint name = texture;
  glDeleteTextures(1, &name);
  texture = 0;
}

}  // namespace

SceneBrowser::SceneBrowser(std::vector<fs::path> folders, ThumbnailCache cache)
    : folders_(std::move(folders)), cache_(std::move(cache)) {
  rescan();
}

std::vector<fs::path> browserFolders(const fs::path& openScene) {
  std::vector<fs::path> folders{openScene.parent_path().empty() ? fs::path(".") : openScene.parent_path(),
                                fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes"};
  if (const char* data = std::getenv("WEFT_DATA_DIR"); data != nullptr && *data != '\0') {
    folders.push_back(fs::path(data) / "presets" / "scenes");
  }
  return folders;
}

void SceneBrowser::setMaterialFolders(std::vector<fs::path> folders) {
  if (folders == materialFolders_) return;
  materialFolders_ = std::move(folders);
  listMaterials();
}

void SceneBrowser::listMaterials() {
  materials_.clear();
  for (const std::string& name : presetNames(materialFolders_)) {
    BrowserPreset preset{name, ""};
    for (const fs::path& folder : materialFolders_) {  // the first folder that has it, as scenes find it
      if (!fs::exists(folder / (name + ".json"))) continue;
      preset.source = listings_.presetSource(folder / (name + ".json"));
      break;
    }
    materials_.push_back(std::move(preset));
  }
}

void SceneBrowser::setFolders(std::vector<fs::path> folders) {
  if (folders == folders_) return;
  folders_ = std::move(folders);
  rescan();
}

SceneBrowser::~SceneBrowser() {
  for (BrowserScene& scene : scenes_) freeTexture(scene.texture);
}

void SceneBrowser::rescan() {
  std::map<std::string, BrowserScene> listed;  // by name: the first folder that has it wins
  std::set<fs::path> seenFolders;
  for (const fs::path& folder : folders_) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(folder, ec);
    if (ec || !seenFolders.insert(canonical).second) continue;
    for (const auto& entry : fs::directory_iterator(canonical, ec)) {
      if (entry.path().extension() != ".json") continue;
      const std::string name = entry.path().stem().string();
      if (listed.count(name) != 0) continue;
      BrowserScene scene;
      scene.file = entry.path();
      scene.name = name;
      SceneListing listing = listings_.scene(entry.path());
      scene.description = std::move(listing.description);
      scene.key = std::move(listing.key);
      listed.emplace(name, std::move(scene));
    }
  }
  std::vector<BrowserScene> next;
  next.reserve(listed.size());
  for (auto& [name, scene] : listed) {
    const auto old = std::find_if(scenes_.begin(), scenes_.end(),
                                  [&](const BrowserScene& s) { return s.file == scene.file && s.key == scene.key; });
    if (old != scenes_.end()) {
      scene.thumbnail = old->thumbnail;
      scene.texture = std::exchange(old->texture, 0u);
      scene.problem = old->problem;
    }
    next.push_back(std::move(scene));
  }
  for (BrowserScene& gone : scenes_) freeTexture(gone.texture);
  scenes_ = std::move(next);
  listMaterials();
}

bool SceneBrowser::pending() const {
  return std::any_of(scenes_.begin(), scenes_.end(),
                     [](const BrowserScene& s) { return s.thumbnail == BrowserScene::Thumbnail::Pending; });
}

bool SceneBrowser::makeNextThumbnail(ui::SceneRenderer& renderer) {
  for (BrowserScene& scene : scenes_) {
    if (scene.thumbnail != BrowserScene::Thumbnail::Pending) continue;
    makeThumbnail(scene, renderer);
    return true;
  }
  return false;
}

void SceneBrowser::makeThumbnail(BrowserScene& scene, ui::SceneRenderer& renderer) {
  if (scene.key.empty()) {
    scene.thumbnail = BrowserScene::Thumbnail::Failed;
    scene.problem = "cannot read the file";
    return;
  }
  const fs::path cached = cache_.pathFor(scene.key);
  if (const std::optional<ui::RgbaImage> image = ui::readPng(cached);
      image && image->width == kThumbnailWidth && image->height == kThumbnailHeight) {
    scene.texture = makeTexture(image->rgba, image->width, image->height);
    scene.thumbnail = BrowserScene::Thumbnail::Ready;
    ++fromCache_;
    return;
  }
  std::vector<std::uint8_t> rgba;
  try {
    rgba = ui::renderSceneThumbnail(loadScene(scene.file), renderer, kThumbnailWidth, kThumbnailHeight);
  } catch (const std::exception& e) {  // a scene that does not load shows why instead
    scene.thumbnail = BrowserScene::Thumbnail::Failed;
    scene.problem = e.what();
    return;
  }
  scene.texture = makeTexture(rgba, kThumbnailWidth, kThumbnailHeight);
  scene.thumbnail = BrowserScene::Thumbnail::Ready;
  ++rendered_;
  try {
    fs::create_directories(cache_.folder());
    ui::writePng(cached, rgba, kThumbnailWidth, kThumbnailHeight);
  } catch (const std::exception& e) {
    scene.problem = std::string("not cached: ") + e.what();  // shown, and drawn again next time
  }
}

}  // namespace weft::editor
