// Material: the preset, density, the measured elasticity table (c11, c12, c22, c33 for each
// measured direction, Wang et al. 2011) with a plot of each coefficient over angle, bending, an
// isotropic mode, and "save as a new preset". Editing a value of a preset makes the cloth's
// material inline in the scene (scene_edits.h); the preset file itself is only written by "save
// as preset", under a new name.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

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
        if (numberField(id.c_str(), v, "%.5g", 80)) {
          session.edit(withElasticityCoefficient(session.json(), session.scene(), state.cloth, row, col, v),
                       std::string(kCoefficients[col]) + " at " + kRows[row + 1]);
        }
        recordWidget(state, "material/e" + std::to_string(row + 1) + std::to_string(col));
      }
    }
    ImGui::EndTable();
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
    if (editNumber("bending stiffness (N*m)", k) && k >= 0.0) {
      session.edit(withBendingStiffness(session.json(), session.scene(), state.cloth, 0, 0, k), "bending stiffness");
    }
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
        if (numberField(id.c_str(), v, "%.3g", 62) && v >= 0.0) {
          session.edit(withBendingStiffness(session.json(), session.scene(), state.cloth, row, col, v),
                       std::string("bending at ") + kRows[row]);
        }
      }
    }
    ImGui::EndTable();
  }
}

void saveAsPreset(EditorSession& session, PanelState& state, const Material& material) {
  const auto folders = defaultSearchPaths(session.scene().file).materialDirs;
  if (folders.empty()) return;
  try {
    const std::filesystem::path file = saveMaterialPreset(material, state.newPresetName, folders.front());
    session.edit(withMaterialPreset(session.json(), state.cloth, state.newPresetName),
                 std::string("material preset ") + state.newPresetName);
    session.status = "saved the material as " + file.string();
  } catch (const std::exception& e) {
    session.status = e.what();
  }
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
  if (!material.source.empty()) ImGui::TextWrapped("source: %s", material.source.c_str());

  double density = material.areaDensity;
  if (editNumber("area density (kg/m^2)", density) && density > 0.0) {
    session.edit(withAreaDensity(session.json(), scene, state.cloth, density), "area density");
  }
  recordWidget(state, "material/density");
  double stiffness = material.elasticity.stiffnessScale;
  if (editNumber("stiffness scale", stiffness) && stiffness > 0.0) {
    session.edit(withStiffnessScale(session.json(), scene, state.cloth, stiffness), "stiffness scale");
  }
  double bending = material.bending.stiffnessScale;
  if (editNumber("bending scale", bending) && bending >= 0.0) {
    session.edit(withBendingScale(session.json(), scene, state.cloth, bending), "bending scale");
  }

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
    if (editNumber("Young's modulus E*h (N/m)", young) && young > 0.0) {
      session.edit(withIsotropicElasticity(session.json(), scene, state.cloth, young, poisson), "Young's modulus");
    }
    if (editNumber("Poisson ratio", poisson, "%.3f") && poisson >= 0.0 && poisson < 0.5) {
      session.edit(withIsotropicElasticity(session.json(), scene, state.cloth, young, poisson), "Poisson ratio");
    }
  } else {
    drawMeasuredTable(session, state, material.elasticity.measured);
  }

  if (ImGui::CollapsingHeader("Bending")) drawBending(session, state, material.bending);

  ImGui::Separator();
  ImGui::SetNextItemWidth(160);
  ImGui::InputText("##presetname", state.newPresetName, sizeof state.newPresetName);
  ImGui::SameLine();
  if (ImGui::Button("Save as new preset")) saveAsPreset(session, state, material);
  ImGui::End();
}

}  // namespace weft::editor
