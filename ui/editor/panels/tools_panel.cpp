// Tools: pick a tool, tag its vertices and edges sharp by clicking them in the viewport (sharp
// parts are drawn red), undo, and save the tags: beside the tool's mesh, or, for a tool shipped
// with Weft or one whose tags file another obstacle of the scene reads too, beside the scene
// (the shipped one unless the user says to change the shipped file); throw a ball from the camera.
#include <optional>
#include <string>
#include <vector>

#include "panels.h"
#include "editor/shared_undo.h"

namespace weft::editor {

namespace {

enum class TagsGoTo { ToolFile, BesideScene, InScene };

void saveTags(EditorSession& session, ToolTagEditor& tool, TagsGoTo where) {
  try {
    if (where == TagsGoTo::InScene) {
      tool.saveInScene(session);
      session.status = "the tags of " + session.scene().obstacles[static_cast<std::size_t>(tool.obstacle())].name +
                       " are in the scene now; save the scene to keep them";
    } else if (where == TagsGoTo::BesideScene) {
      const std::filesystem::path file = tool.saveBesideScene(session);
      session.status = "saved " + file.string() + "; the scene reads the tags from there";
    } else if (const std::optional<std::string> other = tool.tagsFileSharedWith(session)) {
      // Tags are per obstacle (sharp_tag_edits.h): the other's file is left as it was.
      const std::filesystem::path file = tool.saveToToolFile(session);
      session.status = "saved " + file.string() + ": " + other.value() + " reads " + tool.name() +
                       "'s old tags file too, so " + tool.name() + " has its own now; save the scene to keep it";
    } else {
      const std::filesystem::path file = tool.saveToToolFile(session);
      session.status = "saved " + file.string();
    }
  } catch (const std::exception& e) {
    session.status = std::string("tags not saved: ") + e.what();
  }
}

// A shipped tool's tags file is shared by every scene that uses the tool: ask first.
void drawTagsDialog(EditorSession& session, PanelState& state) {
  if (state.tagsDialog) ImGui::OpenPopup("Save sharp tags");
  if (!ImGui::BeginPopupModal("Save sharp tags", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ToolTagEditor& tool = *state.tools.current();
  const std::filesystem::path shipped = tool.document().file();
  ImGui::TextWrapped("%s is a tool shipped with Weft; its tags file %s is used by every scene with this tool.",
                     tool.name().c_str(), shipped.string().c_str());
  // A scene shipped with Weft lives among Weft's own files: nothing goes beside it.
  const bool sceneShipped = session.savesIntoInstalledData();
  if (sceneShipped) {
    ImGui::TextWrapped("This scene ships with Weft too: keep the tags in it, then save your version of the scene with "
                       "Save as.");
  } else {
    wrappedText(state, "tools/besidescenetext",
                "Save beside this scene: writes " + tool.besideSceneTarget(session).string() +
                    "; the scene reads the tags from there (save the scene to keep that).");
  }
  wrappedText(state, "tools/inscenetext", "Keep them in this scene: the tags go into the scene file, saved with it.");
  // Tags are per obstacle (sharp_tag_edits.h): with another obstacle on the same file, "Change the
  // shipped file" writes this one's own file beside the scene, and the dialog says so.
  const std::optional<std::string> other = tool.tagsFileSharedWith(session);
  if (other && sceneShipped) {
    wrappedText(state, "tools/saveshippedtext",
                "Change the shipped file: " + other.value() + " in this scene reads that file too, so the tags would "
                "go beside this scene, which ships with Weft: keep them in the scene instead.");
  } else if (other) {
    wrappedText(state, "tools/saveshippedtext",
                "Change the shipped file: " + other.value() + " in this scene reads that file too, so this writes " +
                    tool.toolFileTarget(session).string() + " beside the scene instead; the shipped file stays as it is.");
  } else {
    wrappedText(state, "tools/saveshippedtext",
                "Change the shipped file: writes " + shipped.string() + ", for every scene with this tool.");
  }
  ImGui::BeginDisabled(sceneShipped);
  if (ImGui::Button("Save beside this scene")) {
    saveTags(session, tool, TagsGoTo::BesideScene);
    state.tagsDialog = false;
  }
  ImGui::EndDisabled();
  recordWidget(state, "tools/savebesidescene");
  ImGui::SameLine();
  if (ImGui::Button("Keep them in this scene")) {
    saveTags(session, tool, TagsGoTo::InScene);
    state.tagsDialog = false;
  }
  recordWidget(state, "tools/saveinscene");
  ImGui::SameLine();
  ImGui::BeginDisabled(other && sceneShipped);
  if (ImGui::Button("Change the shipped file")) {
    saveTags(session, tool, TagsGoTo::ToolFile);
    state.tagsDialog = false;
  }
  ImGui::EndDisabled();
  recordWidget(state, "tools/saveshipped");
  ImGui::SameLine();
  if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) state.tagsDialog = false;
  if (!state.tagsDialog) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

// After a reset the world's tools hold their files' tags again: every tool's unsaved tags go back
// in, whether or not the panel is open.
void reapplyTagsAfterReset(EditorSession& session, PanelState& state) {
  if (session.resetPending()) return;  // the world is not rebuilt yet
  const std::vector<std::string> dropped = state.tools.reapplyAfterReset(session);
  if (!dropped.empty()) {
    std::string names;
    for (const std::string& name : dropped) names += (names.empty() ? "" : ", ") + name;
    session.status = names + (dropped.size() == 1 ? " is" : " are") + " gone from the scene; the unsaved tags were dropped";
  }
}

}  // namespace

void drawToolsPanel(EditorSession& session, PanelState& state) {
  reapplyTagsAfterReset(session, state);
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
  if (state.tools.current() && state.tools.current()->obstacle() >= static_cast<int>(obstacles.size())) {
    state.tools.deselect();
  }
  // Picking another tool keeps this one's unsaved tags and undo steps (tool_tag_editors.h).
  const std::string current = state.tools.current() ? state.tools.current()->name() : "(none)";
  ImGui::SetNextItemWidth(200);
  if (ImGui::BeginCombo("tool", current.c_str())) {
    for (int i = 0; i < static_cast<int>(obstacles.size()); ++i) {
      const std::string& name = obstacles[static_cast<std::size_t>(i)].name;
      if (ImGui::Selectable(name.c_str(), state.tools.current() && state.tools.current()->obstacle() == i)) {
        try {
          state.tools.select(session, i);
        } catch (const std::exception& e) {
          state.tools.deselect();
          session.status = e.what();
        }
      }
      recordWidget(state, "tools/tool" + std::to_string(i));
    }
    ImGui::EndCombo();
  }
  recordWidget(state, "tools/tool");

  if (ToolTagEditor* tool = state.tools.current()) {
    const SharpTags tags = tool->tags();
    ImGui::Text("%zu sharp vertices, %zu sharp edges", tags.vertices.size(), tags.edges.size());
    ImGui::TextWrapped("tags file: %s%s", tool->document().file().string().c_str(),
                       tool->document().dirty() ? " (unsaved)" : "");
    ImGui::Checkbox("click the tool to tag sharp", &state.tagMode);
    recordWidget(state, "tools/tagmode");
    // Blades: every edge where the faces fold more than the angle, in one step.
    if (ImGui::Button("Tag edges sharper than")) tool->tagEdgesSharperThan(session, state.sharperThanDeg);
    recordWidget(state, "tools/sharperthan");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(60);
    ImGui::InputDouble("deg", &state.sharperThanDeg, 0.0, 0.0, "%.0f", ImGuiInputTextFlags_AutoSelectAll);
    // The editor's one history (shared_undo.h), as Ctrl+Z: a tag's own undo here would take back
    // an older tag while a newer parameter edit stays, an order no other Undo follows.
    ToolTagEditors& tools = state.tools;
    ImGui::BeginDisabled(!canUndoLatest(session, tools));
    if (ImGui::Button("Undo")) undoLatest(session, tools);
    if (ImGui::IsItemHovered() && canUndoLatest(session, tools)) ImGui::SetTooltip("undo %s (Ctrl+Z)", latestUndoLabel(session, tools).c_str());
    recordWidget(state, "tools/undo");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!canRedoLatest(session, tools));
    if (ImGui::Button("Redo")) redoLatest(session, tools);
    if (ImGui::IsItemHovered() && canRedoLatest(session, tools)) ImGui::SetTooltip("redo %s (Ctrl+Y)", latestRedoLabel(session, tools).c_str());
    recordWidget(state, "tools/redo");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Save tags")) {
      if (tool->inScene()) {
        saveTags(session, *tool, TagsGoTo::InScene);
      } else if (tool->savesIntoInstalledData()) {
        state.tagsDialog = true;
      } else {
        saveTags(session, *tool, TagsGoTo::ToolFile);
      }
    }
    recordWidget(state, "tools/save");
    if (!tool->inScene()) {
      ImGui::SameLine();
      if (ImGui::Button("In the scene")) saveTags(session, *tool, TagsGoTo::InScene);
      recordWidget(state, "tools/inscene");
    }
    drawTagsDialog(session, state);
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
