// The tear table's polar plot tells the truth: drawn headless, its dip lies along the lines the
// simulation tears for that table (the tear log's direction in material space), not mirrored.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "editor/scene_edits.h"
#include "support/editor_panels_fixture.h"
#include "tearing/tear_candidates.h"
#include "tearing/tear_stage.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::EditorPanelsTest;
constexpr double kPi = 3.14159265358979323846;

double axialDifferenceDeg(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 180.0);
  return std::min(d, 180.0 - d);
}

// The direction (degrees, screen up = material y) of the curve's point nearest the plot's centre
// (the red curve, or the pixels `isCurve` accepts): where the required strength dips; -1 when
// no pixel of the curve is drawn.
bool isCurveRed(const std::uint8_t* p) { return p[0] > 150 && p[1] < 110 && p[2] < 110; }

template <typename IsCurve = decltype(&isCurveRed)>
double dipDirectionDeg(const test::RgbaImage& image, const ImVec4& plot, IsCurve isCurve = &isCurveRed) {
  const double cx = 0.5 * (plot.x + plot.z), cy = 0.5 * (plot.y + plot.w);
  double nearest = std::numeric_limits<double>::max(), direction = -1.0;
  // Only the part of the plot inside the image (a panel may scroll it off).
  for (int y = std::max(0, static_cast<int>(plot.y)); y < std::min(image.height, static_cast<int>(plot.w)); ++y) {
    for (int x = std::max(0, static_cast<int>(plot.x)); x < std::min(image.width, static_cast<int>(plot.z)); ++x) {
      const std::uint8_t* p = &image.pixels[4 * (static_cast<std::size_t>(y) * image.width + x)];
      if (!isCurve(p)) continue;  // the curve's colour
      const double dx = x + 0.5 - cx, dy = cy - (y + 0.5);
      const double r = std::hypot(dx, dy);
      if (r < nearest) {
        nearest = r;
        direction = std::atan2(dy, dx) * 180.0 / kPi;
      }
    }
  }
  if (nearest == std::numeric_limits<double>::max()) return -1.0;  // no curve
  return direction < 0.0 ? direction + 180.0 : direction;
}

// The denim sheet pulled apart sideways, with a table weak only at alpha = 45 degrees: it tears
// along that direction, which the plot must show.
TEST_F(EditorPanelsTest, ThePolarPlotsDipLiesAlongTheLinesTheSimulationTears) {
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sheet-pulled-apart.json");
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({12, 12});
  scene["cloths"][0]["tear_table"] = {{"directions_deg", {0, 45, 90, 135}},
                                       {"strength", {30.0, 6.0, 30.0, 30.0}},
                                       {"unit_n_per_m", 30.0}};
  session_ = std::make_unique<EditorSession>(dir_.write("scenes/weak-at-45.json", scene.dump(2)));
  World& world = session_->world();
  for (int s = 0; s < 2000 && world.tearLog().empty(); ++s) world.step();
  ASSERT_FALSE(world.tearLog().empty()) << "the sheet never tore";
  const TearRecord& tear = world.tearLog().front();
  EXPECT_NEAR(tear.alphaDeg, 45.0, 10.0) << "it tears where the table is weak";

  for (int i = 0; i < 3; ++i) imgui_->frame(drawUi());
  const double dip = dipDirectionDeg(imgui_->image(), probe_.rects.at("tear/plot"));
  ASSERT_GE(dip, 0.0) << "no curve drawn";
  EXPECT_LT(axialDifferenceDeg(dip, tear.angleDeg), 6.0)
      << "plot dips along " << dip << " deg, the simulation tore along " << tear.angleDeg << " deg";
}

// The same with the weft turned: the plot and the tearing stage turn together.
TEST_F(EditorPanelsTest, ThePolarPlotTurnsWithTheWeftAsTheCoreDoes) {
  const double weftDeg = 20.0;
  ASSERT_TRUE(session_->edit(withWeftAngle(session_->json(), 0, weftDeg), "weft angle").accepted);
  ASSERT_TRUE(session_->edit(withTearDirections(session_->json(), session_->scene(), 0, 4), "four").accepted);
  json next = session_->json();
  next["cloths"][0]["tear_table"]["strength"] = {30.0, 6.0, 30.0, 30.0};  // weak at alpha = 45 only
  ASSERT_TRUE(session_->edit(next, "weak at 45").accepted) << session_->status;
  for (int i = 0; i < 3; ++i) imgui_->frame(drawUi());
  const double dip = dipDirectionDeg(imgui_->image(), probe_.rects.at("tear/plot"));
  // The line whose alpha is 45 degrees, found by the core's own convention.
  double expected = -1.0;
  for (int d = 0; d < 1800 && expected < 0.0; ++d) {
    if (std::abs(angleFromWarpDeg(d * 0.1 * kPi / 180.0, weftDeg * kPi / 180.0) - 45.0) < 0.05) expected = d * 0.1;
  }
  ASSERT_GE(expected, 0.0);
  EXPECT_LT(axialDifferenceDeg(dip, expected), 4.0) << "plot dips along " << dip << " deg, core: " << expected;
}

// A cloth's tear region's table is drawn in orange on the cloth's plot: bias-panel-sheet's region
// is weakest at alpha = 45 degrees and its curve dips along that line, while the cloth's own (red,
// on the grain) dips along the warp.
TEST_F(EditorPanelsTest, ATearRegionsTableIsPlottedWithTheClothsOwn) {
  session_ = std::make_unique<EditorSession>(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "bias-panel-sheet.json");
  for (int i = 0; i < 3; ++i) imgui_->frame(drawUi());
  const ImVec4 plot = probe_.rects.at("tear/plot");
  double expected = -1.0;  // the line at alpha = 45 with the weft at 0, by the core's convention
  for (int d = 0; d < 1800 && expected < 0.0; ++d) {
    if (std::abs(angleFromWarpDeg(d * 0.1 * kPi / 180.0, 0.0) - 45.0) < 0.05) expected = d * 0.1;
  }
  const auto orange = [](const std::uint8_t* p) { return p[0] > 200 && p[1] > 110 && p[1] < 170 && p[2] < 60; };
  const double regionDip = dipDirectionDeg(imgui_->image(), plot, orange);
  ASSERT_GE(regionDip, 0.0) << "no orange curve drawn";
  EXPECT_LT(axialDifferenceDeg(regionDip, expected), 6.0) << "orange dips along " << regionDip << " deg, core: " << expected;
  EXPECT_LT(axialDifferenceDeg(dipDirectionDeg(imgui_->image(), plot), 90.0), 6.0) << "the own table dips along the warp";
  // Without a region, no orange.
  session_ = std::make_unique<EditorSession>(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "perforated-sheet.json");
  for (int i = 0; i < 3; ++i) imgui_->frame(drawUi());
  EXPECT_LT(dipDirectionDeg(imgui_->image(), probe_.rects.at("tear/plot"), orange), 0.0);
}

}  // namespace
}  // namespace weft::editor
