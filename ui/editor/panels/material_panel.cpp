// Material: the preset, density, the measured elasticity table (c11, c12, c22, c33 for each
// measured direction, Wang et al. 2011) with a plot of each coefficient over angle, bending, an
// isotropic mode, and "save as a new preset". Editing a value of a preset makes the cloth's
// material inline in the scene (scene_edits.h); the preset file itself is only written by "save
// as preset", under a new name.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "editor/installed_data.h"
#include "editor/material_presets.h"
#include "editor/scene_edits.h"
#include "material/material.h"
#include "panels.h"
#include "preset_names.h"
#include "scene/scene_json.h"

namespace weft::editor {

namespace {

std::vector<std::string> materialPresets(const Scene& scene) {
  return presetNames(defaultSearchPaths(scene.file).materialDirs);
}

bool editNumber(const char* label, double& value, const char* format = "%.4g") {
  return numberField(label, value, format, 110);
}

void drawMeasuredTable(EditorSession& session, PanelState& state, const MeasuredElasticity& measured) {
  static const char* kCoefficients[4] = {"c11", "c12", "c22", "c33"};
  static const char* kRows[6] = {"zero strain", "0 deg", "22.5 deg", "45 deg", "67.5 deg", "90 deg"};
  if (ImGui::BeginTable("elasticity", 5, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn("N/m");
    for (const char* c : kCoefficients) ImGui::TableSetupColumn(c);
    ImGui::TableHeadersRow();
    for (int row = -1; row < 5; ++row) {
      const auto& values = row < 0 ? measured.zeroStrain : measured.directions[static_cast<std::size_t>(row)];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(kRows[row + 1]);
      for (int col = 0; col < 4; ++col) {
        ImGui::TableNextColumn();
        double v = values[static_cast<std::size_t>(col)];
        const std::string id = "##e" + std::to_string(row + 1) + std::to_string(col);
        const std::string label = std::string(kCoefficients[col]) + " at " + kRows[row + 1];
        if (numberField(id.c_str(), v, "%.5g", 80)) {
          session.edit(withElasticityCoefficient(session.json(), session.scene(), state.cloth, row, col, v), label);
        }
        recordWidget(state, "material/e" + std::to_string(row + 1) + std::to_string(col));
        if (session.refusal() && session.refusal()->label == label) {
          ImGui::GetWindowDrawList()->AddRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                                              ImGui::GetColorU32(kRefusedColour), 0.0f, 0, 2.0f);
        }
      }
    }
    ImGui::EndTable();
  }
  // A refused coefficient is framed red in the table; the reason goes under the table.
  if (session.refusal()) {
    for (int row = -1; row < 5; ++row) {
      for (int col = 0; col < 4; ++col) showRefusal(session, std::string(kCoefficients[col]) + " at " + kRows[row + 1]);
    }
  }
  // Each coefficient over the five measured directions (0 to 90 deg from the weft).
  for (int col = 0; col < 4; ++col) {
    std::array<float, 5> curve{};
    for (int d = 0; d < 5; ++d) curve[static_cast<std::size_t>(d)] = static_cast<float>(measured.directions[static_cast<std::size_t>(d)][static_cast<std::size_t>(col)]);
    const std::string overlay = std::string(kCoefficients[col]) + " over 0..90 deg";
    ImGui::PlotLines(("##plot" + std::to_string(col)).c_str(), curve.data(), 5, 0, overlay.c_str(), FLT_MAX, FLT_MAX,
                     ImVec2(260, 44));
  }
}

// Bending (Bridson 2003; measured by Wang et al. 2011 by edge direction and curvature).
void drawBending(EditorSession& session, PanelState& state, const BendingSettings& bending) {
  if (bending.model == BendingSettings::Model::None) {
    ImGui::TextUnformatted("bending: none");
    return;
  }
  if (bending.model == BendingSettings::Model::Constant) {
    double k = bending.stiffness;
    if (editNumber("bending stiffness (N*m)", k)) {
      session.edit(withBendingStiffness(session.json(), session.scene(), state.cloth, 0, 0, k), "bending stiffness");
    }
    showRefusal(session, "bending stiffness");
    return;
  }
  static const char* kRows[3] = {"0 deg", "45 deg", "90 deg"};
  if (ImGui::BeginTable("bending", 6, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn("N*m");
    for (const char* alpha : {"a=0", "a=5", "a=10", "a=15", "a=20"}) ImGui::TableSetupColumn(alpha);
    ImGui::TableHeadersRow();
    for (int row = 0; row < 3; ++row) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(kRows[row]);
      for (int col = 0; col < 5; ++col) {
        ImGui::TableNextColumn();
        double v = bending.measured[static_cast<std::size_t>(row)][static_cast<std::size_t>(col)];
        const std::string id = "##b" + std::to_string(row) + std::to_string(col);
        if (numberField(id.c_str(), v, "%.3g", 62)) {
          session.edit(withBendingStiffness(session.json(), session.scene(), state.cloth, row, col, v),
                       std::string("bending at ") + kRows[row]);
        }
      }
    }
    ImGui::EndTable();
  }
  for (const char* row : kRows) showRefusal(session, std::string("bending at ") + row);
}

// Writes the preset where the dialog says. The scene then uses it by name when it looks in that
// folder; elsewhere the scene keeps its material inline (a preset name it cannot find would make
// the scene unreadable). Returns false, with the reason in the status bar, when nothing was written.
bool saveAsPreset(EditorSession& session, PanelState& state, const Material& material) {
  const std::filesystem::path folder = std::filesystem::absolute(state.presetFolder);
  try {
    const std::filesystem::path file = saveMaterialPreset(material, state.newPresetName, folder);
    state.settings.materialPresetFolder = folder;
    if (sceneFindsPresetsIn(session.document().file(), folder)) {
      session.edit(withMaterialPreset(session.json(), state.cloth, state.newPresetName),
                   std::string("material preset ") + state.newPresetName);
      session.status = "saved the material as " + file.string() + "; the scene uses it by name";
    } else {
      session.status = "saved the material as " + file.string() +
                       "; the scene keeps its material inline (it does not look for presets in that folder)";
    }
    return true;
  } catch (const std::exception& e) {
    session.status = std::string("preset not saved: ") + e.what();
    return false;
  }
}

// "Save as new preset": name and folder (the last one used, else the scene's ../materials), what
// the scene will do with it, and a warning before writing into Weft's installed presets.
void drawSavePresetDialog(EditorSession& session, PanelState& state, const Material& material) {
  if (state.presetDialog) ImGui::OpenPopup("Save material preset");
  if (!ImGui::BeginPopupModal("Save material preset", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::SetNextItemWidth(220);
  ImGui::InputText("name", state.newPresetName, sizeof state.newPresetName);
  recordWidget(state, "material/presetname");
  ImGui::SetNextItemWidth(420);
  ImGui::InputText("folder", state.presetFolder, sizeof state.presetFolder, ImGuiInputTextFlags_AutoSelectAll);
  recordWidget(state, "material/presetfolder");
  const std::filesystem::path folder = std::filesystem::absolute(state.presetFolder);
  const std::string file = (folder / (std::string(state.newPresetName) + ".json")).string();
  ImGui::TextWrapped("Writes %s%s", file.c_str(), std::filesystem::is_directory(folder) ? "" : " (the folder is created)");
  ImGui::TextWrapped(sceneFindsPresetsIn(session.document().file(), folder)
                         ? "This scene will use the preset by name."
                         : "This scene does not look for presets there: it keeps its material inline.");
  const bool installed = isInstalledData(folder / "preset.json");
  if (installed) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.35f, 0.0f, 1.0f));
    ImGui::TextWrapped("This folder holds Weft's installed presets: every scene and every user of this copy of Weft "
                       "will see the new preset.");
    ImGui::PopStyleColor();
    ImGui::Checkbox("write into the installed presets", &state.writeInstalled);
    recordWidget(state, "material/writeinstalled");
  }
  ImGui::BeginDisabled((installed && !state.writeInstalled) || state.newPresetName[0] == '\0');
  if (ImGui::Button("Save preset") && saveAsPreset(session, state, material)) state.presetDialog = false;
  recordWidget(state, "material/savepreset");
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) state.presetDialog = false;
  if (!state.presetDialog) {
    state.writeInstalled = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace

void drawMaterialPanel(EditorSession& session, PanelState& state) {
  if (!ImGui::Begin("Material")) {
    ImGui::End();
    return;
  }
  const Scene& scene = session.scene();
  const ClothSpec& cloth = scene.cloths.at(static_cast<std::size_t>(state.cloth));
  const Material& material = cloth.material;
  ImGui::Text("Cloth: %s", cloth.name.c_str());
  const std::string shown = material.name.empty() ? "(inline)" : material.name;
  ImGui::SetNextItemWidth(220);
  if (ImGui::BeginCombo("preset", shown.c_str())) {
    for (const std::string& name : materialPresets(scene)) {
      if (ImGui::Selectable(name.c_str(), name == material.name)) {
        session.edit(withMaterialPreset(session.json(), state.cloth, name), "material " + name);
      }
    }
    ImGui::EndCombo();
  }
  recordWidget(state, "material/preset");
  ImGui::SameLine();
  if (ImGui::SmallButton("Save as...")) {
    state.presetFolder[0] = '\0';
    state.presetDialog = true;
  }
  recordWidget(state, "material/saveas");
  if (state.presetDialog && state.presetFolder[0] == '\0') {  // opened here or from the menu
    const std::filesystem::path folder = suggestedPresetFolder(state.settings.materialPresetFolder, session.document().file());
    std::snprintf(state.presetFolder, sizeof state.presetFolder, "%s", folder.string().c_str());
  }
  if (!material.source.empty()) ImGui::TextWrapped("source: %s", material.source.c_str());
  drawStrengthBrushSection(session, state);

  double density = material.areaDensity;
  // Every typed value goes to the strict reader, which refuses a bad one with the reason.
  if (editNumber("area density (kg/m^2)", density)) {
    session.edit(withAreaDensity(session.json(), scene, state.cloth, density), "area density");
  }
  recordWidget(state, "material/density");
  showRefusal(session, "area density");
  double stiffness = material.elasticity.stiffnessScale;
  if (editNumber("stiffness scale", stiffness)) {
    session.edit(withStiffnessScale(session.json(), scene, state.cloth, stiffness), "stiffness scale");
  }
  showRefusal(session, "stiffness scale");
  double bending = material.bending.stiffnessScale;
  if (editNumber("bending scale", bending)) {
    session.edit(withBendingScale(session.json(), scene, state.cloth, bending), "bending scale");
  }
  showRefusal(session, "bending scale");

  bool isotropic = material.elasticity.model == ElasticitySettings::Model::Isotropic;
  if (ImGui::Checkbox("isotropic (Young's modulus, Poisson ratio)", &isotropic)) {
    if (isotropic) {
      session.edit(withIsotropicElasticity(session.json(), scene, state.cloth, material.elasticity.youngModulus,
                                           material.elasticity.poissonRatio),
                   "isotropic elasticity");
    } else {
      session.status = "measured elasticity comes from a preset: choose one above";
    }
  }
  if (isotropic) {
    double young = material.elasticity.youngModulus;
    double poisson = material.elasticity.poissonRatio;
    if (editNumber("Young's modulus E*h (N/m)", young)) {
      session.edit(withIsotropicElasticity(session.json(), scene, state.cloth, young, poisson), "Young's modulus");
    }
    showRefusal(session, "Young's modulus");
    if (editNumber("Poisson ratio", poisson, "%.3f")) {
      session.edit(withIsotropicElasticity(session.json(), scene, state.cloth, young, poisson), "Poisson ratio");
    }
    showRefusal(session, "Poisson ratio");
  } else {
    drawMeasuredTable(session, state, material.elasticity.measured);
  }

  if (ImGui::CollapsingHeader("Bending")) drawBending(session, state, material.bending);

  drawSavePresetDialog(session, state, material);
  ImGui::End();
}

}  // namespace weft::editor
