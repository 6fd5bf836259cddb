// The editor's viewport without a window: the mouse grabs and drags cloth (and releases it), a
// ball thrown from the camera enters the world, and a tool's sharp tags toggle, apply to the
// running world, undo and save beside the tool's mesh.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/editor_session.h"
#include "editor/sharp_tag_edits.h"
#include "editor/viewport_interaction.h"
#include "rigid/sharp_tags.h"
#include "support/temp_dir.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSource(WEFT_SOURCE_DIR);

json readJson(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

// The hanging sheet, small, seen from straight in front.
struct FacingSheet {
  test::TempDir dir;
  fs::path file;
  std::unique_ptr<EditorSession> session;
  ui::OrbitCamera camera;

  FacingSheet() {
    json scene = readJson(kSource / "presets/scenes/hanging-sheet.json");
    scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
    scene["cloths"][0]["placement"] = json::parse(R"({"translate": [-0.5, 0.5, 0]})");  // hangs in z = 0
    file = dir.write("scenes/sheet.json", scene.dump());
    session = std::make_unique<EditorSession>(file);
    camera.target = Vec3(0, 1.0, 0);
    camera.distance = 3.0;
    camera.yawDeg = 0.0;
    camera.pitchDeg = 0.0;
  }
};

TEST(ViewportInteraction, APressOnTheClothGrabsItADragMovesTheTargetAReleaseLetsGo) {
  FacingSheet s;
  ViewportInteraction interaction;
  ui::MouseState mouse;
  mouse.x = 400;
  mouse.y = 300;  // the centre of an 800 x 600 view: the sheet's middle
  interaction.update(*s.session, s.camera, mouse, false, 800, 600);
  ASSERT_FALSE(s.session->world().grabState());
  mouse.left = true;
  EXPECT_TRUE(interaction.update(*s.session, s.camera, mouse, false, 800, 600)) << "the press is taken from the camera";
  const auto grab = s.session->world().grabState();
  ASSERT_TRUE(grab);
  const Vec3 start = grab->spring.target;
  EXPECT_NEAR(start.z(), 0.0, 1e-9) << "on the sheet";
  mouse.y = 200;  // up the screen: the target rises
  interaction.update(*s.session, s.camera, mouse, false, 800, 600);
  EXPECT_GT(s.session->world().grabState()->spring.target.y(), start.y() + 0.1);
  EXPECT_NEAR(s.session->world().grabState()->spring.target.z(), 0.0, 1e-9) << "dragged in the plane facing the camera";
  s.session->advanceFrame();
  mouse.left = false;
  interaction.update(*s.session, s.camera, mouse, false, 800, 600);
  EXPECT_FALSE(s.session->world().grabState());
}

TEST(ViewportInteraction, APressBesideTheClothLeavesTheMouseToTheCamera) {
  FacingSheet s;
  ViewportInteraction interaction;
  ui::MouseState mouse;
  mouse.x = 5;
  mouse.y = 5;
  interaction.update(*s.session, s.camera, mouse, false, 800, 600);
  mouse.left = true;
  EXPECT_FALSE(interaction.update(*s.session, s.camera, mouse, false, 800, 600));
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

}  // namespace
}  // namespace weft::editor
