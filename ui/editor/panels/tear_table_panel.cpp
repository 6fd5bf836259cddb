// Tear table: the required strength per direction (thesis §3.1, Tables 3.1 and 4.1), the number
// of evenly spaced directions, the thesis' presets, and a polar plot of the interpolated
// strength over the full circle with the weft and warp axes of the cloth drawn on it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "editor/scene_edits.h"
#include "panels.h"
#include "preset_names.h"
#include "scene/scene_json.h"
#include "tearing/tear_candidates.h"
#include "tearing/tear_region.h"
#include "tearing/tear_table.h"

namespace weft::editor {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<std::string> tearTablePresets(const Scene& scene) {
  return presetNames(defaultSearchPaths(scene.file).tearTableDirs);
}

// ℜ(α) around the full circle, in material space (screen right = material x, up = material y),
// the frame the woven texture is drawn in. The line at screen angle θ is a line at θ in material
// space; its α comes from the core's own angleFromWarpDeg, the one convention the tearing stage
// and its tear log use, so the plot's dips lie along the lines the simulation tears.
// With a tear region, its table is drawn too, in orange, on the same scale.
void drawPolarPlot(const TearTable& table, const TearTable* region, double weftAngleDeg, float size) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("polar", ImVec2(size, size));
  const ImVec2 c(origin.x + 0.5f * size, origin.y + 0.5f * size);
  // Room around the circle for the axis labels, which are kept inside the plot's square.
  const float radius = 0.40f * size;
  double largest = 0.0;
  for (double s : table.strength) largest = std::max(largest, s * table.unitNPerM);
  if (region != nullptr) {
    for (double s : region->strength) largest = std::max(largest, s * region->unitNPerM);
  }
  if (largest <= 0.0) return;

  draw->AddCircle(c, radius, IM_COL32(200, 200, 200, 255), 64);
  draw->AddCircle(c, 0.5f * radius, IM_COL32(225, 225, 225, 255), 64);
  // Material axes turned by the weft angle: U (weft) and V (warp), as the texture shows them.
  const double weft = weftAngleDeg * kPi / 180.0;
  auto axis = [&](double angle, ImU32 colour, const char* label) {
    const ImVec2 tip(c.x + radius * static_cast<float>(std::cos(angle)), c.y - radius * static_cast<float>(std::sin(angle)));
    const ImVec2 tail(c.x - radius * static_cast<float>(std::cos(angle)), c.y + radius * static_cast<float>(std::sin(angle)));
    draw->AddLine(tail, tip, colour, 1.5f);
    // The label's centre just past the tip, lifted off a near-horizontal axis so the line does not
    // cross it, then kept inside the plot's square.
    const ImVec2 text = ImGui::CalcTextSize(label);
    const float out = 0.5f * text.y + 3.0f;
    const float lift = (0.5f * text.y + 2.0f) * static_cast<float>(std::abs(std::cos(angle)));
    const float x = tip.x + out * static_cast<float>(std::cos(angle)) - 0.5f * text.x;
    const float y = tip.y - out * static_cast<float>(std::sin(angle)) - lift - 0.5f * text.y;
    draw->AddText(ImVec2(std::clamp(x, origin.x, origin.x + size - text.x), std::clamp(y, origin.y, origin.y + size - text.y)),
                  colour, label);
  };
  axis(weft, IM_COL32(40, 90, 200, 255), "weft");
  axis(weft + 0.5 * kPi, IM_COL32(30, 150, 60, 255), "warp");

  // The curve: at screen angle θ, the line direction is θ in material space.
  auto curve = [&](const TearTable& of, ImU32 colour) {
    std::vector<ImVec2> points;
    for (int i = 0; i <= 360; ++i) {
      const double theta = i * kPi / 180.0;
      const double alphaDeg = angleFromWarpDeg(theta, weft);
      const double r = radius * requiredStrength(of, alphaDeg) / largest;
      points.emplace_back(c.x + static_cast<float>(r * std::cos(theta)), c.y - static_cast<float>(r * std::sin(theta)));
    }
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), colour, 0, 2.0f);
  };
  if (region != nullptr) curve(*region, IM_COL32(235, 140, 20, 255));
  curve(table, IM_COL32(200, 40, 40, 255));
}

