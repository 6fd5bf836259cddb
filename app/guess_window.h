#pragma once
// The window of `weft guess`: for each clip it waits for the participant to press Play, plays the
// clip once at its own frame rate (decoded by ffmpeg, mp4_decoder.h; no pausing, rewinding or
// replaying: the thesis let its participants watch each video only once, §3.4), then hides it and
// asks which of the four fabrics it was and which elasticity group.
//
// The recorded clip is played, not its scene run live: the simulation of the ball part is not
// real time on a small machine, and a cloth that moves slower than it should looks softer, which
// is the very thing the participant is judging. A recording is shown at its true speed and is the
// same pixels for every participant.
#include <filesystem>
#include <memory>
#include <optional>

#include "study/fabric_guess.h"

namespace weft::app {

struct ClipToShow {
  std::filesystem::path file;
  int width = 0, height = 0;  // px of the video's frames
  double fps = 30.0;
  int index = 0, count = 0;   // "clip index + 1 of count"
};

class GuessWindow {
 public:
  // Opens the window. Throws ui::WindowUnavailable (no display).
  GuessWindow();
  ~GuessWindow();
  GuessWindow(const GuessWindow&) = delete;
  GuessWindow& operator=(const GuessWindow&) = delete;

  // Plays the clip once and returns the answer; nothing when the participant closed the window.
  std::optional<study::FabricGuess> ask(const ClipToShow& clip);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace weft::app
