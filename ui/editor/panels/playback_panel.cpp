// Playback: play, pause, single step, reset and the target speed, with what playback achieves
// (real-time factor, ms a step, frame rate) measured beside it.
#include <algorithm>
#include <filesystem>
#include <string>

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
  if (ImGui::SliderFloat("target speed", &speed, 0.05f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) {
    session.speed = speed;
  }
  // The target is what was asked for; the scene may not keep up with it.
  const PlaybackMeter& meter = session.meter();
  const bool behind = !session.paused && meter.measured() && meter.achievedSpeed() < 0.9 * session.speed;
  if (behind) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.35f, 0.0f, 1.0f));
  ImGui::TextWrapped("%s", playbackReadout(meter, session.speed, session.paused).c_str());
  if (behind) ImGui::PopStyleColor();
  recordWidget(state, "play/readout");
  ImGui::Text("t = %.3f s   step %lld%s", session.world().time(), session.world().stepCount(),
              session.stopped() ? "   STOPPED (non-finite)" : "");
  if (state.recorder != nullptr) {
    ImGui::Separator();
    ImGui::SetNextItemWidth(90);
    ImGui::InputInt("frames", &state.recordFrames, 30, 120);
    state.recordFrames = std::max(state.recordFrames, 1);
    ImGui::SameLine();
    ImGui::Checkbox("video", &state.recordVideo);
    ImGui::BeginDisabled(state.recorder->running());
    if (ImGui::Button(state.recorder->running() ? "Recording..." : "Record headless")) {
      const std::filesystem::path out = std::filesystem::path("out") / (session.scene().name + "-recording");
      state.recorder->start(session.json(), session.document().file(), out, state.recordFrames, state.recordVideo);
    }
    ImGui::EndDisabled();
    recordWidget(state, "play/record");
    const std::string message = state.recorder->lastMessage();
    if (!message.empty()) ImGui::TextWrapped("%s", message.c_str());
  }
  ImGui::End();
}

}  // namespace weft::editor
