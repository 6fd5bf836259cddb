// The Material panel's tear strength brush (issue 23): "Paint tear strength" turns the viewport's
// left drag on a cloth into strokes of the brush (editor/strength_painting.h, through the session:
// each stroke is one undo step and reaches the running world when it ends), with the brush's
// radius, the multiplier it paints and erase. The cloth is drawn tinted by its map meanwhile (the
// app: weak red, strong blue). File > Save writes the map beside the scene.
#include <algorithm>
#include <string>

#include "panels.h"

namespace weft::editor {

void drawStrengthBrushSection(EditorSession& session, PanelState& state) {
  ImGui::Separator();
  ImGui::Checkbox("Paint tear strength", &state.paintMode);
  recordWidget(state, "material/paint");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Left drag on a cloth paints its tear strength (red: weaker, blue: stronger); right or middle "
                      "drag still moves the camera. Ctrl+Z takes a stroke back; File > Save writes the map beside the "
                      "scene.");
  }
  if (!state.paintMode) return;
  if (state.tagMode) ImGui::TextDisabled("(the Tools panel's tag mode has the mouse: turn it off to paint)");
  StrengthBrush& brush = state.brush;
  float radiusCm = static_cast<float>(brush.radius * 100.0);
  ImGui::SetNextItemWidth(160);
  if (ImGui::SliderFloat("radius (cm)", &radiusCm, 0.5f, 30.0f, "%.1f", ImGuiSliderFlags_Logarithmic)) {
    brush.radius = std::max(static_cast<double>(radiusCm), 0.1) / 100.0;
  }
  recordWidget(state, "material/paint_radius");
  float multiplier = static_cast<float>(brush.multiplier);
  ImGui::SetNextItemWidth(160);
  if (ImGui::SliderFloat("strength x", &multiplier, 0.05f, 4.0f, "%.2f", ImGuiSliderFlags_Logarithmic)) {
    brush.multiplier = multiplier;
  }
  recordWidget(state, "material/paint_strength");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("The multiplier on the tear table's strength the brush paints at its centre (below 1 weaker, "
                      "above 1 stronger), within the map's black..white.");
  }
  ImGui::Checkbox("erase (back to the map as loaded)", &brush.erase);
  recordWidget(state, "material/paint_erase");
  const int cloth = state.cloth;
  if (const StrengthPainting* painting = session.findStrengthPainting(cloth)) {
    const TearStrengthMap& map = painting->map();
    ImGui::TextDisabled("map %dx%d px, x%.2f..x%.2f%s", map.width, map.height, map.black, map.white,
                        painting->dirty() ? ", unsaved" : "");
  } else if (cloth < static_cast<int>(session.scene().cloths.size()) &&
             !session.scene().cloths[static_cast<std::size_t>(cloth)].tearStrengthMap) {
    ImGui::TextDisabled("no map yet: the first stroke makes one (x0.05..x1)");
  }
}

}  // namespace weft::editor
