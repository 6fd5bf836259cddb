// EditorSession's tear strength brush (editor_session.h): the cloths' paintings, their hand-over
// to the running world, their save beside the scene and their autosave.
//
// A painted map is not in the scene document until it is saved (the document names a PNG, and the
// PNG does not hold the paint yet), so the session lays each painting over the parsed document
// wherever it hands a scene to the world: live edits, resets and rewinds of the timeline all see
// the painted map, never the file's.
#include <stdexcept>
#include <iterator>
#include <system_error>
#include <utility>

#include "editor/align_by_name.h"
#include "editor/editor_session.h"
#include "mesh/material_bounds.h"
#include "sim/live_edit.h"

namespace weft::editor {

namespace {

// The document's "image" of cloth `cloth`'s map, or "" when it has none.
std::string namedImage(const nlohmann::json& scene, int cloth) {
  const nlohmann::json& spec = scene.at("cloths").at(static_cast<std::size_t>(cloth));
  if (!spec.contains("tear_strength_map") || !spec["tear_strength_map"].contains("image")) return "";
  const nlohmann::json& image = spec["tear_strength_map"]["image"];
  return image.is_string() ? image.get<std::string>() : "";
}

}  // namespace

StrengthPainting& EditorSession::strengthPainting(int cloth) {
  if (StrengthPainting* found = findStrengthPainting(cloth)) return *found;
  if (cloth < 0 || cloth >= static_cast<int>(scene_.cloths.size())) throw std::out_of_range("no cloth " + std::to_string(cloth));
  const MaterialBounds bounds = materialBounds(world().cloth(cloth));
  const Vec2 lo = bounds.lo, hi = bounds.hi;
  const ClothSpec& spec = scene_.cloths[static_cast<std::size_t>(cloth)];
  TearStrengthMap start;
  if (spec.tearStrengthMap) {
    start = *spec.tearStrengthMap;
    prepareStrengthMap(start, lo, hi);
  } else {
    start = newStrengthMap(lo, hi, paintedMapFile(document_.file(), spec.name, "").filename().string());
  }
  auto painting = std::make_unique<StrengthPainting>(std::move(start), document_.history().clock());
  return *(paintings_[cloth] = std::move(painting));
}

StrengthPainting* EditorSession::findStrengthPainting(int cloth) {
  const auto it = paintings_.find(cloth);
  return it == paintings_.end() ? nullptr : it->second.get();
}

const StrengthPainting* EditorSession::findStrengthPainting(int cloth) const {
  const auto it = paintings_.find(cloth);
  return it == paintings_.end() ? nullptr : it->second.get();
}

void EditorSession::followClothNames(const Scene& next) {
  std::vector<std::string> before, after;
  for (const ClothSpec& cloth : scene_.cloths) before.push_back(cloth.name);
  for (const ClothSpec& cloth : next.cloths) after.push_back(cloth.name);
  if (before == after) return;
  const std::vector<int> to = alignByName(before, after);
  std::map<int, std::unique_ptr<StrengthPainting>> moved;
  for (auto& [was, painting] : paintings_) {
    const int now = was < static_cast<int>(to.size()) ? to[static_cast<std::size_t>(was)] : -1;
    if (now >= 0) {
      moved.emplace(now, std::move(painting));
    } else if (was < static_cast<int>(before.size())) {
      asidePaintings_.emplace_back(before[static_cast<std::size_t>(was)], std::move(painting));
    }
  }
  // A cloth back in the scene (its removal undone) gets its painting back, the latest of its name.
  for (int now = 0; now < static_cast<int>(after.size()); ++now) {
    if (moved.count(now)) continue;
    for (auto it = asidePaintings_.rbegin(); it != asidePaintings_.rend(); ++it) {
      if (it->first != after[static_cast<std::size_t>(now)]) continue;
      moved.emplace(now, std::move(it->second));
      asidePaintings_.erase(std::next(it).base());
      break;
    }
  }
  paintings_ = std::move(moved);
}

std::vector<int> EditorSession::paintedCloths() const {
  std::vector<int> cloths;
  for (const auto& [cloth, painting] : paintings_) cloths.push_back(cloth);
  return cloths;
}

Scene EditorSession::withPaintedMaps(Scene scene) const {
  for (const auto& [cloth, painting] : paintings_) {
    if (cloth < static_cast<int>(scene.cloths.size())) scene.cloths[static_cast<std::size_t>(cloth)].tearStrengthMap = painting->map();
  }
  return scene;
}

void EditorSession::strengthPaintingChanged(int cloth) {
  const StrengthPainting* painting = findStrengthPainting(cloth);
  if (painting == nullptr || cloth >= static_cast<int>(liveScene_.cloths.size())) return;
  auto map = std::make_shared<const TearStrengthMap>(painting->map());
  liveScene_.cloths[static_cast<std::size_t>(cloth)].tearStrengthMap = *map;
  const std::size_t bytes = map->grey.size() * 3 * sizeof(float);  // grey, multipliers, lower bounds
  applyToWorld(WorldChange{[cloth, map](World& world) { world.setClothTearStrengthMap(cloth, *map); }, {}, bytes});
}

void EditorSession::undoStrengthPainting(int cloth) {
  if (StrengthPainting* painting = findStrengthPainting(cloth); painting && painting->history().canUndo()) {
    const std::string label = painting->history().undoLabel();
    painting->undo();
    strengthPaintingChanged(cloth);
    status = "undo " + label + ": applied live";
  }
}

void EditorSession::redoStrengthPainting(int cloth) {
  if (StrengthPainting* painting = findStrengthPainting(cloth); painting && painting->history().canRedo()) {
    const std::string label = painting->history().redoLabel();
    painting->redo();
    strengthPaintingChanged(cloth);
    status = "redo " + label + ": applied live";
  }
}

std::vector<std::string> EditorSession::unsavedStrengthMaps() const {
  std::vector<std::string> names;
  for (const auto& [cloth, painting] : paintings_) {
    if (painting->dirty() && cloth < static_cast<int>(scene_.cloths.size()))
      names.push_back(scene_.cloths[static_cast<std::size_t>(cloth)].name);
  }
  return names;
}

void EditorSession::saveStrengthMaps(const std::filesystem::path& sceneFile, bool all) {
  nlohmann::json next = document_.json();
  for (int cloth = 0; cloth < static_cast<int>(scene_.cloths.size()); ++cloth) {
    const std::string named = namedImage(next, cloth);
    // A map recovered from an autosave is named by its absolute path there: it moves beside the
    // scene on the first save, as a painted one.
    const bool recovered = !named.empty() && std::filesystem::path(named).is_absolute();
    StrengthPainting* painting = findStrengthPainting(cloth);
    if (painting == nullptr && recovered) painting = &strengthPainting(cloth);
    if (painting == nullptr || !((all && painting->history().canUndo()) || recovered || painting->dirty())) continue;
    const std::string clothName = scene_.cloths[static_cast<std::size_t>(cloth)].name;
    const std::filesystem::path png = paintedMapFile(sceneFile, clothName, recovered ? "" : named);
    painting->savePng(png);
    next = withStrengthMapImage(next, cloth, png.filename().string(), painting->map().black, painting->map().white);
  }
  if (next != document_.json()) {
    const EditResult result = edit(std::move(next), "point the scene at its painted strength maps");
    if (!result.accepted) throw std::runtime_error(result.message);
  }
}

void EditorSession::autosave(Autosave& store, const std::vector<UnsavedToolTags>& toolTags) const {
  if (unsavedStrengthMaps().empty()) {
    store.write(document_, toolTags);
    return;
  }
  nlohmann::json kept = document_.json();
  std::error_code ec;
  std::filesystem::create_directories(store.directory(), ec);  // else the PNG's write says why
  for (const auto& [cloth, painting] : paintings_) {
    if (!painting->dirty() || cloth >= static_cast<int>(scene_.cloths.size())) continue;
    const std::filesystem::path png = store.strengthMapFile(document_.file(), scene_.cloths[static_cast<std::size_t>(cloth)].name);
    StrengthPainting copy(painting->map(), nullptr);  // saving marks saved: not the session's own
    copy.savePng(png);
    kept = withStrengthMapImage(kept, cloth, std::filesystem::absolute(png).string(), painting->map().black,
                                painting->map().white);
  }
  store.write(document_, kept, true, toolTags);
}

}  // namespace weft::editor
