#pragma once
// The editor's session on the hanging sheet, small (8 x 8), hanging in z = 0 and seen from straight
// in front by an 800 x 600 view: the viewport tests' scene (grabbing, tags, the strength brush).
#include <filesystem>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "editor/editor_session.h"
#include "orbit_camera.h"
#include "support/temp_dir.h"

namespace weft::test {

struct FacingSheet {
  static constexpr int kWidth = 800, kHeight = 600;
  TempDir dir;
  std::filesystem::path file;
  std::unique_ptr<editor::EditorSession> session;
  ui::OrbitCamera camera;

  FacingSheet() {
    std::ifstream in(std::filesystem::path(WEFT_SOURCE_DIR) / "presets/scenes/hanging-sheet.json");
    nlohmann::json scene = nlohmann::json::parse(in);
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = nlohmann::json::array({8, 8});
    scene["cloths"][0]["placement"] = nlohmann::json::parse(R"({"translate": [-0.5, 0.5, 0]})");
    file = dir.write("scenes/sheet.json", scene.dump());
    session = std::make_unique<editor::EditorSession>(file);
    camera.target = Vec3(0, 1.0, 0);
    camera.distance = 3.0;
    camera.yawDeg = 0.0;
    camera.pitchDeg = 0.0;
  }
};

}  // namespace weft::test
