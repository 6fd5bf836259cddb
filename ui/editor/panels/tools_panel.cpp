// Tools: pick a tool, tag its vertices and edges sharp by clicking them in the viewport (sharp
// parts are drawn red), undo, and save the tags beside the tool's mesh; throw a ball from the
// camera.
#include <string>

#include "panels.h"

namespace weft::editor {

void drawToolsPanel(EditorSession& session, PanelState& state) {
  if (!ImGui::Begin("Tools")) {
    ImGui::End();
    return;
  }
  const auto& obstacles = session.scene().obstacles;
  if (session.resetPending()) {
    // The document's obstacles and the running world's may differ until the reset; the tags
    // being edited are kept.
    state.tagMode = false;
    ImGui::TextWrapped("Reset (Playback panel) to apply the scene's edits before tagging tools.");
    ImGui::End();
    return;
  }
  if (state.tool && state.tool->obstacle() >= static_cast<int>(obstacles.size())) state.tool.reset();
  const std::string current = state.tool ? obstacles[static_cast<std::size_t>(state.tool->obstacle())].name : "(none)";
  ImGui::SetNextItemWidth(200);
  if (ImGui::BeginCombo("tool", current.c_str())) {
    for (int i = 0; i < static_cast<int>(obstacles.size()); ++i) {
      const std::string& name = obstacles[static_cast<std::size_t>(i)].name;
      if (ImGui::Selectable(name.c_str(), state.tool && state.tool->obstacle() == i)) {
        try {
          state.tool.emplace(session, i);
          state.toolGeneration = session.worldGeneration();
        } catch (const std::exception& e) {
          state.tool.reset();
          session.status = e.what();
        }
      }
    }
    ImGui::EndCombo();
  }
  recordWidget(state, "tools/tool");

  if (state.tool) {
    if (state.toolGeneration != session.worldGeneration()) {
      if (!state.tool->reapply(session)) {
        session.status = "the tool being tagged is gone from the scene; its unsaved tags were dropped";
        state.tool.reset();
        ImGui::End();
        return;
      }
      state.toolGeneration = session.worldGeneration();
    }
    const SharpTags tags = state.tool->tags();
    ImGui::Text("%zu sharp vertices, %zu sharp edges", tags.vertices.size(), tags.edges.size());
    ImGui::TextWrapped("tags file: %s%s", state.tool->document().file().string().c_str(),
                       state.tool->document().dirty() ? " (unsaved)" : "");
    ImGui::Checkbox("click the tool to tag sharp", &state.tagMode);
    recordWidget(state, "tools/tagmode");
    ImGui::BeginDisabled(!state.tool->document().history().canUndo());
    if (ImGui::Button("Undo tag")) state.tool->undo(session);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!state.tool->document().history().canRedo());
    if (ImGui::Button("Redo tag")) state.tool->redo(session);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Save tags")) {
      try {
        state.tool->save();
        session.status = "saved " + state.tool->document().file().string();
      } catch (const std::exception& e) {
        session.status = e.what();
      }
    }
    recordWidget(state, "tools/save");
  } else {
    state.tagMode = false;
    ImGui::TextWrapped("Choose a tool to tag its sharp vertices and edges (mesh tools only).");
  }
  ImGui::Separator();
  if (ImGui::Button("Throw a ball (B)")) state.throwBallRequested = true;
  ImGui::TextWrapped("In the viewport: drag the cloth to pull it (and tear it); Alt+drag moves a kinematic tool.");
  ImGui::End();
}

}  // namespace weft::editor
