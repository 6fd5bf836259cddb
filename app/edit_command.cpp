// `weft edit [SCENE]` (and `weft` alone): the editor, the scene live in a window with its panels
// (editor_app.cpp). Where no
// window can open (no display, or GLFW fails) it says why and runs the same scene headless
// instead, with PNG frames in out/<scene name>/frames, so it always shows the user something.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_checks.h"
#include "command.h"
#include "default_scene.h"
#include "glfw_window.h"
#include "editor_app.h"
#include "scene/scene_json.h"
#include "scene/scene_limits.h"
#include "run_command.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;

struct EditOptions {
  std::string scene;                   // default: defaultEditorScenePath()
  std::vector<std::string> overrides;  // --set PATH=VALUE, kept for R (reload)
  std::optional<int> frames;           // window: displayed frames; headless: simulated frames
  fs::path screenshot;                 // the last frame as PNG
  bool play = false;                   // start playing instead of paused at t = 0
  bool printChanges = false;           // window: a line for every change of what is shown
};

// The highest-numbered frame_NNNN.png of a headless run, or empty when there is none.
fs::path lastPngFrame(const fs::path& framesDir) {
  fs::path last;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(framesDir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("frame_", 0) == 0 && entry.path().extension() == ".png") last = std::max(last, entry.path());
  }
  return last;
}

int runHeadlessInstead(const EditOptions& options, const fs::path& sceneFile, const std::string& sceneName) {
  RunOptions run;
  run.scene = sceneFile.string();
  run.overrides = options.overrides;
  run.frames = options.frames;
  run.png = true;
  const int code = runScene(run);
  if (code == kExitOk && !options.screenshot.empty()) {
    // The headless run names its frames itself; the screenshot is a copy of the last one.
    const fs::path last = lastPngFrame(fs::path("out") / sceneName / "frames");
    std::error_code ec;
    if (last.empty() || !fs::copy_file(last, options.screenshot, fs::copy_options::overwrite_existing, ec)) {
      std::cerr << "weft edit: --screenshot: cannot copy the last frame to " << options.screenshot.string() << "\n";
      return kExitFailure;
    }
    std::cout << "wrote " << options.screenshot.string() << " (a copy of " << last.string() << ")\n";
  }
  return code;
}

int edit(const EditOptions& options) {
  const fs::path sceneFile = options.scene.empty() ? defaultEditorScenePath() : fs::path(options.scene);
  // A bad scene is reported as such, before any window opens or any fallback runs.
  std::string sceneName;
  try {
    sceneName = loadScene(sceneFile, options.overrides).name;
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }

  try {
    EditorOptions editor;
    editor.scene = fs::absolute(sceneFile);
    editor.overrides = options.overrides;
    editor.frames = options.frames;
    editor.screenshot = options.screenshot;
    editor.play = options.play;
    editor.printChanges = options.printChanges;
    return runEditor(editor);
  } catch (const ui::WindowUnavailable& e) {
    std::cerr << "weft edit: cannot open a window (" << e.what() << "); running headless instead\n";
    return runHeadlessInstead(options, sceneFile, sceneName);
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }
}

}  // namespace

int editDefaultScene() { return edit(EditOptions{}); }

Command addEditCommand(CLI::App& app) {
  struct Parsed {
    EditOptions options;
    int frames = 0;
    std::string screenshot;
    CLI::Option* framesOption = nullptr;
  };
  auto parsed = std::make_shared<Parsed>();
  CLI::App* cli = app.add_subcommand(
      "edit", "Edit a scene and watch it simulate live (headless PNG frames when no window can open)");
  cli->add_option("scene", parsed->options.scene, "Scene file (default: presets/scenes/ball-into-sheet-table4.1-cloth2.json, a ball tearing denim)");
  cli->add_option("--set", parsed->options.overrides,
                  "Override a scene value, e.g. --set solver.dt=0.005 (repeatable; an undoable, unsaved edit)")
      ->type_name("PATH=VALUE")
      ->allow_extra_args(false);
  parsed->framesOption = cli->add_option("--frames", parsed->frames,
                                         "Quit after N displayed frames (headless fallback: simulate N frames)")
                             ->check(integerIn(1, limits::kMaxFrames));
  cli->add_option("--screenshot", parsed->screenshot, "Write the last displayed frame to FILE as PNG")
      ->type_name("FILE");
  cli->add_flag("--play", parsed->options.play, "Start playing (scenes open paused at t = 0)");
  cli->add_flag("--print-changes", parsed->options.printChanges,
                "Print a line once a frame showing another step or status message is on screen (for scripts and tests)");
  return {cli, [parsed] {
            EditOptions given = parsed->options;
            if (parsed->framesOption->count() > 0) given.frames = parsed->frames;
            given.screenshot = parsed->screenshot;
            return edit(given);
          }};
}

}  // namespace weft::app