// The cloth's second table (core/tearing/tear_region.h), described, not edited here: its image
// and table are the scene file's. The plot above draws it in orange.
void describeTearRegion(const TearRegion& region) {
  std::string strengths;
  for (int k = 0; k < static_cast<int>(region.table.strength.size()); ++k) {
    char entry[64];
    std::snprintf(entry, sizeof entry, "%s%.3g at %.4g", k == 0 ? "" : ", ", region.table.strength[k],
                  tableDirectionDeg(region.table, k));
    strengths += entry;
  }
  ImGui::TextColored(ImVec4(0.85f, 0.5f, 0.05f, 1.0f), "Tear region (orange above):");
  ImGui::TextWrapped("where %s is white, table %s: %s deg (x %.3g N/m); edit them in the scene file",
                     region.outside.image.c_str(), region.table.name.empty() ? "inline" : region.table.name.c_str(),
                     strengths.c_str(), region.table.unitNPerM);
}

}  // namespace

void drawTearTablePanel(EditorSession& session, PanelState& state) {
  if (!ImGui::Begin("Tear table")) {
    ImGui::End();
    return;
  }
  const Scene& scene = session.scene();
  const ClothSpec& cloth = scene.cloths.at(static_cast<std::size_t>(state.cloth));
  ImGui::Text("Cloth: %s", cloth.name.c_str());

  const std::string current = cloth.material.tearTable ? cloth.material.tearTable->name : std::string();
  if (ImGui::BeginCombo("preset", current.empty() ? (cloth.material.tearTable ? "(edited)" : "(none: never tears)")
                                                  : current.c_str())) {
    if (ImGui::Selectable("(none: never tears)", !cloth.material.tearTable)) {
      session.edit(withoutTearTable(session.json(), scene, state.cloth), "remove tear table");
    }
    for (const std::string& name : tearTablePresets(scene)) {
      if (ImGui::Selectable(name.c_str(), name == current)) {
        session.edit(withTearTablePreset(session.json(), state.cloth, name), "tear table " + name);
      }
    }
    ImGui::EndCombo();
  }
  recordWidget(state, "tear/preset");

  if (!cloth.material.tearTable) {
    ImGui::TextWrapped("This cloth has no tear table and never tears.");
    if (ImGui::Button("Add a uniform table")) {
      session.edit(withInlineTearTable(session.json(), scene, state.cloth), "add tear table");
    }
    recordWidget(state, "tear/add");
    ImGui::End();
    return;
  }

  const TearTable& table = *cloth.material.tearTable;
  // Directions stay evenly spaced over [0, 180): adding or removing one resamples the curve.
  const int directions = static_cast<int>(table.strength.size());
  ImGui::Text("%d directions, every %.4g deg", directions, 180.0 / directions);
  ImGui::BeginDisabled(directions <= 1);
  if (ImGui::Button(" - ")) {
    session.edit(withTearDirections(session.json(), scene, state.cloth, directions - 1), "fewer tear directions");
  }
  recordWidget(state, "tear/fewer");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(directions >= 36);
  if (ImGui::Button(" + ")) {
    session.edit(withTearDirections(session.json(), scene, state.cloth, directions + 1), "more tear directions");
  }
  recordWidget(state, "tear/more");
  ImGui::EndDisabled();
  ImGui::Text("strength (x %.3g N/m), by direction from the warp:", table.unitNPerM);
  for (int k = 0; k < static_cast<int>(table.strength.size()); ++k) {
    double value = table.strength[static_cast<std::size_t>(k)];
    const std::string label = std::to_string(static_cast<int>(std::lround(tableDirectionDeg(table, k)))) + " deg##tear" +
                              std::to_string(k);
    const std::string editLabel = "tear strength " + label.substr(0, label.find("##"));
    if (numberField(label.c_str(), value, "%.3g", 120)) {
      session.edit(withTearStrength(session.json(), scene, state.cloth, k, value), editLabel);
    }
    recordWidget(state, "tear/" + std::to_string(k));
    showRefusal(session, editLabel);
  }
  drawPolarPlot(table, cloth.tearRegion ? &cloth.tearRegion->table : nullptr, cloth.weftAngleDeg, 220.0f);
  recordWidget(state, "tear/plot");
  if (cloth.tearRegion) describeTearRegion(*cloth.tearRegion);
  ImGui::End();
}

}  // namespace weft::editor
