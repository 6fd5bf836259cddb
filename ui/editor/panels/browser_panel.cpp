// Browser (issue 21, item 8): the scenes beside the open one and Weft's own, each a thumbnail of
// how it starts with its name and description (a click opens it, asking first about unsaved
// edits), and the material presets with their source (a click gives the selected cloth that
// material). The thumbnails fill in one a frame (scene_browser.h); the app makes them.
#include <algorithm>
#include <cstdint>
#include <string>

#include "editor/scene_browser.h"
#include "editor/scene_edits.h"
#include "panels.h"
#include "scene/scene_json.h"

namespace weft::editor {

namespace {

void drawScenes(EditorSession& session, PanelState& state, SceneBrowser& browser) {
  const ImVec2 thumbnail(static_cast<float>(kThumbnailWidth), static_cast<float>(kThumbnailHeight));
  const float cell = thumbnail.x + 2.0f * ImGui::GetStyle().FramePadding.x + ImGui::GetStyle().ItemSpacing.x;
  const int columns = std::max(1, static_cast<int>(ImGui::GetContentRegionAvail().x / cell));
  if (!ImGui::BeginTable("##scenes", columns)) return;
  for (const BrowserScene& scene : browser.scenes()) {
    ImGui::TableNextColumn();
    ImGui::PushID(scene.file.string().c_str());
    const bool open = scene.file == session.document().file();
    bool clicked = false;
    if (scene.thumbnail == BrowserScene::Thumbnail::Ready) {
      const auto texture = reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(scene.texture));
      clicked = ImGui::ImageButton(texture, thumbnail, ImVec2(0, 0), ImVec2(1, 1), -1, ImVec4(0, 0, 0, 0),
                                   ImVec4(1, 1, 1, open ? 0.6f : 1.0f));
    } else {
      clicked = ImGui::Button(scene.thumbnail == BrowserScene::Thumbnail::Pending ? "drawing..." : "no picture",
                              ImVec2(thumbnail.x + 2 * ImGui::GetStyle().FramePadding.x,
                                     thumbnail.y + 2 * ImGui::GetStyle().FramePadding.y));
    }
    recordWidget(state, "browser/" + scene.name);
    if (clicked && !open) {
      state.openRequest = scene.file;
      state.browserOpen = false;
    }
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + cell - ImGui::GetStyle().ItemSpacing.x);
    ImGui::TextUnformatted((scene.name + (open ? "  (open)" : "")).c_str());
    if (!scene.description.empty()) ImGui::TextDisabled("%s", scene.description.c_str());
    if (!scene.problem.empty()) ImGui::TextColored(kRefusedColour, "%s", scene.problem.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopID();
  }
  ImGui::EndTable();
}

void drawMaterials(EditorSession& session, PanelState& state, SceneBrowser& browser) {
  const Scene& scene = session.scene();
  if (scene.cloths.empty()) return;
  const ClothSpec& cloth = scene.cloths[static_cast<std::size_t>(std::clamp(state.cloth, 0, static_cast<int>(scene.cloths.size()) - 1))];
  ImGui::Text("A click gives cloth \"%s\" the material:", cloth.name.c_str());
  browser.setMaterialFolders(defaultSearchPaths(scene.file).materialDirs);  // lists them when the folders change
  for (const BrowserPreset& preset : browser.materials()) {
    if (ImGui::Selectable(preset.name.c_str(), cloth.materialName == preset.name)) {
      session.edit(withMaterialPreset(session.json(), state.cloth, preset.name), "material " + preset.name);
    }
    recordWidget(state, "browser/material/" + preset.name);
    if (preset.source.empty()) continue;
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("    %s", preset.source.c_str());
    ImGui::PopTextWrapPos();
  }
}

}  // namespace

void drawBrowserPanel(EditorSession& session, PanelState& state) {
  if (!state.browserOpen || state.browser == nullptr) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowSize(ImVec2(std::min(880.0f, io.DisplaySize.x - 40), std::min(640.0f, io.DisplaySize.y - 80)),
                           ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.5f * io.DisplaySize.y), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Browser", &state.browserOpen, ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  if (ImGui::IsWindowAppearing()) state.browser->rescan();  // files added or changed since last time
  if (ImGui::BeginTabBar("##browser")) {
    const bool scenes = ImGui::BeginTabItem("Scenes");
    recordWidget(state, "browser/scenes-tab");
    if (scenes) {
      drawScenes(session, state, *state.browser);
      ImGui::EndTabItem();
    }
    const bool materials = ImGui::BeginTabItem("Materials");
    recordWidget(state, "browser/materials-tab");
    if (materials) {
      drawMaterials(session, state, *state.browser);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
}

}  // namespace weft::editor
