// The editor's real window driven as a user would: `weft edit` on a virtual X display (Xvfb),
// real mouse and keyboard events from xdotool. Where a headless panel test cannot show it: a
// crash (kill -9) and the next start. Skipped when Xvfb, xdotool or headless EGL are missing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "editor/autosave.h"
#include "support/editor_panels_fixture.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace std::chrono_literals;

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path != nullptr ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    if (!folder.empty() && ::access((fs::path(folder) / program).c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int run(const std::string& command) { return std::system(command.c_str()); }

// An Xvfb display of its own (1440x900, the editor's window size), stopped at the end.
class VirtualDisplay {
 public:
  explicit VirtualDisplay(const fs::path& folder) : pidFile_(folder / "xvfb.pid") {
    std::random_device seed;
    number_ = 300 + static_cast<int>(seed() % 400);
    run("Xvfb :" + std::to_string(number_) + " -screen 0 1440x900x24 -nolisten tcp >/dev/null 2>&1 & echo $! > '" +
        pidFile_.string() + "'");
    const fs::path socket = "/tmp/.X11-unix/X" + std::to_string(number_);
    for (int i = 0; i < 100 && !fs::exists(socket); ++i) std::this_thread::sleep_for(50ms);
    ready_ = fs::exists(socket);
  }
  ~VirtualDisplay() { run("kill " + readText(pidFile_) + " 2>/dev/null"); }
  bool ready() const { return ready_; }
  std::string env() const { return "DISPLAY=:" + std::to_string(number_) + " "; }
  // xdotool on this display.
  int xdotool(const std::string& arguments) const { return run(env() + "xdotool " + arguments + " >/dev/null 2>&1"); }

 private:
  fs::path pidFile_;
  int number_ = 0;
  bool ready_ = false;
};

// Where a widget of the editor's UI is drawn in a 1440x900 window, found by laying the same UI out
// headless (the window lays it out identically: same fonts, same sizes).
class WidgetLocator : public weft::test::EditorPanelsTest {
 public:
  void TestBody() override {}
  bool start() {
    SetUpTestSuite();
    if (!context_) return false;
    SetUp();
    return true;
  }
  ImVec2 centre(const std::string& id) const { return probe_.centre(id); }
  void finish() {
    TearDown();
    TearDownTestSuite();
  }
};

class EditorWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!onPath("Xvfb") || !onPath("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool (scripts/install_deps.sh)";
    std::random_device seed;
    root_ = fs::temp_directory_path() / ("weft_window_test_" + std::to_string(seed()));
    fs::create_directories(root_ / "scenes");
    display_ = std::make_unique<VirtualDisplay>(root_);
    if (!display_->ready()) GTEST_SKIP() << "Xvfb did not start";
  }
  void TearDown() override {
    if (!pidFile().empty() && fs::exists(pidFile())) run("kill -9 " + readText(pidFile()) + " 2>/dev/null");
    display_.reset();
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }

  fs::path pidFile() const { return root_.empty() ? fs::path() : root_ / "weft.pid"; }
  fs::path autosaveDir() const { return root_ / "autosave"; }
  std::string environment() const {
    return display_->env() + "GALLIUM_DRIVER=llvmpipe LIBGL_ALWAYS_SOFTWARE=1 WEFT_AUTOSAVE_DIR='" +
           autosaveDir().string() + "' WEFT_CONFIG_DIR='" + (root_ / "config").string() + "' ";
  }
  // `weft ARGUMENTS` in the background; its output goes to `log`.
  void startWeft(const std::string& arguments, const fs::path& log) {
    run("cd '" + root_.string() + "' && " + environment() + "'" + WEFT_BINARY + "' " + arguments + " > '" +
        log.string() + "' 2>&1 & echo $! > '" + pidFile().string() + "'");
  }
  // Waits for the editor's window; false after `seconds`.
  bool waitForWindow(int seconds) const {
    return run(display_->env() + "timeout " + std::to_string(seconds) +
               " xdotool search --sync --onlyvisible --name '^Weft' >/dev/null 2>&1") == 0;
  }
  // A press and a release a few frames apart, at window pixel `at`.
  void pressAt(ImVec2 at) const {
    const std::string xy = std::to_string(static_cast<int>(at.x)) + " " + std::to_string(static_cast<int>(at.y));
    display_->xdotool("search --name '^Weft' mousemove --window %1 " + xy);
    std::this_thread::sleep_for(300ms);
    display_->xdotool("mousedown 1");
    std::this_thread::sleep_for(300ms);
    display_->xdotool("mouseup 1");
  }
  fs::path smallScene(const std::string& preset, const std::string& as) const {
    std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / (preset + ".json"));
    json scene = json::parse(in);
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
    const fs::path file = root_ / "scenes" / as;
    std::ofstream(file) << scene.dump(2);
    return file;
  }

  fs::path root_;
  std::unique_ptr<VirtualDisplay> display_;
};

