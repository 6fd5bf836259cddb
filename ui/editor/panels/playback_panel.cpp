// Playback: play, pause, single step, reset and speed.
#include "panels.h"

namespace weft::editor {

void drawPlaybackPanel(EditorSession& session, PanelState& state) {
  if (!ImGui::Begin("Playback")) {
    ImGui::End();
    return;
  }
  if (ImGui::Button(session.paused ? "Play" : "Pause")) session.paused = !session.paused;
  recordWidget(state, "play/toggle");
  ImGui::SameLine();
  if (ImGui::Button("Step")) {
    session.paused = true;
    session.stepOnce();
  }
  recordWidget(state, "play/step");
  ImGui::SameLine();
  if (ImGui::Button(session.resetPending() ? "Reset (applies edits)" : "Reset")) session.reset();
  recordWidget(state, "play/reset");
  float speed = static_cast<float>(session.speed);
  ImGui::SetNextItemWidth(160);
  if (ImGui::SliderFloat("speed", &speed, 0.05f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) session.speed = speed;
  ImGui::Text("t = %.3f s   step %lld%s", session.world().time(), session.world().stepCount(),
              session.stopped() ? "   STOPPED (non-finite)" : "");
  ImGui::End();
}

}  // namespace weft::editor
