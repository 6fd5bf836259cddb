#pragma once
// The headless run behind `weft run`, for the other commands that need one: `weft edit` falls back
// to it when no window can open.
#include <optional>
#include <string>
#include <vector>

namespace weft::app {

struct RunOptions {
  std::string scene;                    // scene file (JSON)
  std::optional<int> frames;            // frames to simulate; default: the scene's output.frames
  std::optional<int> threads;           // worker threads; default: the scene's solver.threads
  std::string out;                      // output folder; default: out/<scene name>
  bool obj = false;                     // write frames/frame_NNNN.obj
  bool png = false;                     // render frames/frame_NNNN.png headless (EGL)
  bool video = false;                   // implies png; frames.mp4 when ffmpeg is installed
  int every = 1;                        // render every N-th frame
  std::string size = "960x720";         // PNG size, WxH pixels
  bool quiet = false;                   // print nothing but errors
  bool keepGoing = false;               // an unhealthy run (sim/health_check.h) warns and continues
  std::vector<std::string> overrides;   // --set PATH=VALUE, in order
};

// Simulates, writes metrics.json and the frames asked for, and prints where. Returns an ExitCode.
int runScene(const RunOptions& options);

}  // namespace weft::app
