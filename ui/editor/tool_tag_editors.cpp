#include "editor/tool_tag_editors.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <utility>

#include "editor/align_by_name.h"

namespace weft::editor {

namespace {

std::vector<std::string> obstacleNames(const EditorSession& session) {
  std::vector<std::string> names;
  for (const ObstacleSpec& spec : session.scene().obstacles) names.push_back(spec.name);
  return names;
}

}  // namespace

ToolTagEditors::Kept::Kept(const EditorSession& session, int obstacle)
    : editor(session, obstacle),
      worldGeneration(session.worldGeneration()),
      meshPath(session.scene().obstacles[static_cast<std::size_t>(obstacle)].shape.meshPath) {}

ToolTagEditor* ToolTagEditors::current() {
  const auto it = kept_.find(current_);
  return it == kept_.end() ? nullptr : &it->second->editor;
}

const ToolTagEditor* ToolTagEditors::current() const {
  const auto it = kept_.find(current_);
  return it == kept_.end() ? nullptr : &it->second->editor;
}

ToolTagEditor& ToolTagEditors::select(const EditorSession& session, int obstacle) {
  follow(session);
  auto it = kept_.find(obstacle);
  if (it == kept_.end()) it = kept_.emplace(obstacle, std::make_unique<Kept>(session, obstacle)).first;
  current_ = obstacle;
  return it->second->editor;
}

void ToolTagEditors::deselect() { current_ = -1; }

void ToolTagEditors::follow(const EditorSession& session) {
  std::vector<std::string> names = obstacleNames(session);
  if (names == names_) return;
  const std::vector<int> to = alignByName(names_, names);
  const auto& obstacles = session.scene().obstacles;
  std::map<int, std::unique_ptr<Kept>> moved;
  int current = -1;
  for (auto& [was, kept] : kept_) {
    const int now = was < static_cast<int>(to.size()) ? to[static_cast<std::size_t>(was)] : -1;
    if (now < 0) {
      aside_.push_back(std::move(kept));  // its obstacle was removed: its editor goes with it
      continue;
    }
    kept->editor.obstacle_ = now;
    if (was == current_) current = now;
    moved.emplace(now, std::move(kept));
  }
  // An obstacle back in the scene (its removal undone): its editor comes back with it.
  for (int now = 0; now < static_cast<int>(obstacles.size()); ++now) {
    if (moved.count(now)) continue;
    const ObstacleSpec& spec = obstacles[static_cast<std::size_t>(now)];
    for (auto it = aside_.rbegin(); it != aside_.rend(); ++it) {
      if ((*it)->editor.name() != spec.name || spec.shape.kind != ShapeKind::Mesh || (*it)->meshPath != spec.shape.meshPath) continue;
      (*it)->editor.obstacle_ = now;
      moved.emplace(now, std::move(*it));
      aside_.erase(std::next(it).base());
      break;
    }
  }
  kept_ = std::move(moved);
  current_ = current;
  names_ = std::move(names);
}

void ToolTagEditors::clear() {
  kept_.clear();
  aside_.clear();
  names_.clear();
  current_ = -1;
}

std::vector<std::string> ToolTagEditors::reapplyAfterReset(EditorSession& session) {
  follow(session);
  std::vector<std::string> dropped;
  for (auto it = kept_.begin(); it != kept_.end();) {
    Kept& kept = *it->second;
    if (kept.worldGeneration == session.worldGeneration()) {
      ++it;
    } else if (kept.editor.reapply(session)) {
      kept.worldGeneration = session.worldGeneration();
      ++it;
    } else {
      if (kept.editor.document().dirty()) dropped.push_back(kept.editor.name());
      if (current_ == it->first) current_ = -1;
      it = kept_.erase(it);
    }
  }
  return dropped;
}

std::vector<ToolTagEditor*> ToolTagEditors::editors() {
  std::vector<ToolTagEditor*> all;
  for (auto& [obstacle, kept] : kept_) all.push_back(&kept->editor);
  return all;
}

std::vector<const ToolTagEditor*> ToolTagEditors::editors() const {
  std::vector<const ToolTagEditor*> all;
  for (const auto& [obstacle, kept] : kept_) all.push_back(&kept->editor);
  return all;
}

std::vector<UnsavedToolTags> ToolTagEditors::unsavedTags() const {
  std::vector<UnsavedToolTags> unsaved;
  for (const auto& [obstacle, kept] : kept_) {
    const ToolTagEditor& tool = kept->editor;
    if (!tool.document().dirty()) continue;
    unsaved.push_back(UnsavedToolTags{obstacle, tool.name(), tool.inScene() ? std::filesystem::path() : tool.document().file(),
                                      tool.inScene(), tool.document().json()});
  }
  return unsaved;
}

std::vector<std::string> ToolTagEditors::recover(EditorSession& session, const std::vector<UnsavedToolTags>& tags) {
  std::vector<std::string> skipped;
  const auto& obstacles = session.scene().obstacles;
  for (const UnsavedToolTags& recovered : tags) {
    const bool there = recovered.obstacle >= 0 && recovered.obstacle < static_cast<int>(obstacles.size()) &&
                       obstacles[static_cast<std::size_t>(recovered.obstacle)].name == recovered.tool;
    if (!there) {
      skipped.push_back(recovered.tool);
      continue;
    }
    const int wasCurrent = current_;
    try {
      select(session, recovered.obstacle).recover(session, recovered.tags);
    } catch (const std::exception&) {
      skipped.push_back(recovered.tool);  // a generated shape now, or tags its mesh cannot have
    }
    current_ = wasCurrent;
  }
  return skipped;
}

std::vector<std::string> ToolTagEditors::unsavedToolNames() const {
  std::vector<std::string> names;
  for (const auto& [obstacle, kept] : kept_) {
    if (kept->editor.document().dirty()) names.push_back(kept->editor.name());
  }
  return names;
}

void ToolTagEditors::saveUnsaved(EditorSession& session) {
  follow(session);
  for (auto& [obstacle, kept] : kept_) {
    ToolTagEditor& tool = kept->editor;
    if (!tool.document().dirty()) continue;
    if (tool.inScene()) {
      tool.saveInScene(session);
    } else if (tool.savesIntoInstalledData()) {
      tool.saveBesideScene(session);
    } else {
      tool.saveToToolFile(session);
    }
  }
}

}  // namespace weft::editor
