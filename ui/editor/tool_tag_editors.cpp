#include "editor/tool_tag_editors.h"

#include <exception>
#include <filesystem>
#include <tuple>

namespace weft::editor {

ToolTagEditor* ToolTagEditors::current() {
  const auto it = kept_.find(current_);
  return it == kept_.end() ? nullptr : &it->second.editor;
}

const ToolTagEditor* ToolTagEditors::current() const {
  const auto it = kept_.find(current_);
  return it == kept_.end() ? nullptr : &it->second.editor;
}

ToolTagEditor& ToolTagEditors::select(const EditorSession& session, int obstacle) {
  auto it = kept_.find(obstacle);
  if (it == kept_.end()) {
    it = kept_
             .emplace(std::piecewise_construct, std::forward_as_tuple(obstacle),
                      std::forward_as_tuple(session, obstacle))
             .first;
  }
  current_ = obstacle;
  return it->second.editor;
}

void ToolTagEditors::deselect() { current_ = -1; }

void ToolTagEditors::forget(int obstacle) {
  kept_.erase(obstacle);
  if (current_ == obstacle) current_ = -1;
}

void ToolTagEditors::clear() {
  kept_.clear();
  current_ = -1;
}

std::vector<std::string> ToolTagEditors::reapplyAfterReset(EditorSession& session) {
  std::vector<std::string> dropped;
  for (auto it = kept_.begin(); it != kept_.end();) {
    Kept& kept = it->second;
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
  for (auto& [obstacle, kept] : kept_) all.push_back(&kept.editor);
  return all;
}

std::vector<const ToolTagEditor*> ToolTagEditors::editors() const {
  std::vector<const ToolTagEditor*> all;
  for (const auto& [obstacle, kept] : kept_) all.push_back(&kept.editor);
  return all;
}

std::vector<UnsavedToolTags> ToolTagEditors::unsavedTags() const {
  std::vector<UnsavedToolTags> unsaved;
  for (const auto& [obstacle, kept] : kept_) {
    const ToolTagEditor& tool = kept.editor;
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
    if (kept.editor.document().dirty()) names.push_back(kept.editor.name());
  }
  return names;
}

void ToolTagEditors::saveUnsaved(EditorSession& session) {
  for (auto& [obstacle, kept] : kept_) {
    ToolTagEditor& tool = kept.editor;
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
