// Scene: the cloths (pick the one the other panels edit), obstacles and tools, the stages the
// scene runs, and the document's save, undo and redo.
#include <algorithm>
#include <cmath>
#include <functional>
#include <filesystem>
#include <string>
#include <vector>

#include "editor/scene_edits.h"
#include "panels.h"
#include "editor/shared_undo.h"
#include "preset_names.h"

namespace weft::editor {

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

// Three numbers edited together (a vector), applied when Enter is pressed in any of them.
bool editVector(const char* label, Vec3& value) {
  double v[3] = {value.x(), value.y(), value.z()};
  ImGui::SetNextItemWidth(200);
  if (!ImGui::InputScalarN(label, ImGuiDataType_Double, v, 3, nullptr, nullptr, "%.3g",
                           ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
    return false;
  }
  for (double x : v) {
    if (!std::isfinite(x)) return false;
  }
  value = Vec3(v[0], v[1], v[2]);
  return true;
}

// Scene edits that can refuse (the last cloth, an unknown shape) report why in the status bar.
void tryEdit(EditorSession& session, const std::function<nlohmann::json()>& makeEdit, const std::string& label) {
  try {
    session.edit(makeEdit(), label);
  } catch (const std::exception& e) {
    session.status = label + ": " + e.what();
  }
}

void drawObjects(EditorSession& session, PanelState& state) {
  const Scene& scene = session.scene();
  ImGui::Separator();
  ImGui::TextUnformatted("Cloths");
  for (int i = 0; i < static_cast<int>(scene.cloths.size()); ++i) {
    const ClothSpec& cloth = scene.cloths[static_cast<std::size_t>(i)];
    const std::string label = cloth.name + "  (" + (cloth.materialName.empty() ? cloth.material.name : cloth.materialName) + ")";
    if (ImGui::Selectable(label.c_str(), state.cloth == i)) state.cloth = i;
    recordWidget(state, "scene/cloth" + std::to_string(i));
  }
  if (ImGui::SmallButton("Duplicate cloth")) {
    tryEdit(session, [&] { return withClothDuplicated(session.json(), state.cloth, Vec3(0.0, 0.0, 0.3)); },
            "duplicate cloth");
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(scene.cloths.size() < 2);
  if (ImGui::SmallButton("Remove cloth")) {
    const int removed = state.cloth;
    state.cloth = 0;
    tryEdit(session, [&] { return withoutCloth(session.json(), removed); }, "remove cloth");
  }
  ImGui::EndDisabled();

  ImGui::Separator();
  ImGui::TextUnformatted("Obstacles and tools");
  if (state.obstacle >= static_cast<int>(scene.obstacles.size())) state.obstacle = -1;
  for (int i = 0; i < static_cast<int>(scene.obstacles.size()); ++i) {
    if (ImGui::Selectable(scene.obstacles[static_cast<std::size_t>(i)].name.c_str(), state.obstacle == i)) state.obstacle = i;
    recordWidget(state, "scene/obstacle" + std::to_string(i));
  }
  // New obstacles appear beside the first cloth's first vertex, where they can be seen.
  const std::shared_ptr<const WorldSnapshot> shown = session.view();
  const Vec3 at = shown->cloths.empty() || shown->cloths[0].x.empty() ? Vec3::Zero() : shown->cloths[0].x.front();
  if (ImGui::SmallButton("Add sphere")) {
    tryEdit(session, [&] { return withObstacleAdded(session.json(), "sphere", at + Vec3(0.3, -0.3, 0.3), 0.1); },
            "add sphere");
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("Add box")) {
    tryEdit(session, [&] { return withObstacleAdded(session.json(), "box", at + Vec3(0.3, -0.3, 0.3), 0.1); }, "add box");
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(state.obstacle < 0);
  if (ImGui::SmallButton("Remove")) {
    const int removed = state.obstacle;
    state.obstacle = -1;
    tryEdit(session, [&] { return withoutObstacle(session.json(), removed); }, "remove obstacle");
    // The tools' tag editors follow their obstacles: the removed one's is set aside (back with an
    // undo), those after it move up one (tool_tag_editors.h).
    state.tools.follow(session);
  }
  recordWidget(state, "scene/remove");
  ImGui::EndDisabled();
}

void drawForces(EditorSession& session) {
  const ForcesSpec& forces = session.scene().forces;
  ImGui::Separator();
  ImGui::TextUnformatted("Forces");
  Vec3 gravity = forces.gravity;
  if (editVector("gravity (m/s^2)", gravity)) session.edit(withGravity(session.json(), gravity), "gravity");
  showRefusal(session, "gravity");
  Vec3 wind = forces.wind.velocity;
  if (editVector("wind (m/s)", wind)) session.edit(withWind(session.json(), wind), "wind");
  showRefusal(session, "wind");
  double damping = forces.damping.mass;
  if (numberField("mass damping (1/s)", damping, "%.3g", 100)) {
    session.edit(withMassDamping(session.json(), damping), "mass damping");
  }
  showRefusal(session, "mass damping");
}

}  // namespace

void drawScenePanel(EditorSession& session, PanelState& state) {
  if (!ImGui::Begin("Scene")) {
    ImGui::End();
    return;
  }
  ImGui::Text("%s%s", session.document().file().filename().string().c_str(), session.dirty() ? " *" : "");
  if (ImGui::Button("Save")) saveScene(session, state);
  recordWidget(state, "scene/save");
  ImGui::SameLine();
  // The editor's one history (shared_undo.h): a sharp tag clicked last, on any tool, is undone here too.
  ImGui::BeginDisabled(!canUndoLatest(session, state.tools));
  if (ImGui::Button("Undo")) undoLatest(session, state.tools);
  recordWidget(state, "scene/undo");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!canRedoLatest(session, state.tools));
  if (ImGui::Button("Redo")) redoLatest(session, state.tools);
  recordWidget(state, "scene/redo");
  ImGui::EndDisabled();
  if (state.browser != nullptr) {
    ImGui::SameLine();
    if (ImGui::Button("Browse...")) state.browserOpen = true;  // thumbnails and descriptions
    recordWidget(state, "scene/browse");
  }

  ImGui::SetNextItemWidth(220);
  if (ImGui::BeginCombo("open", session.document().file().filename().string().c_str())) {
    for (const auto& file : scenesBeside(session.document().file())) {
      if (ImGui::Selectable(file.filename().string().c_str(), file == session.document().file())) state.openRequest = file;
      if (ImGui::IsItemHovered()) {  // what the scene shows, before opening it
        const std::string description = sceneDescription(file);
        if (!description.empty()) {
          ImGui::BeginTooltip();
          ImGui::PushTextWrapPos(420.0f);
          ImGui::TextUnformatted(description.c_str());
          ImGui::PopTextWrapPos();
          ImGui::EndTooltip();
        }
      }
    }
    ImGui::EndCombo();
  }
  recordWidget(state, "scene/open");
  ImGui::SetNextItemWidth(170);
  ImGui::InputTextWithHint("##openpath", "path/to/scene.json", state.openPath, sizeof state.openPath,
                           ImGuiInputTextFlags_AutoSelectAll);
  recordWidget(state, "scene/openpath");
  ImGui::SameLine();
  if (ImGui::Button("Open") && state.openPath[0] != '\0') state.openRequest = std::filesystem::absolute(state.openPath);

  ImGui::SetNextItemWidth(170);
  ImGui::InputTextWithHint("##saveas", "other/scene.json", state.saveAsPath, sizeof state.saveAsPath,
                           ImGuiInputTextFlags_AutoSelectAll);
  ImGui::SameLine();
  if (ImGui::Button("Save as") && state.saveAsPath[0] != '\0') {
    try {
      session.saveAs(std::filesystem::absolute(state.saveAsPath));
    } catch (const std::exception& e) {
      session.status = e.what();
    }
  }
  drawObjects(session, state);
  drawForces(session);

  ImGui::Separator();
  ImGui::TextUnformatted("Stages");
  const std::string stages[] = {"gravity", "wind", "bending", "collision", "tearing"};
  for (const std::string& name : stages) {
    bool on = session.json().contains("stages") ? session.json()["stages"].value(name, true) : true;
    if (ImGui::Checkbox(name.c_str(), &on)) {
      session.edit(withStage(session.json(), name, on), std::string(on ? "run " : "skip ") + name);
    }
  }
  ImGui::TextDisabled("runs now:");
  for (const std::string& name : session.view()->stagesRun) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", name.c_str());
  }
  ImGui::End();
}

}  // namespace weft::editor
