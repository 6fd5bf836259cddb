#pragma once
// The editor behind `weft edit` and `weft`: a window showing the scene as it simulates, with the
// panels of ui/editor around it. One loop: poll input, panels, playback, draw the scene, draw the
// panels, swap; an autosave every few seconds while there are unsaved edits.
//
// Mouse (outside the panels): left drag orbits, right or middle drag pans, the wheel zooms. Keys
// (outside text fields): Space play/pause, N step, R reset (the camera stays), F frame the selected
// obstacle or else the scene, Ctrl+Z undo (scene edits and sharp tags in one history), Ctrl+Y or
// Ctrl+Shift+Z redo, Ctrl+S save, Esc closes an open popup, else quits (asking first when there
// are unsaved edits). Scenes open paused at t = 0.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "editor/autosave.h"

namespace weft::app {

struct EditorOptions {
  std::filesystem::path scene;
  std::vector<std::string> overrides;  // --set: applied as the first (undoable, unsaved) edit
  std::optional<int> frames;           // quit after this many displayed frames (tests, scripts)
  std::filesystem::path screenshot;    // when set: the last displayed frame as PNG, written on quit
  bool play = false;                   // start playing (scenes open paused at t = 0 otherwise)
  // After each swap that put a new state on screen, print what it shows: "weft edit: shows step S
  // (frame F, live|cached)" and "weft edit: status: MESSAGE". Scripts and the window tests wait on
  // these lines instead of guessing how long a step or a frame takes.
  bool printChanges = false;
  std::filesystem::path autosaveDir = editor::Autosave::defaultDirectory();
};

// Opens the window and runs until the user quits. Throws ui::WindowUnavailable, before anything
// is shown, when no window can open; InputError for a bad scene. Returns an ExitCode.
int runEditor(const EditorOptions& options);

}  // namespace weft::app
