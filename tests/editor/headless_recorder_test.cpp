// Playback's "record": the edited scene runs headless in a child `weft run --png`, the live view
// untouched, and the hidden copy it reads is removed afterwards.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "editor/headless_recorder.h"
#include "support/temp_dir.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;

TEST(HeadlessRecorder, RecordsTheEditedSceneNotTheFileOnDisk) {
  test::TempDir dir;
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets/scenes/hanging-sheet.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = nlohmann::json::array({6, 6});
  const fs::path file = dir.write("scenes/sheet.json", scene.dump());
  // The edit not saved yet: a different weft angle only the document has.
  scene["cloths"][0]["weft_angle_deg"] = 30;
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  HeadlessRecorder recorder{fs::path(WEFT_BINARY)};
  ASSERT_TRUE(recorder.start(scene, file, dir.path() / "out", 3, false));
  EXPECT_FALSE(recorder.start(scene, file, dir.path() / "out2", 3, false)) << "one recording at a time";
  recorder.wait();
  EXPECT_FALSE(recorder.running());
  const std::string message = recorder.lastMessage();
  if (message.find("EGL") != std::string::npos) GTEST_SKIP() << "headless OpenGL cannot start here: " << message;
  EXPECT_NE(message.find("recorded"), std::string::npos) << message;
  EXPECT_TRUE(fs::is_regular_file(dir.path() / "out/frames/frame_0003.png")) << message;
  std::ifstream metrics(dir.path() / "out/metrics.json");
  ASSERT_TRUE(metrics);
  EXPECT_FALSE(fs::exists(dir.path() / "scenes/.sheet.recording.json")) << "the hidden copy is removed";
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(file))["cloths"][0].value("weft_angle_deg", 0.0), 0.0)
      << "the scene file is untouched";
}

}  // namespace
}  // namespace weft::editor
