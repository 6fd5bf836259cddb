#pragma once
// The live viewer behind `weft edit`: a window showing a LiveSimulation as it runs, with the orbit
// camera on the mouse. One loop: poll input, apply keys, advance, draw, swap. The editor's
// panels will be drawn in the same loop, after the scene.
//
// Keys: Space pauses and resumes, N steps once while paused, R reloads the scene file, Esc (or
// closing the window) quits. The title shows the scene, the simulated time and the state.
#include <filesystem>
#include <optional>

#include "live_simulation.h"

namespace weft::app {

struct LiveViewerOptions {
  std::optional<int> frames;         // quit after this many displayed frames (tests, scripts)
  std::filesystem::path screenshot;  // when set: the last displayed frame as PNG, written on quit
};

// Opens the window and runs until the user quits. Throws ui::WindowUnavailable, before anything
// is shown, when no window can open. Returns an ExitCode: kExitNonFinite when the simulation is
// stopped on a non-finite state at the end, kExitFailure when the screenshot cannot be written.
int runLiveViewer(ui::LiveSimulation& simulation, const LiveViewerOptions& options);

}  // namespace weft::app
