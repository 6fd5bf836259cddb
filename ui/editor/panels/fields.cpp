// What every panel's fields share: where a widget was drawn (for tests), the number field, and
// the message of a refused edit shown under its field.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "panels.h"

#include "editor/installed_data.h"

namespace weft::editor {

void recordWidget(PanelState& state, const std::string& id) {
  if (state.probe == nullptr) return;
  const ImVec2 lo = ImGui::GetItemRectMin();
  const ImVec2 hi = ImGui::GetItemRectMax();
  state.probe->rects[id] = ImVec4(lo.x, lo.y, hi.x, hi.y);
}

void wrappedText(PanelState& state, const std::string& id, const std::string& text) {
  ImGui::TextWrapped("%s", text.c_str());
  recordWidget(state, id);
  if (state.probe != nullptr) state.probe->texts[id] = text;
}

void saveScene(EditorSession& session, PanelState& state) {
  if (session.savesIntoInstalledData()) {
    const std::filesystem::path copy = suggestedSceneCopy(session.document().file());
    std::snprintf(state.saveAsPath, sizeof state.saveAsPath, "%s", copy.string().c_str());
    state.saveAsRequested = true;
    session.status = session.document().file().filename().string() + " ships with Weft: choose where to save your version";
    return;
  }
  try {
    session.save();
  } catch (const std::exception& e) {
    session.status = e.what();
  }
}

bool numberField(const char* label, double& value, const char* format, float width) {
  ImGui::SetNextItemWidth(width);
  return ImGui::InputDouble(label, &value, 0.0, 0.0, format,
                            ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll) &&
         std::isfinite(value);
}

const ImVec4 kRefusedColour(0.80f, 0.05f, 0.05f, 1.0f);

bool showRefusal(const EditorSession& session, const std::string& label) {
  const std::optional<Refusal>& refusal = session.refusal();
  if (!refusal || refusal->label != label) return false;
  // The field itself shows the value in force again; the message says what was refused and why.
  ImGui::PushStyleColor(ImGuiCol_Text, kRefusedColour);
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(("not applied: " + refusal->message).c_str());
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
  return true;
}

}  // namespace weft::editor
