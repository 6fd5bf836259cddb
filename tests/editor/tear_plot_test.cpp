// The tear table's polar plot tells the truth: drawn headless, its dip lies along the lines the
// simulation tears for that table (the tear log's direction in material space), not mirrored.
#include <gtest/gtest.h>

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

// The direction (degrees, screen up = material y) of the red curve's point nearest the plot's
// centre: where the required strength dips.
double dipDirectionDeg(const test::RgbaImage& image, const ImVec4& plot) {
  const double cx = 0.5 * (plot.x + plot.z), cy = 0.5 * (plot.y + plot.w);
  double nearest = std::numeric_limits<double>::max(), direction = -1.0;
  for (int y = static_cast<int>(plot.y); y < static_cast<int>(plot.w); ++y) {
    for (int x = static_cast<int>(plot.x); x < static_cast<int>(plot.z); ++x) {
      const std::uint8_t* p = &image.pixels[4 * (static_cast<std::size_t>(y) * image.width + x)];
      if (!(p[0] > 150 && p[1] < 110 && p[2] < 110)) continue;  // the curve's red
      const double dx = x + 0.5 - cx, dy = cy - (y + 0.5);
      const double r = std::hypot(dx, dy);
      if (r < nearest) {
        nearest = r;
        direction = std::atan2(dy, dx) * 180.0 / kPi;
      }
    }
  }
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

}  // namespace
}  // namespace weft::editor
