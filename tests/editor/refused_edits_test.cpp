// A value the strict reader refuses is never silently dropped: the field shows the reader's
// message under it in red, the status bar keeps it until the next edit, and the scene is unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "editor/scene_edits.h"
#include "support/editor_panels_fixture.h"

namespace weft::editor {
namespace {

using test::EditorPanelsTest;
using test::kHeight;
using test::kWidth;

// Pixels of the refusal's red (kRefusedColour, 204/13/13 with antialiased edges) in a rectangle.
long long redPixels(const test::RgbaImage& image, float x0, float y0, float x1, float y1) {
  long long count = 0;
  for (int y = std::max(0, static_cast<int>(y0)); y < std::min(image.height, static_cast<int>(y1)); ++y) {
    for (int x = std::max(0, static_cast<int>(x0)); x < std::min(image.width, static_cast<int>(x1)); ++x) {
      const std::uint8_t* p = &image.pixels[4 * (static_cast<std::size_t>(y) * image.width + x)];
      if (p[0] > 140 && p[1] < 90 && p[2] < 90) ++count;
    }
  }
  return count;
}

struct BadValue {
  std::string widget;   // the field, as the panels record it
  std::string typed;    // what the user types
  std::string label;    // the edit's label
  std::string pointer;  // the JSON field the reader's message names
};

class RefusedEditsTest : public EditorPanelsTest, public ::testing::WithParamInterface<BadValue> {};

TEST_P(RefusedEditsTest, TheReadersMessageShowsBesideTheFieldAndInTheStatusBar) {
  const BadValue& bad = GetParam();
  const nlohmann::json before = session_->json();
  const ImVec4 field = probe_.rects.at(bad.widget);
  auto underField = [&](const test::RgbaImage& image) {
    return redPixels(image, field.x, field.w, field.x + 260, field.w + 40);
  };
  auto inStatusBar = [&](const test::RgbaImage& image) { return redPixels(image, 0, kHeight - 24, kWidth, kHeight); };
  ASSERT_EQ(underField(imgui_->image()), 0);
  ASSERT_EQ(inStatusBar(imgui_->image()), 0);

  imgui_->click(ImVec2(field.x + 20, 0.5f * (field.y + field.w)), drawUi());
  imgui_->typeAndEnter(bad.typed, drawUi());
  EXPECT_EQ(session_->json(), before) << "nothing changed";
  EXPECT_FALSE(session_->dirty());
  ASSERT_TRUE(session_->refusal().has_value()) << "refused silently; status: " << session_->status;
  EXPECT_EQ(session_->refusal()->label, bad.label);
  EXPECT_NE(session_->refusal()->message.find(bad.pointer), std::string::npos) << session_->refusal()->message;
  EXPECT_GT(underField(imgui_->image()), 20) << "no red message under the field";
  EXPECT_GT(inStatusBar(imgui_->image()), 20) << "no red message in the status bar";

  // Time passing and playback do not hide it; the next edit does.
  for (int i = 0; i < 3; ++i) imgui_->frame(drawUi());
  EXPECT_GT(inStatusBar(imgui_->image()), 20);
  ASSERT_TRUE(session_->edit(withWeftAngle(session_->json(), 0, 10.0), "weft angle").accepted);
  imgui_->frame(drawUi());
  EXPECT_FALSE(session_->refusal().has_value());
  EXPECT_EQ(underField(imgui_->image()), 0);
  EXPECT_EQ(inStatusBar(imgui_->image()), 0);
}

INSTANTIATE_TEST_SUITE_P(
    IssueExamples, RefusedEditsTest,
    ::testing::Values(BadValue{"material/density", "-0.3", "area density", "area_density_kg_m2"},
                      BadValue{"solver/dt", "0", "time step", "/solver/dt"},
                      BadValue{"solver/tolerance", "-1", "CG tolerance", "/solver/linear_solver/tolerance"},
                      BadValue{"solver/substeps", "0", "substeps", "/solver/substeps"},
                      BadValue{"tear/1", "-5", "tear strength 45 deg", "strength"}),
    [](const ::testing::TestParamInfo<BadValue>& info) {
      std::string name;
      for (char c : info.param.label) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name;
    });

}  // namespace
}  // namespace weft::editor
