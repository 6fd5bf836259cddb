#include "editor/playback_meter.h"

#include <cstdio>

namespace weft::editor {

void PlaybackMeter::addSteps(long long steps, double wallMs) {
  pendingSteps_ += steps;
  pendingMs_ += wallMs;
}

void PlaybackMeter::frame(double wallSeconds, double simulatedSeconds) {
  frames_.push_back(Frame{wallSeconds, simulatedSeconds, pendingSteps_, pendingMs_});
  if (pendingSteps_ > 0) lastMsPerStep_ = pendingMs_ / static_cast<double>(pendingSteps_);
  pendingSteps_ = 0;
  pendingMs_ = 0.0;
  // Keep the newest frames that fit in the window (at least the newest one).
  double kept = 0.0;
  std::size_t keep = 0;
  for (auto it = frames_.rbegin(); it != frames_.rend() && (keep == 0 || kept + it->wallSeconds <= kWindowSeconds);
       ++it) {
    kept += it->wallSeconds;
    ++keep;
  }
  while (frames_.size() > keep) frames_.pop_front();
}

double PlaybackMeter::achievedSpeed() const {
  double wall = 0.0, simulated = 0.0;
  for (const Frame& f : frames_) {
    wall += f.wallSeconds;
    simulated += f.simulatedSeconds;
  }
  return wall > 0.0 ? simulated / wall : 0.0;
}

double PlaybackMeter::framesPerSecond() const {
  double wall = 0.0;
  for (const Frame& f : frames_) wall += f.wallSeconds;
  return wall > 0.0 ? static_cast<double>(frames_.size()) / wall : 0.0;
}

double PlaybackMeter::msPerStep() const {
  long long steps = 0;
  double ms = 0.0;
  for (const Frame& f : frames_) {
    steps += f.steps;
    ms += f.stepMs;
  }
  return steps > 0 ? ms / static_cast<double>(steps) : lastMsPerStep_;
}

double PlaybackMeter::stepsPerFrame() const {
  long long steps = 0;
  for (const Frame& f : frames_) steps += f.steps;
  return frames_.empty() ? 0.0 : static_cast<double>(steps) / static_cast<double>(frames_.size());
}

std::string playbackReadout(const PlaybackMeter& meter, double targetSpeed, bool paused) {
  char text[160];
  if (paused || !meter.measured()) {
    std::snprintf(text, sizeof text, "target %.2fx  %s  |  %.2f ms a step  |  %.0f fps", targetSpeed,
                  paused ? "paused" : "starting", meter.msPerStep(), meter.framesPerSecond());
  } else {
    std::snprintf(text, sizeof text, "target %.2fx  achieved %.2fx real time  |  %.2f ms a step, %.1f a frame  |  %.0f fps",
                  targetSpeed, meter.achievedSpeed(), meter.msPerStep(), meter.stepsPerFrame(),
                  meter.framesPerSecond());
  }
  return text;
}

}  // namespace weft::editor
