// Picking a tool's features to tag in screen space: a vertex right under the cursor, else the edge
// whose drawn segment the cursor is on (even near a vertex), and what a click would toggle is known
// (and highlighted) before the click.
#include "editor/tag_picking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "editor/editor_session.h"
#include "editor/viewport_interaction.h"
#include "support/temp_dir.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kW = 800, kH = 600;

// A 0.4 m box at the origin, seen straight on from +z.
struct BoxInView {
  test::TempDir dir;
  std::unique_ptr<EditorSession> session;
  ui::OrbitCamera camera;
  int corner = -1;  // the vertex at (+0.2, +0.2, +0.2), the front face's top right

  BoxInView() {
    std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "hanging-sheet.json");
    json scene = json::parse(in);
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({4, 4});
    scene["cloths"][0]["placement"] = json::parse(R"({"translate": [5, 0, 0]})");  // out of the way
    scene["obstacles"] = json::parse(R"([{"name": "block", "shape": {"box": {"half_extents": [0.2, 0.2, 0.2]}}}])");
    session = std::make_unique<EditorSession>(dir.write("scenes/box.json", scene.dump()));
    camera.target = Vec3::Zero();
    camera.distance = 2.0;
    camera.yawDeg = 0.0;
    camera.pitchDeg = 0.0;
    const std::vector<Vec3> v = session->world().obstacleVertices(0);
    for (int i = 0; i < static_cast<int>(v.size()); ++i) {
      if ((v[static_cast<std::size_t>(i)] - Vec3(0.2, 0.2, 0.2)).norm() < 1e-9) corner = i;
    }
  }
  // Where a world point is drawn, in pixels.
  Vec2 screenOf(const Vec3& p) const {
    const Eigen::Vector4f c = camera.projection(static_cast<double>(kW) / kH) * camera.view() *
                              Eigen::Vector4f(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()), 1.0f);
    return Vec2((0.5 * c.x() / c.w() + 0.5) * kW, (0.5 - 0.5 * c.y() / c.w()) * kH);
  }
};

TEST(TagPicking, AVertexRightUnderTheCursorWins) {
  BoxInView s;
  ASSERT_GE(s.corner, 0);
  const Vec2 at = s.screenOf(Vec3(0.2, 0.2, 0.2));
  const auto target = pickTagTarget(s.session->world(), 0, s.camera, at.x() + 1, at.y(), kW, kH);
  ASSERT_TRUE(target);
  EXPECT_TRUE(target->isVertex());
  EXPECT_EQ(target->vertex, s.corner);
}

TEST(TagPicking, OnAnEdgesSegmentNearAVertexTheEdgeWins) {
  BoxInView s;
  // 6 pixels along the front face's top edge from its right corner, 1 pixel above the edge.
  const Vec2 corner = s.screenOf(Vec3(0.2, 0.2, 0.2));
  const Vec2 along = (s.screenOf(Vec3(-0.2, 0.2, 0.2)) - corner).normalized();
  const Vec2 at = corner + 6.0 * along + Vec2(0, -1);
  const auto target = pickTagTarget(s.session->world(), 0, s.camera, at.x(), at.y(), kW, kH);
  ASSERT_TRUE(target);
  ASSERT_FALSE(target->isVertex()) << "the old pick took the vertex 6 px away";
  const std::vector<Vec3> v = s.session->world().obstacleVertices(0);
  for (int end : target->edge) {
    EXPECT_NEAR(v[static_cast<std::size_t>(end)].y(), 0.2, 1e-9) << "an edge along the top";
    EXPECT_NEAR(v[static_cast<std::size_t>(end)].z(), 0.2, 1e-9) << "of the front face";
  }
}

TEST(TagPicking, NothingFarFromTheTool) {
  BoxInView s;
  EXPECT_FALSE(pickTagTarget(s.session->world(), 0, s.camera, 20, 20, kW, kH));
}

}  // namespace
}  // namespace weft::editor

namespace weft::editor {
namespace {

TEST(TagPicking, ABoxTagsTheEdgesItHoldsThatAreSeen) {
  BoxInView s;
  // A box around the whole block on screen: the back face's corners are drawn inside it too
  // (perspective), but the front face hides them.
  const auto edges = edgesInBox(s.session->world(), 0, s.camera, 1, 1, kW - 1, kH - 1, kW, kH);
  ASSERT_FALSE(edges.empty());
  const std::vector<Vec3> v = s.session->world().obstacleVertices(0);
  for (const auto& e : edges) {
    for (int end : e) EXPECT_NEAR(v[static_cast<std::size_t>(end)].z(), 0.2, 1e-9) << "only the front face's edges";
  }
  EXPECT_TRUE(edgesInBox(s.session->world(), 0, s.camera, 1, 1, 20, 20, kW, kH).empty());
}

}  // namespace
}  // namespace weft::editor
