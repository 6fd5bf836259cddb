// Scene: the cloths (pick the one the other panels edit), obstacles and tools, the stages the
// scene runs, and the document's save, undo and redo.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "panels.h"

namespace weft::editor {

void recordWidget(PanelState& state, const std::string& id) {
  if (state.probe == nullptr) return;
  const ImVec2 lo = ImGui::GetItemRectMin();
  const ImVec2 hi = ImGui::GetItemRectMax();
  state.probe->rects[id] = ImVec4(lo.x, lo.y, hi.x, hi.y);
}

namespace {

// The scenes beside the open one, to open instead.
std::vector<std::filesystem::path> scenesBeside(const std::filesystem::path& file) {
  std::vector<std::filesystem::path> scenes;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(file.parent_path(), ec)) {
    if (entry.path().extension() == ".json") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

}  // namespace

void drawScenePanel(EditorSession& session, PanelState& state) {
  if (!ImGui::Begin("Scene")) {
    ImGui::End();
    return;
  }
  const Scene& scene = session.scene();
  ImGui::Text("%s%s", session.document().file().filename().string().c_str(), session.dirty() ? " *" : "");
  if (ImGui::Button("Save")) {
    try {
      session.save();
    } catch (const std::exception& e) {
      session.status = e.what();
    }
  }
  recordWidget(state, "scene/save");
  ImGui::SameLine();
  ImGui::BeginDisabled(!session.document().history().canUndo());
  if (ImGui::Button("Undo")) session.undo();
  recordWidget(state, "scene/undo");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!session.document().history().canRedo());
  if (ImGui::Button("Redo")) session.redo();
  recordWidget(state, "scene/redo");
  ImGui::EndDisabled();

  ImGui::SetNextItemWidth(220);
  if (ImGui::BeginCombo("open", session.document().file().filename().string().c_str())) {
    for (const auto& file : scenesBeside(session.document().file())) {
      if (ImGui::Selectable(file.filename().string().c_str(), file == session.document().file())) state.openRequest = file;
    }
    ImGui::EndCombo();
  }
  recordWidget(state, "scene/open");

  ImGui::Separator();
  ImGui::TextUnformatted("Cloths");
  for (int i = 0; i < static_cast<int>(scene.cloths.size()); ++i) {
    const ClothSpec& cloth = scene.cloths[static_cast<std::size_t>(i)];
    const std::string label = cloth.name + "  (" + (cloth.materialName.empty() ? cloth.material.name : cloth.materialName) + ")";
    if (ImGui::Selectable(label.c_str(), state.cloth == i)) state.cloth = i;
    recordWidget(state, "scene/cloth" + std::to_string(i));
  }
  if (!scene.obstacles.empty()) {
    ImGui::Separator();
  ImGui::TextUnformatted("Obstacles and tools");
    for (const ObstacleSpec& o : scene.obstacles) ImGui::BulletText("%s", o.name.c_str());
  }

  ImGui::Separator();
  ImGui::TextUnformatted("Stages");
  const std::string stages[] = {"gravity", "wind", "bending", "collision", "tearing"};
  for (const std::string& name : stages) {
    bool on = session.json().contains("stages") ? session.json()["stages"].value(name, true) : true;
    if (ImGui::Checkbox(name.c_str(), &on)) {
      nlohmann::json next = session.json();
      next["stages"][name] = on;
      session.edit(std::move(next), std::string(on ? "run " : "skip ") + name);
    }
  }
  ImGui::TextDisabled("runs now:");
  for (const std::string& name : session.world().stagesRun()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", name.c_str());
  }
  ImGui::End();
}

}  // namespace weft::editor
