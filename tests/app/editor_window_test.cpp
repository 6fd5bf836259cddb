// The editor's real window driven as a user would: `weft edit` on a virtual X display (Xvfb),
// real mouse and keyboard events from xdotool. Where a headless panel test cannot show it: a
// crash (kill -9) and the next start, for a scene's edits and for a tool's sharp tags. Skipped when Xvfb, xdotool or headless EGL are missing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <vector>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "editor/autosave.h"
#include "editor/editor_viewport.h"
#include "editor/scene_browser.h"
#include "editor/thumbnail_cache.h"
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

// The root window of an X display as RGB rows, from `xwd` (x11-apps): its ZPixmap dump of
// Xvfb's 24-bit screen, 32 bits a pixel. Empty when xwd failed.
struct Screen {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  bool sameRegion(const Screen& o, int x0, int y0, int x1, int y1) const {
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
        if (rgb[i] != o.rgb[i] || rgb[i + 1] != o.rgb[i + 1] || rgb[i + 2] != o.rgb[i + 2]) return false;
      }
    }
    return true;
  }
};

Screen readXwd(const fs::path& file) {
  const std::string data = readText(file);
  Screen screen;
  if (data.size() < 100) return screen;
  const auto word = [&](std::size_t i) {
    const auto* b = reinterpret_cast<const unsigned char*>(data.data()) + 4 * i;
    return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) | b[3];
  };
  const std::uint32_t headerSize = word(0), width = word(4), height = word(5), byteOrder = word(7), bitsPerPixel = word(11),
                      bytesPerLine = word(12), colours = word(19);
  const std::size_t start = headerSize + 12u * colours;
  if (bitsPerPixel != 32 || data.size() < start + std::size_t{bytesPerLine} * height) return screen;
  screen.width = static_cast<int>(width);
  screen.height = static_cast<int>(height);
  screen.rgb.resize(3u * width * height);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const auto* p = reinterpret_cast<const unsigned char*>(data.data()) + start + std::size_t{y} * bytesPerLine + 4u * x;
      const std::size_t o = 3u * (std::size_t{y} * width + x);
      screen.rgb[o] = byteOrder == 0 ? p[2] : p[1];  // LSBFirst: B G R x
      screen.rgb[o + 1] = byteOrder == 0 ? p[1] : p[2];
      screen.rgb[o + 2] = byteOrder == 0 ? p[0] : p[3];
    }
  }
  return screen;
}

