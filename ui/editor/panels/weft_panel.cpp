// Weft/warp: the weft angle with a dial. Dragging on the dial points the weft where the mouse is;
// the woven texture in the viewport turns with it as the edit applies live.
#include <cmath>
#include <string>

#include "editor/scene_edits.h"
#include "panels.h"

namespace weft::editor {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Weft angles are kept in (-180, 180] and rounded to 0.5° so a dial drag writes tidy numbers.
double tidyAngle(double degrees) {
  double a = std::remainder(degrees, 360.0);
  if (a <= -180.0) a += 360.0;
  return std::round(a * 2.0) / 2.0;
}
}  // namespace

void drawWeftPanel(EditorSession& session, PanelState& state) {
  if (!ImGui::Begin("Weft/warp")) {
    ImGui::End();
    return;
  }
  const ClothSpec& cloth = session.scene().cloths.at(static_cast<std::size_t>(state.cloth));
  double angle = cloth.weftAngleDeg;

  const float size = 140.0f;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("dial", ImVec2(size, size));
  recordWidget(state, "weft/dial");
  const ImVec2 c(origin.x + 0.5f * size, origin.y + 0.5f * size);
  const float radius = 0.42f * size;
  if (ImGui::IsItemActive()) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const double dx = mouse.x - c.x, dy = c.y - mouse.y;  // screen y grows downwards
    if (dx * dx + dy * dy > 4.0) {
      const double picked = tidyAngle(std::atan2(dy, dx) * 180.0 / kPi);
      if (picked != angle) {
        session.edit(withWeftAngle(session.json(), state.cloth, picked), "weft angle", "weft-dial");
        angle = picked;
      }
    }
  }
  if (ImGui::IsItemDeactivated()) session.endMerge();

  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddCircleFilled(c, radius, IM_COL32(240, 240, 240, 255), 48);
  draw->AddCircle(c, radius, IM_COL32(150, 150, 150, 255), 48);
  const double a = angle * kPi / 180.0;
  auto ray = [&](double t, ImU32 colour, float thickness) {
    draw->AddLine(c, ImVec2(c.x + radius * static_cast<float>(std::cos(t)), c.y - radius * static_cast<float>(std::sin(t))),
                  colour, thickness);
  };
  ray(a, IM_COL32(40, 90, 200, 255), 3.0f);            // weft
  ray(a + 0.5 * kPi, IM_COL32(30, 150, 60, 255), 2.0f);  // warp
  draw->AddText(ImVec2(origin.x + size + 4, origin.y), IM_COL32(40, 90, 200, 255), "weft");
  draw->AddText(ImVec2(origin.x + size + 4, origin.y + 16), IM_COL32(30, 150, 60, 255), "warp");

  ImGui::SetNextItemWidth(120);
  if (ImGui::InputDouble("weft angle (deg)", &angle, 5.0, 15.0, "%.1f",
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
    if (std::isfinite(angle)) session.edit(withWeftAngle(session.json(), state.cloth, tidyAngle(angle)), "weft angle");
  }
  recordWidget(state, "weft/angle");
  ImGui::TextWrapped("Angle of the weft from the cloth's material x axis; the tear table's directions turn with it.");
  ImGui::End();
}

}  // namespace weft::editor