TEST_F(EditorWindow, AfterKillMinus9TheNextStartOffersTheEditsBack) {
  const fs::path edited = smallScene("ball-into-sheet-table4.1-cloth2", "x.json");
  // Where the weft dial is drawn (the same UI, laid out headless on a copy of this scene).
  WidgetLocator locator;
  if (!locator.start()) GTEST_SKIP() << "headless EGL is needed to locate the widgets";
  const ImVec2 dial = locator.centre("weft/dial");
  locator.finish();

  startWeft("edit '" + edited.string() + "'", root_ / "first.txt");
  ASSERT_TRUE(waitForWindow(30)) << readText(root_ / "first.txt");
  pressAt(ImVec2(dial.x + 40, dial.y - 23));  // the weft to about 30 degrees: one edit
  // The autosave comes within 5 s of the edit.
  const weft::editor::Autosave store(autosaveDir());
  for (int i = 0; i < 150 && !store.find(edited); ++i) std::this_thread::sleep_for(100ms);
  ASSERT_TRUE(store.find(edited).has_value()) << "no autosave 15 s after the edit: " << readText(root_ / "first.txt");
  EXPECT_GT(store.find(edited)->document["cloths"][0].value("weft_angle_deg", 0.0), 10.0);
  run("kill -9 " + readText(pidFile()));
  std::this_thread::sleep_for(300ms);

  // Plain `weft` (another scene) offers it, and leaves it in place when it ends without a choice.
  const fs::path other = smallScene("hanging-sheet", "other.json");
  startWeft("edit '" + other.string() + "' --frames 30 --screenshot second.png", root_ / "second.txt");
  for (int i = 0; i < 300 && !fs::exists(root_ / "second.png"); ++i) std::this_thread::sleep_for(100ms);
  const std::string second = readText(root_ / "second.txt");
  EXPECT_NE(second.find("offering unsaved edits to " + fs::weakly_canonical(edited).string()), std::string::npos)
      << second;
  EXPECT_TRUE(store.find(edited).has_value()) << "the edits are still there";
}

// Keys tapped as fast as xdotool sends them (press and release back to back, well inside one
// frame): the typed value's Enter and Ctrl+S both arrive, so the file on disk holds the value.
TEST_F(EditorWindow, KeyTapsShorterThanAFrameAreNotLost) {
  const fs::path scene = smallScene("ball-into-sheet-table4.1-cloth2", "taps.json");
  WidgetLocator locator;
  if (!locator.start()) GTEST_SKIP() << "headless EGL is needed to locate the widgets";
  const ImVec2 field = locator.centre("tear/2");
  locator.finish();

  startWeft("edit '" + scene.string() + "'", root_ / "taps.txt");
  ASSERT_TRUE(waitForWindow(30)) << readText(root_ / "taps.txt");
  pressAt(field);
  std::this_thread::sleep_for(300ms);
  display_->xdotool("type --delay 120 20");
  display_->xdotool("key Return");
  std::this_thread::sleep_for(500ms);
  display_->xdotool("key ctrl+s");
  double saved = 0.0;
  for (int i = 0; i < 100 && saved != 20.0; ++i) {
    std::this_thread::sleep_for(100ms);
    const json j = json::parse(readText(scene), nullptr, false);
    if (!j.is_discarded() && j["cloths"][0].contains("tear_table") && j["cloths"][0]["tear_table"].is_object())
      saved = j["cloths"][0]["tear_table"]["strength"][2].get<double>();
  }
  EXPECT_EQ(saved, 20.0) << readText(root_ / "taps.txt");
}

// A scene whose step takes far longer than a frame, playing: the window still draws at its own
// rate (the steps run on the worker thread), so it shows many frames per step. Stepping on the
// UI thread, every frame waited for at least one step.
TEST_F(EditorWindow, TheWindowDrawsAtItsOwnRateWhileAStepTakesLongerThanAFrame) {
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "hanging-sheet.json");
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({20, 20});
  scene["solver"]["substeps"] = 300;  // a step of 0.2 s and more
  const fs::path file = root_ / "scenes" / "heavy.json";
  std::ofstream(file) << scene.dump(2);

  startWeft("edit '" + file.string() + "' --play --frames 40", root_ / "heavy.txt");
  std::string out;
  for (int i = 0; i < 600 && out.find(" frames in ") == std::string::npos; ++i) {
    std::this_thread::sleep_for(100ms);
    out = readText(root_ / "heavy.txt");
  }
  std::smatch summary;
  ASSERT_TRUE(std::regex_search(out, summary, std::regex(R"(weft edit: (\d+) frames in .*, the scene at step (\d+))")))
      << out;
  const int frames = std::stoi(summary[1]);
  const long long steps = std::stoll(summary[2]);
  EXPECT_EQ(frames, 40) << out;
  EXPECT_GT(steps, 0) << "it played: " << out;
  EXPECT_GT(frames, 2 * steps) << "frames waited for steps: " << out;
}

}  // namespace
