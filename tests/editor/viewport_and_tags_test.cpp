// The editor's viewport without a window: the mouse grabs and drags cloth (and releases it), a
// ball thrown from the camera enters the world, and a tool's sharp tags toggle, apply to the
// running world, undo and save beside the tool's mesh.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/editor_session.h"
#include "editor/sharp_tag_edits.h"
#include "editor/viewport_interaction.h"
#include "rigid/sharp_tags.h"
#include "support/facing_sheet.h"
#include "support/temp_dir.h"

namespace weft::editor {
namespace {

constexpr double kOutputFrame = 1.0 / 30.0;  // one displayed frame

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSource(WEFT_SOURCE_DIR);

json readJson(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

using test::FacingSheet;

TEST(ViewportInteraction, APressOnTheClothGrabsItADragMovesTheTargetAReleaseLetsGo) {
  FacingSheet s;
  ViewportInteraction interaction;
  ui::MouseState mouse;
  mouse.x = 400;
  mouse.y = 300;  // the centre of an 800 x 600 view: the sheet's middle
  interaction.update(*s.session, s.camera, mouse, {}, 800, 600);
  ASSERT_FALSE(s.session->world().grabState());
  mouse.left = true;
  EXPECT_TRUE(interaction.update(*s.session, s.camera, mouse, {}, 800, 600)) << "the press is taken from the camera";
  const auto grab = s.session->world().grabState();
  ASSERT_TRUE(grab);
  const Vec3 start = grab->spring.target;
  EXPECT_NEAR(start.z(), 0.0, 1e-9) << "on the sheet";
  mouse.y = 200;  // up the screen: the target rises
  interaction.update(*s.session, s.camera, mouse, {}, 800, 600);
  EXPECT_GT(s.session->world().grabState()->spring.target.y(), start.y() + 0.1);
  EXPECT_NEAR(s.session->world().grabState()->spring.target.z(), 0.0, 1e-9) << "dragged in the plane facing the camera";
  s.session->advanceFrame(kOutputFrame);
  mouse.left = false;
  interaction.update(*s.session, s.camera, mouse, {}, 800, 600);
  EXPECT_FALSE(s.session->world().grabState());
}

TEST(ViewportInteraction, APressBesideTheClothLeavesTheMouseToTheCamera) {
  FacingSheet s;
  ViewportInteraction interaction;
  ui::MouseState mouse;
  mouse.x = 5;
  mouse.y = 5;
  interaction.update(*s.session, s.camera, mouse, {}, 800, 600);
  mouse.left = true;
  EXPECT_FALSE(interaction.update(*s.session, s.camera, mouse, {}, 800, 600));
  EXPECT_FALSE(s.session->world().grabState());
}

TEST(ViewportInteraction, AThrownBallFliesFromTheCameraTowardsTheCursor) {
  FacingSheet s;
  ViewportInteraction interaction;
  const int before = s.session->world().obstacleCount();
  interaction.throwBall(*s.session, s.camera, 400, 300, 800, 600);
  ASSERT_EQ(s.session->world().obstacleCount(), before + 1);
  const Obstacle& ball = s.session->world().obstacle(before);
  EXPECT_LT(ball.body.state.linearVelocity.z(), -5.0) << "towards the sheet, away from the camera";
  EXPECT_NEAR(ball.body.state.linearVelocity.x(), 0.0, 1e-9);
}

// The sword scene with the sword's mesh and tags copied beside it, so saving never touches assets/.
struct SwordScene {
  test::TempDir dir;
  fs::path file;
  fs::path tagsFile;
  std::unique_ptr<EditorSession> session;

  SwordScene() {
    json scene = readJson(kSource / "presets/scenes/sword-into-sheet.json");
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
    file = dir.write("scenes/sword.json", scene.dump());
    fs::create_directories(dir.path() / "scenes/tools");
    fs::copy_file(kSource / "assets/tools/sword.obj", dir.path() / "scenes/tools/sword.obj");
    fs::copy_file(kSource / "assets/tools/sword.sharp.json", dir.path() / "scenes/tools/sword.sharp.json");
    tagsFile = dir.path() / "scenes/tools/sword.sharp.json";
    session = std::make_unique<EditorSession>(file);
  }
};

TEST(ToolTags, TaggingAnEdgeSharpMarksItInTheToolsDataAndTheWorld) {
  SwordScene s;
  ToolTagEditor tags(*s.session, 0);
  EXPECT_EQ(tags.document().file(), s.tagsFile);
  const SharpTags before = tags.tags();
  const Obstacle& sword = s.session->world().obstacle(0);
  // An edge that is not sharp yet.
  int edgeId = -1;
  for (std::size_t e = 0; e < sword.sharpEdge.size(); ++e) {
    if (!sword.sharpEdge[e]) {
      edgeId = static_cast<int>(e);
      break;
    }
  }
  ASSERT_GE(edgeId, 0);
  const std::array<int, 2> edge = sword.topology.edges[static_cast<std::size_t>(edgeId)];
  tags.toggleEdge(*s.session, edge);
  EXPECT_EQ(tags.tags().edges.size(), before.edges.size() + 1);
  EXPECT_TRUE(isSharpEdge(s.session->world().obstacle(0), edgeId)) << "drawn red and recorded from now on";
  EXPECT_TRUE(tags.document().dirty());

  tags.undo(*s.session);
  EXPECT_EQ(tags.tags().edges, before.edges);
  EXPECT_FALSE(isSharpEdge(s.session->world().obstacle(0), edgeId));
  tags.redo(*s.session);

  tags.save();
  const SharpTags saved = loadSharpTags(s.tagsFile, TriangleMesh{sword.bodyVertices, sword.topology.triangles});
  EXPECT_NE(std::find(saved.edges.begin(), saved.edges.end(), edge), saved.edges.end()) << "saved beside the mesh";
  EXPECT_TRUE(fs::exists(s.tagsFile.string() + ".bak"));

  // A reset rebuilds the world from the files: the saved tag is there.
  s.session->reset();
  EXPECT_TRUE(isSharpEdge(s.session->world().obstacle(0), edgeId));
}

TEST(ToolTags, TogglingTwiceRestoresAndAGeneratedShapeHasNoTagsFile) {
  SharpTags tags;
  tags = withVertexToggled(tags, 5);
  tags = withVertexToggled(tags, 2);
  EXPECT_EQ(tags.vertices, (std::vector<int>{2, 5}));
  tags = withEdgeToggled(tags, {7, 3});
  EXPECT_EQ(tags.edges, (std::vector<std::array<int, 2>>{{3, 7}})) << "canonical: a < b";
  tags = withEdgeToggled(tags, {3, 7});
  tags = withVertexToggled(tags, 5);
  EXPECT_TRUE(tags.edges.empty());
  EXPECT_EQ(tags.vertices, (std::vector<int>{2}));
  EXPECT_EQ(sharpTagsFromJson(sharpTagsJson(tags)).vertices, tags.vertices);

  ObstacleSpec ball;
  ball.shape.kind = ShapeKind::Sphere;
  EXPECT_FALSE(sharpTagsFileOf(ball));
}

struct ImVec2Like {
  double x = 0, y = 0;
};

// Where a world point appears in a width x height view of the camera (pixels from the top-left).
ImVec2Like project(const ui::OrbitCamera& camera, const Vec3& p, int width, int height) {
  const Eigen::Vector4f clip = camera.projection(double(width) / height) * camera.view() *
                               Eigen::Vector4f(float(p.x()), float(p.y()), float(p.z()), 1.0f);
  return {(clip.x() / clip.w() + 1.0) * 0.5 * width, (1.0 - clip.y() / clip.w()) * 0.5 * height};
}

TEST(ToolTags, AClickOnAToolEdgeInTagModeTogglesItSharp) {
  SwordScene s;
  ToolTagEditor tags(*s.session, 0);
  const World& world = s.session->world();
  const Obstacle& sword = world.obstacle(0);
  const std::vector<Vec3> x = world.obstacleVertices(0);
  // A camera looking at the middle of a not-yet-sharp edge from 1 m along its first face's normal.
  int edgeId = -1;
  for (std::size_t e = 0; e < sword.sharpEdge.size() && edgeId < 0; ++e) {
    if (!sword.sharpEdge[e]) edgeId = static_cast<int>(e);
  }
  ASSERT_GE(edgeId, 0);
  const auto edge = sword.topology.edges[static_cast<std::size_t>(edgeId)];
  const Vec3 middle = 0.5 * (x[edge[0]] + x[edge[1]]);
  ui::OrbitCamera camera;
  camera.target = middle;
  camera.distance = 0.5;
  camera.nearPlane = 0.01;
  // Look from outside the tool: from the side its centre is not on.
  const Vec3 outward = (middle - sword.body.state.position).normalized();
  camera.yawDeg = std::atan2(outward.x(), outward.z()) * 180.0 / 3.14159265358979323846;
  camera.pitchDeg = std::asin(std::clamp(outward.y(), -0.99, 0.99)) * 180.0 / 3.14159265358979323846;
  const ImVec2Like at = project(camera, middle, 800, 600);
  ASSERT_NEAR(at.x, 400.0, 1.0);
  ASSERT_NEAR(at.y, 300.0, 1.0);

  ViewportInteraction interaction;
  ui::MouseState mouse;
  mouse.x = at.x;
  mouse.y = at.y;
  interaction.update(*s.session, camera, mouse, {}, 800, 600, &tags);
  mouse.left = true;
  EXPECT_TRUE(interaction.update(*s.session, camera, mouse, {}, 800, 600, &tags));
  const SharpTags after = tags.tags();
  const bool edgeTagged = std::find(after.edges.begin(), after.edges.end(), edge) != after.edges.end();
  const bool endTagged = std::find(after.vertices.begin(), after.vertices.end(), edge[0]) != after.vertices.end() ||
                         std::find(after.vertices.begin(), after.vertices.end(), edge[1]) != after.vertices.end();
  EXPECT_TRUE(edgeTagged || endTagged) << "the click lands on the edge (or, on a short edge, its nearer end)";
  EXPECT_TRUE(tags.document().dirty());
}

TEST(ToolTags, AShiftDragBoxTagsTheEdgesInsideAsOneStep) {
  SwordScene s;
  ToolTagEditor tags(*s.session, 0);
  const SharpTags before = tags.tags();
  ui::OrbitCamera camera = ui::frameBox(Vec3(-0.3, 0.0, -1.0), Vec3(0.3, 1.2, 1.2), 800.0 / 600.0, 90.0, 10.0);
  ViewportInteraction interaction;
  ui::MouseState mouse;
  mouse.x = 1;
  mouse.y = 1;
  interaction.update(*s.session, camera, mouse, {false, true}, 800, 600, &tags);
  mouse.left = true;
  EXPECT_TRUE(interaction.update(*s.session, camera, mouse, {false, true}, 800, 600, &tags)) << "the box takes the mouse";
  mouse.x = 799;
  mouse.y = 599;
  interaction.update(*s.session, camera, mouse, {false, true}, 800, 600, &tags);
  ASSERT_TRUE(interaction.box());
  mouse.left = false;
  interaction.update(*s.session, camera, mouse, {false, true}, 800, 600, &tags);
  EXPECT_FALSE(interaction.box());
  EXPECT_GT(tags.tags().edges.size(), before.edges.size()) << s.session->status;
  tags.undo(*s.session);
  EXPECT_EQ(tags.tags().edges, before.edges) << "one undo step";
}

// Frames until the first tear (or `frames` when none), pulling the hanging sheet's middle down
// the screen by hand when `pull`.
int framesToFirstTear(bool pull, int frames) {
  FacingSheet s;
  json scene = s.session->json();
  scene["cloths"][0]["tear_table"] =
      json::parse(R"({"directions_deg": [0, 45, 90, 135], "strength": [40, 40, 40, 40], "unit_n_per_m": 1})");
  EXPECT_TRUE(s.session->edit(scene, "tear table").accepted) << s.session->status;
  ViewportInteraction interaction;
  ui::MouseState mouse;
  mouse.x = 400;
  mouse.y = 300;
  mouse.left = pull;
  interaction.update(*s.session, s.camera, mouse, {}, 800, 600);
  if (pull) EXPECT_TRUE(s.session->world().grabState());
  for (int frame = 0; frame < frames; ++frame) {
    if (s.session->world().tearStats().tears > 0) return frame;
    mouse.y = 300 + 8 * frame;  // down the screen, much further than the sheet can stretch
    interaction.update(*s.session, s.camera, mouse, {}, 800, 600);
    s.session->advanceFrame(kOutputFrame);
  }
  return frames;
}

TEST(ViewportInteraction, PullingAClothByHandTearsIt) {
  EXPECT_EQ(framesToFirstTear(false, 40), 40) << "left alone the sheet holds";
  EXPECT_LT(framesToFirstTear(true, 40), 40) << "a hard pull tears it";
}

}  // namespace
}  // namespace weft::editor
