// Playback: play, pause, single step, reset and the target speed, with what playback achieves
// (real-time factor, ms a step, frame rate) measured beside it.
#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>

#include "panels.h"

namespace weft::editor {

namespace {

// The scrub bar over the cached frames (frame_cache.h), the cache's size against its budget, and
// what an edit does while an earlier frame is shown.
void drawTimeline(EditorSession& session, PanelState& state) {
  const FrameCache& frames = session.frames();
  if (frames.empty()) return;
  const long long live = session.liveFrame();
  int frame = static_cast<int>(session.shownFrame().value_or(live));
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderInt("##timeline", &frame, static_cast<int>(frames.firstFrame()),
                       static_cast<int>(std::max(frames.lastFrame(), live)), "frame %d")) {
    session.showFrame(frame);
  }
  recordWidget(state, "play/timeline");
  // One line right under the bar (the frame number is on it), so it is in view with the bar.
  if (const std::optional<long long> shown = session.shownFrame()) {
    if (ImGui::SmallButton("Live")) session.showLive();
    recordWidget(state, "play/live");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to frame %lld, where the simulation is (End)", live);
    ImGui::SameLine();
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.1f, 0.35f, 0.75f, 1.0f));
    ImGui::TextUnformatted("cached: an edit goes on from here");
    ImGui::PopStyleColor();
  }
  constexpr double kMiB = 1024.0 * 1024.0;
  // Every frame is shown from the cache; an edit resumes from the nearest one keeping its world.
  // The changes a resume replays count too (step_worker.h).
  // Wrapped: the panel is narrow, and the budget is the part that matters.
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("cache: %zu frames (%zu to resume from), %.1f of %.0f MB (changes logged: %.0f kB)",
                     frames.frameCount(), frames.worldCount(), frames.bytes() / kMiB, frames.budgetBytes() / kMiB,
                     frames.changeLogBytes() / 1024.0);
  ImGui::PopStyleColor();
  recordWidget(state, "play/cache");
}

}  // namespace

void drawPlaybackPanel(EditorSession& session, PanelState& state) {
  if (!ImGui::Begin("Playback")) {
    ImGui::End();
    return;
  }
  if (state.probe != nullptr) {  // the panel's own rect: tests check what stays in view
    const ImVec2 pos = ImGui::GetWindowPos();
    const ImVec2 size = ImGui::GetWindowSize();
    state.probe->rects["play/panel"] = ImVec4(pos.x, pos.y, pos.x + size.x, pos.y + size.y);
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
  const std::shared_ptr<const WorldSnapshot> shown = session.view();
  ImGui::Text("t = %.3f s   step %lld%s", shown->time, shown->stepCount,
              session.stopped() ? "   STOPPED (non-finite)" : "");
  if (const auto& unhealthy = session.unhealthy()) {
    // The warning `weft run` prints for the same steps (sim/health_check.h), until a reset: a red
    // word beside the time, the whole message under the cursor and in the status bar. Wrapped
    // here it took six lines and pushed the scrub bar out of the panel's view.
    ImGui::SameLine();
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.8f, 0.1f, 0.1f, 1.0f));
    ImGui::TextUnformatted("WARNING");
    ImGui::PopStyleColor();
    recordWidget(state, "play/health");
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      ImGui::PushTextWrapPos(ImGui::GetFontSize() * 35.0f);
      ImGui::TextUnformatted(("warning: " + healthWarning(*unhealthy)).c_str());
      ImGui::PopTextWrapPos();
      ImGui::EndTooltip();
    }
  }
  drawTimeline(session, state);
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