// An Xvfb display of its own (1440x900, the editor's window size), stopped at the end.
class VirtualDisplay {
 public:
  explicit VirtualDisplay(const fs::path& folder) : pidFile_(folder / "xvfb.pid") {
    std::random_device seed;
    number_ = 300 + static_cast<int>(seed() % 400);
    run("Xvfb :" + std::to_string(number_) + " -screen 0 1440x900x24 -nolisten tcp >/dev/null 2>&1 & echo $! > '" +
        pidFile_.string() + "'");
    const fs::path socket = "/tmp/.X11-unix/X" + std::to_string(number_);
    for (int i = 0; i < 600 && !fs::exists(socket); ++i) std::this_thread::sleep_for(50ms);
    ready_ = fs::exists(socket);
  }
  ~VirtualDisplay() { run("kill " + readText(pidFile_) + " 2>/dev/null"); }
  bool ready() const { return ready_; }
  std::string env() const { return "DISPLAY=:" + std::to_string(number_) + " "; }
  // The screen as it is now (xwd); empty when xwd is missing or failed.
  Screen screenshot(const fs::path& file) const {
    if (run(env() + "xwd -root -silent > '" + file.string() + "' 2>/dev/null") != 0) return {};
    return readXwd(file);
  }
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
  // Lays out `scene` instead and picks its first tool in the Tools panel's combo, as a user would,
  // so the combo's items and the tool's buttons are located too. False when no tool was picked.
  bool pickFirstToolOf(const fs::path& scene) {
    session_ = std::make_unique<weft::editor::EditorSession>(scene);
    session_->paused = true;
    imgui_->frame(drawUi());
    imgui_->click(probe_.centre("tools/tool"), drawUi());
    imgui_->frame(drawUi());
    if (!probe_.rects.count("tools/tool0")) return false;
    imgui_->click(probe_.centre("tools/tool0"), drawUi());
    imgui_->frame(drawUi());
    return ui_.panels.tools.current() != nullptr && probe_.rects.count("tools/sharperthan") > 0;
  }
  // The Scene panel's Browse button, drawn only where a browser exists (the window has one).
  ImVec2 browseButton(const fs::path& thumbnails) {
    weft::editor::SceneBrowser browser({fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes"},
                                       weft::editor::ThumbnailCache(thumbnails));
    ui_.panels.browser = &browser;
    imgui_->frame(drawUi());
    imgui_->frame(drawUi());
    ui_.panels.browser = nullptr;
    return probe_.rects.count("scene/browse") ? probe_.centre("scene/browse") : ImVec2(-1, -1);
  }
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
  // Waits until `log` (weft's output) holds `text` past its first `from` characters; false after
  // `seconds`. The waits are generous: a loaded machine draws a frame in seconds, not ms.
  static bool waitForOutput(const fs::path& log, const std::string& text, int seconds, std::size_t from = 0) {
    for (int i = 0; i < 10 * seconds; ++i) {
      const std::string out = readText(log);
      if (out.size() > from && out.find(text, from) != std::string::npos) return true;
      std::this_thread::sleep_for(100ms);
    }
    return false;
  }
  // The same for a pattern: its first match's first group past `from`; none after `seconds`.
  static std::optional<std::string> waitForMatch(const fs::path& log, const std::regex& pattern, int seconds,
                                                 std::size_t from = 0) {
    for (int i = 0; i < 10 * seconds; ++i) {
      const std::string out = readText(log);
      std::smatch match;
      if (out.size() > from && std::regex_search(out.cbegin() + static_cast<std::ptrdiff_t>(from), out.cend(), match, pattern)) {
        return match[1].str();
      }
      std::this_thread::sleep_for(100ms);
    }
    return std::nullopt;
  }
  static std::size_t outputSize(const fs::path& log) { return readText(log).size(); }
  // A key tapped in the editor's window (run with --print-changes), then waits until the editor
  // says it shows `shows` ("step 1 (frame 1, live)"): the frame it was drawn in has been swapped.
  // False after `seconds`.
  bool keyAndWaitFor(const std::string& key, const fs::path& log, const std::string& shows, int seconds = 120) const {
    const std::size_t from = outputSize(log);
    display_->xdotool("key " + key);
    return waitForOutput(log, "weft edit: shows " + shows + "\n", seconds, from);
  }
  // The screen once the scene's part of it stops changing: the frame the editor said it drew may
  // still be on its way to the X server; two screenshots in a row that agree are what is shown.
  Screen settledScreenshot(const fs::path& file, int seconds = 60) const {
    Screen last = display_->screenshot(file);
    for (int i = 0; i < 10 * seconds && last.width > 0; ++i) {
      std::this_thread::sleep_for(100ms);
      Screen next = display_->screenshot(file);
      if (next.width != last.width) return {};
      const weft::editor::ViewportRect r = weft::editor::sceneViewport(next.width, next.height);
      if (next.sameRegion(last, r.x, r.y, r.x + r.width, r.y + r.height)) return next;
      last = std::move(next);
    }
    return {};
  }
  // Waits until the process in the pid file is gone or a zombie (killed, not yet reaped by
  // whoever adopted it); false after `seconds`.
  bool waitForExit(int seconds) const {
    const std::string pid = std::to_string(std::stoll(readText(pidFile())));
    for (int i = 0; i < 10 * seconds; ++i) {
      const std::string stat = readText("/proc/" + pid + "/stat");  // "PID (NAME) STATE ..."
      const std::size_t name = stat.rfind(')');
      if (stat.empty() || name == std::string::npos || stat.compare(name + 1, 2, " Z") == 0) return true;
      std::this_thread::sleep_for(100ms);
    }
    return false;
  }
  // Waits until the editor has drawn its first frames (it prints "weft edit: SCENE (RENDERER)"
  // once its panels have settled): before, the window may exist while the scene is still being
  // built, and a click lands on no widget, as it would for a user. False after `seconds`.
  static bool waitForFirstFrame(const fs::path& log, const fs::path& scene, int seconds) {
    return waitForOutput(log, "weft edit: " + scene.string() + " (", seconds);
  }
  // Waits for the editor's window; false after `seconds`.
  bool waitForWindow(int seconds) const {
    return run(display_->env() + "timeout " + std::to_string(seconds) +
               " xdotool search --sync --onlyvisible --name '^Weft' >/dev/null 2>&1") == 0;
  }
  // A click at window pixel `at`: moved there, pressed and released back to back, as fast as
  // xdotool sends them. The editor's input queue (input_queue.h) hands the press and the release
  // to ImGui in frames of their own, at the position they were made, however slow the frames: no
  // wait between them is needed, and none would be long enough on a loaded machine anyway.
  void pressAt(ImVec2 at) const {
    const std::string xy = std::to_string(static_cast<int>(at.x)) + " " + std::to_string(static_cast<int>(at.y));
    display_->xdotool("search --name '^Weft' mousemove --sync --window %1 " + xy + " mousedown 1 mouseup 1");
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
  ASSERT_TRUE(waitForWindow(60)) << readText(root_ / "first.txt");
  ASSERT_TRUE(waitForFirstFrame(root_ / "first.txt", edited, 120)) << readText(root_ / "first.txt");
  pressAt(ImVec2(dial.x + 40, dial.y - 23));  // the weft to about 30 degrees: one edit
  // The autosave comes within 5 s of the edit (the editor's clock: on a loaded machine the click
  // itself may take many slow frames to arrive, so the wait is far longer).
  const weft::editor::Autosave store(autosaveDir());
  for (int i = 0; i < 1200 && !store.find(edited); ++i) std::this_thread::sleep_for(100ms);
  ASSERT_TRUE(store.find(edited).has_value()) << "no autosave 120 s after the edit: " << readText(root_ / "first.txt");
  EXPECT_GT(store.find(edited)->document["cloths"][0].value("weft_angle_deg", 0.0), 10.0);
  run("kill -9 " + readText(pidFile()));
  ASSERT_TRUE(waitForExit(60)) << "the editor outlived kill -9";

  // Plain `weft` (another scene) offers it, and leaves it in place when it ends without a choice.
  const fs::path other = smallScene("hanging-sheet", "other.json");
  startWeft("edit '" + other.string() + "' --frames 30 --screenshot second.png", root_ / "second.txt");
  for (int i = 0; i < 1800 && !fs::exists(root_ / "second.png"); ++i) std::this_thread::sleep_for(100ms);
  const std::string second = readText(root_ / "second.txt");
  EXPECT_NE(second.find("offering unsaved edits to " + fs::weakly_canonical(edited).string()), std::string::npos)
      << second;
  EXPECT_TRUE(store.find(edited).has_value()) << "the edits are still there";
}

// Sharp tags are the user's work too: tags alone (the scene itself unchanged), on a tool whose
// tags live in a file of their own, are autosaved, and after kill -9 the next start offers them
// back with the scene.
TEST_F(EditorWindow, AfterKillMinus9TheNextStartOffersAToolsUnsavedTagsBack) {
  const fs::path edited = smallScene("sword-into-sheet", "tagged.json");
  fs::create_directories(root_ / "scenes" / "tools");
  fs::copy_file(fs::path(WEFT_SOURCE_DIR) / "assets" / "tools" / "sword.obj", root_ / "scenes" / "tools" / "sword.obj");
  json scene = json::parse(readText(edited));
  scene["obstacles"][0]["shape"]["mesh"]["path"] = "tools/sword.obj";  // its tags file is this test's own
  std::ofstream(edited) << scene.dump(2);
  WidgetLocator locator;
  if (!locator.start()) GTEST_SKIP() << "headless EGL is needed to locate the widgets";
  ASSERT_TRUE(locator.pickFirstToolOf(edited));
  const ImVec2 combo = locator.centre("tools/tool"), sword = locator.centre("tools/tool0"),
               sharperThan = locator.centre("tools/sharperthan");
  locator.finish();

  startWeft("edit '" + edited.string() + "' --print-changes", root_ / "first.txt");
  ASSERT_TRUE(waitForWindow(60)) << readText(root_ / "first.txt");
  ASSERT_TRUE(waitForFirstFrame(root_ / "first.txt", edited, 120)) << readText(root_ / "first.txt");
  // Pick the sword, then tag every edge sharper than 60 degrees: one tag edit, the scene untouched.
  // The combo's list has to be on screen before the press on its item: sent back to back, the
  // pick was lost (seen here), so each press waits a little, and the whole pick is tried again
  // if no tag came of it (on a loaded machine a few seconds may not be a frame).
  bool tagged = false;
  for (int attempt = 0; attempt < 3 && !tagged; ++attempt) {
    const std::size_t from = outputSize(root_ / "first.txt");
    pressAt(combo);
    std::this_thread::sleep_for(3s);
    pressAt(sword);
    std::this_thread::sleep_for(3s);
    pressAt(sharperThan);
    tagged = waitForOutput(root_ / "first.txt", "sharper than 60 deg (save the tags to keep them)", 60, from);
  }
  ASSERT_TRUE(tagged) << readText(root_ / "first.txt");
  const weft::editor::Autosave store(autosaveDir());
  for (int i = 0; i < 1200 && !store.find(edited); ++i) std::this_thread::sleep_for(100ms);
  ASSERT_TRUE(store.find(edited).has_value()) << "no autosave 120 s after the tags: " << readText(root_ / "first.txt");
  ASSERT_EQ(store.find(edited)->toolTags.size(), 1u);
  EXPECT_FALSE(store.find(edited)->toolTags[0].tags["sharp_edges"].empty());
  EXPECT_EQ(store.find(edited)->document, scene) << "only the tags were edited";
  run("kill -9 " + readText(pidFile()));
  ASSERT_TRUE(waitForExit(60)) << "the editor outlived kill -9";
  EXPECT_FALSE(fs::exists(root_ / "scenes" / "tools" / "sword.sharp.json")) << "nothing was saved";

  startWeft("edit '" + edited.string() + "' --frames 30 --screenshot second.png", root_ / "second.txt");
  for (int i = 0; i < 1800 && !fs::exists(root_ / "second.png"); ++i) std::this_thread::sleep_for(100ms);
  const std::string second = readText(root_ / "second.txt");
  EXPECT_NE(second.find("offering unsaved edits to " + fs::weakly_canonical(edited).string() + " and the sharp tags of sword"),
            std::string::npos)
      << second;
  EXPECT_TRUE(store.find(edited).has_value()) << "the tags are still there";
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
  ASSERT_TRUE(waitForWindow(60)) << readText(root_ / "taps.txt");
  // The taps start once the window has drawn (not after a guessed delay: on a loaded machine
  // building the scene and the first frame take longer than any fixed wait).
  ASSERT_TRUE(waitForFirstFrame(root_ / "taps.txt", scene, 120)) << readText(root_ / "taps.txt");
  // Click, type, Enter and Ctrl+S sent back to back, with no pause for the window to catch up:
  // the queue keeps them in order (the click gives the field the keyboard before "20" arrives).
  pressAt(field);
  display_->xdotool("type --delay 120 20");
  display_->xdotool("key Return");
  display_->xdotool("key ctrl+s");
  // The events are queued and reach ImGui one frame after another, in order, however slow the
  // frames: they all arrive, in as many frames as it takes (about ten here; on a machine loaded
  // enough that llvmpipe draws a frame in seconds, that is a minute or more: up to three).
  double saved = 0.0;
  for (int i = 0; i < 1800 && saved != 20.0; ++i) {
    std::this_thread::sleep_for(100ms);
    const json j = json::parse(readText(scene), nullptr, false);
    if (!j.is_discarded() && j["cloths"][0].contains("tear_table") && j["cloths"][0]["tear_table"].is_object())
      saved = j["cloths"][0]["tear_table"]["strength"][2].get<double>();
  }
  if (saved != 20.0) {  // what the window showed, kept for whoever reads the failure
    const fs::path kept = fs::temp_directory_path() / "weft_window_test_failures";
    fs::create_directories(kept);
    const Screen shot = display_->screenshot(root_ / "taps.xwd");
    weft::test::RgbaImage image{shot.width, shot.height, {}};
    for (std::size_t i = 0; i < shot.rgb.size(); i += 3) {
      image.pixels.insert(image.pixels.end(), {shot.rgb[i], shot.rgb[i + 1], shot.rgb[i + 2], 255});
    }
    if (!image.empty()) weft::test::writePng(kept / "taps.png", image);
    fs::copy_file(scene, kept / "taps.json", fs::copy_options::overwrite_existing);
  }
  EXPECT_EQ(saved, 20.0) << readText(root_ / "taps.txt") << "(the window and the file as they were: "
                         << (fs::temp_directory_path() / "weft_window_test_failures").string() << ")";
}

// Esc closes what is open before it quits: the scene and preset browser is a window of its own,
// not a popup, and Esc used to quit the editor with it open.
TEST_F(EditorWindow, EscClosesTheBrowserBeforeItQuits) {
  const fs::path scene = smallScene("ball-into-sheet-table4.1-cloth2", "browse.json");
  WidgetLocator locator;
  if (!locator.start()) GTEST_SKIP() << "headless EGL is needed to locate the widgets";
  const ImVec2 browse = locator.browseButton(root_ / "thumbnails");
  ASSERT_GE(browse.x, 0.0f) << "the Browse button was not laid out";
  locator.finish();
  const fs::path log = root_ / "browse.txt";
  startWeft("edit '" + scene.string() + "' --print-changes", log);
  ASSERT_TRUE(waitForWindow(60)) << readText(log);
  ASSERT_TRUE(waitForFirstFrame(log, scene, 120)) << readText(log);
  pressAt(browse);
  ASSERT_TRUE(waitForOutput(log, "weft edit: browser open\n", 120)) << readText(log);
  const std::size_t opened = outputSize(log);
  display_->xdotool("key Escape");
  ASSERT_TRUE(waitForOutput(log, "weft edit: browser closed\n", 120, opened)) << readText(log);
  EXPECT_FALSE(waitForExit(2)) << "Esc quit with the browser open\n" << readText(log);
  display_->xdotool("key Escape");  // nothing open, nothing unsaved: now it quits
  EXPECT_TRUE(waitForExit(120)) << readText(log);
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

// The timeline in the real window: N steps one frame at a time (one step a frame here), Left
// goes back through the cached frames; the viewport then shows exactly the pixels it showed when
// that frame was simulated, and not those of the frame the simulation is at.
TEST_F(EditorWindow, ScrubbingBackShowsTheSamePixelsAsWhenTheFrameWasSimulated) {
  if (!onPath("xwd")) GTEST_SKIP() << "needs xwd (x11-apps, scripts/install_deps.sh)";
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "hanging-sheet.json");
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
  scene["output"]["fps"] = 60;  // dt 1/60 s: a step is a frame
  const fs::path file = root_ / "scenes" / "scrub.json";
  std::ofstream(file) << scene.dump(2);

  const fs::path log = root_ / "scrub.txt";
  startWeft("edit '" + file.string() + "' --print-changes", log);
  ASSERT_TRUE(waitForWindow(60)) << readText(log);
  ASSERT_TRUE(waitForFirstFrame(log, file, 120)) << readText(log);
  display_->xdotool("search --name '^Weft' mousemove --sync --window %1 700 450");  // over the scene, not a panel
  // Each key's effect is waited for as the editor reports it drawn (--print-changes), then the
  // screen is read once it has settled: no guessed delays, which a loaded machine outlasts.
  ASSERT_TRUE(keyAndWaitFor("n", log, "step 1 (frame 1, live)")) << readText(log);
  const Screen simulated = settledScreenshot(root_ / "frame1.xwd");
  ASSERT_GT(simulated.width, 0) << "xwd gave no image, or the screen never settled";
  ASSERT_TRUE(keyAndWaitFor("n", log, "step 2 (frame 2, live)")) << readText(log);
  ASSERT_TRUE(keyAndWaitFor("n", log, "step 3 (frame 3, live)")) << readText(log);
  const Screen later = settledScreenshot(root_ / "frame3.xwd");
  ASSERT_TRUE(keyAndWaitFor("Left", log, "step 2 (frame 2, cached)")) << readText(log);
  ASSERT_TRUE(keyAndWaitFor("Left", log, "step 1 (frame 1, cached)")) << readText(log);
  const Screen scrubbed = settledScreenshot(root_ / "scrubbed.xwd");
  ASSERT_EQ(scrubbed.width, simulated.width);
  const weft::editor::ViewportRect scene3d = weft::editor::sceneViewport(simulated.width, simulated.height);
  const int x0 = scene3d.x + 8, y0 = scene3d.y + 40, x1 = scene3d.x + scene3d.width - 8, y1 = scene3d.y + scene3d.height - 8;
  EXPECT_FALSE(later.sameRegion(simulated, x0, y0, x1, y1)) << "the sheet fell between frames 1 and 3";
  EXPECT_TRUE(scrubbed.sameRegion(simulated, x0, y0, x1, y1)) << "frame 1 scrubbed back to is not frame 1 as simulated";
}

// The timeline in the real window (item 7): four steps (a step is a frame here), Left twice back
// to frame 2, then an edit there (the weft dial): the frames after 2 are dropped and the world
// goes on from frame 2 (the headless Timeline tests show it is frame 2's own state, copied, not
// simulated again). The editor, paused after the edit, shows the live world at step 2, not 4.
TEST_F(EditorWindow, AnEditOnAnEarlierFrameContinuesFromThatFrame) {
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "ball-into-sheet-table4.1-cloth2.json");
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
  scene["output"]["fps"] = 240;  // dt 1/240 s: a step is a frame
  const fs::path file = root_ / "scenes" / "edit-back.json";
  std::ofstream(file) << scene.dump(2);
  WidgetLocator locator;
  if (!locator.start()) GTEST_SKIP() << "headless EGL is needed to locate the widgets";
  const ImVec2 dial = locator.centre("weft/dial");
  locator.finish();

  const fs::path log = root_ / "back.txt";
  startWeft("edit '" + file.string() + "' --print-changes", log);
  ASSERT_TRUE(waitForWindow(60)) << readText(log);
  ASSERT_TRUE(waitForFirstFrame(log, file, 120)) << readText(log);
  display_->xdotool("search --name '^Weft' mousemove --sync --window %1 700 450");  // over the scene, not a panel
  for (int step = 1; step <= 4; ++step) {
    const std::string frame = std::to_string(step);
    ASSERT_TRUE(keyAndWaitFor("n", log, "step " + frame + " (frame " + frame + ", live)")) << readText(log);
  }
  ASSERT_TRUE(keyAndWaitFor("Left", log, "step 3 (frame 3, cached)")) << readText(log);
  ASSERT_TRUE(keyAndWaitFor("Left", log, "step 2 (frame 2, cached)")) << readText(log);
  const std::size_t beforeEdit = outputSize(log);
  pressAt(ImVec2(dial.x + 40, dial.y - 23));  // the weft to about 30 degrees: an edit on frame 2
  ASSERT_TRUE(waitForOutput(log, "weft edit: status: weft angle", 120, beforeEdit)) << readText(log);
  // End shows the live world: without the edit going back it would be the world at step 4.
  display_->xdotool("search --name '^Weft' mousemove --sync --window %1 700 450");
  display_->xdotool("key End");
  const std::optional<std::string> live =
      waitForMatch(log, std::regex(R"(weft edit: shows step (\d+) \(frame \d+, live\))"), 120, beforeEdit);
  ASSERT_TRUE(live.has_value()) << readText(log);
  EXPECT_EQ(std::stoll(*live), 2) << "back at frame 2 and on from there: " << readText(log);
}

}  // namespace
