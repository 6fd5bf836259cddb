#pragma once
// What playback achieves, measured rather than asked for: simulated seconds per real second, the
// wall time of a step and the display's frame rate, over the last second of frames. The speed
// slider is only a target; a heavy scene falls behind it, and this is what says so.
//
// No clock inside: the caller passes each frame's wall duration and the step times it measured,
// so tests feed it exact numbers.
#include <deque>
#include <string>

namespace weft::editor {

class PlaybackMeter {
 public:
  // Steps taken since the last frame() and the wall time (ms) they took together.
  void addSteps(long long steps, double wallMs);
  // One displayed frame that lasted `wallSeconds` (since the previous one) and advanced the
  // simulation by `simulatedSeconds`. Frames older than the window are forgotten.
  void frame(double wallSeconds, double simulatedSeconds);

  bool measured() const { return !frames_.empty(); }
  double achievedSpeed() const;    // simulated s per wall s over the window; 0 with no frames
  double framesPerSecond() const;  // displayed frames per wall second over the window
  // Mean wall ms of a step over the window, else of the last steps measured; 0 before any step.
  double msPerStep() const;
  double stepsPerFrame() const;    // mean steps a displayed frame over the window

  static constexpr double kWindowSeconds = 1.0;

 private:
  struct Frame {
    double wallSeconds = 0.0;
    double simulatedSeconds = 0.0;
    long long steps = 0;
    double stepMs = 0.0;
  };
  std::deque<Frame> frames_;
  long long pendingSteps_ = 0;  // since the last frame()
  double pendingMs_ = 0.0;
  double lastMsPerStep_ = 0.0;
};

// The playback panel's readout: the target, what is achieved, ms per step and the frame rate,
// e.g. "target 1.00x  achieved 0.22x real time  |  45.1 ms a step, 1.0 a frame  |  12 fps".
std::string playbackReadout(const PlaybackMeter& meter, double targetSpeed, bool paused);

}  // namespace weft::editor
