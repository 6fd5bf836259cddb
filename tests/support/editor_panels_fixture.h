#pragma once
// The editor's whole UI driven headless, for the panel tests: an EGL context shared by the suite,
// an ImGui context per test, a small copy of a preset scene open in a session, and a probe that
// records where each widget was drawn. Skipped (with the reason) where EGL cannot start.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "editor/editor_session.h"
#include "editor/editor_ui.h"
#include "headless_gl_context.h"
#include "support/imgui_harness.h"
#include "support/temp_dir.h"

namespace weft::test {

namespace fs = std::filesystem;
using editor::EditorSession;
using editor::EditorUi;
using editor::WidgetProbe;
using nlohmann::json;

constexpr int kWidth = 1440;
constexpr int kHeight = 900;

inline fs::path copyScene(const test::TempDir& dir, const std::string& preset, int resolution) {
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / (preset + ".json"));
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({resolution, resolution});
  return dir.write("scenes/" + preset + ".json", scene.dump(2));
}

class EditorPanelsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    setenv("LP_NATIVE_VECTOR_WIDTH", "128", 1);
    try {
      context_ = std::make_unique<ui::HeadlessGlContext>();
    } catch (const ui::GlContextError& e) {
      skipReason_ = std::string("headless OpenGL (EGL surfaceless) cannot start here: ") + e.what();
    }
  }
  static void TearDownTestSuite() { context_.reset(); }

  void SetUp() override {
    if (!context_) GTEST_SKIP() << skipReason_;
    scene_ = copyScene(dir_, "ball-into-sheet-table4.1-cloth2", 8);
    session_ = std::make_unique<EditorSession>(scene_);
    session_->paused = true;
    imgui_ = std::make_unique<test::HeadlessImGui>(kWidth, kHeight);
    ui_.panels.probe = &probe_;
    imgui_->frame(drawUi());  // lays the panels out and records where each widget is
  }
  void TearDown() override { imgui_.reset(); }

  std::function<void()> drawUi() {
    return [this] { drawEditorUi(*session_, ui_); };
  }

  // Clicks a widget where it is now: one frame first, so that an edit made since the last frame
  // (a longer status, an "(unsaved)" that wraps a line) has moved it in the probe too.
  void clickWidget(const std::string& name, const std::function<void()>& draw) {
    imgui_->frame(draw);
    ASSERT_TRUE(probe_.rects.count(name)) << name << " is not drawn";
    imgui_->click(probe_.centre(name), draw);
  }

  static inline std::unique_ptr<ui::HeadlessGlContext> context_;
  static inline std::string skipReason_;
  test::TempDir dir_;
  fs::path scene_;
  std::unique_ptr<EditorSession> session_;
  std::unique_ptr<test::HeadlessImGui> imgui_;
  EditorUi ui_;
  WidgetProbe probe_;
};

}  // namespace weft::test
