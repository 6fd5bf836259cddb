// The contact sections of a scene ("ground", "obstacles", "contact"): read as documented, and every
// kind of bad input rejected with an InputError naming the file and the field — at load time for
// the JSON, and when the World is built for a mesh or tag file that is wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "scene/scene_json.h"
#include "sim/world.h"
#include "support/temp_dir.h"
#include "util/input_error.h"

namespace weft {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::TempDir;

json sceneWithObstacle(const std::string& obstacle) {
  json scene = json::parse(R"({"cloths": [{"mesh": {"grid": {}}, "material": "royal-target"}]})");
  scene["obstacles"] = json::array({json::parse(obstacle)});
  return scene;
}

TEST(ContactJson, ObstaclesGroundAndContactAreRead) {
  TempDir dir;
  json scene = sceneWithObstacle(R"({"name": "ball", "shape": {"sphere": {"radius": 0.2}},
      "placement": {"translate": [1, 2, 3]}, "motion": {"dynamic": {"mass": 3, "velocity": [0, 0, -4]}}})");
  scene["obstacles"].push_back(json::parse(R"({"name": "sword", "shape": {"mesh": {"path": "tools/sword.obj"}},
      "motion": {"kinematic": {"keyframes": [{"t": 0, "translate": [0, 1, 0]}, {"t": 1, "translate": [0, 0, 0]}]}}})"));
  scene["ground"] = json::parse(R"({"height": -0.5})");
  scene["contact"] = json::parse(R"({"self": true, "thickness": 0.002, "ccd_iterations": 12, "reuse_pairs": false,
                                         "recheck_all_pairs": true})");
  const Scene s = loadScene(dir.write("scene.json", scene.dump()));
  ASSERT_EQ(s.obstacles.size(), 2u);
  EXPECT_EQ(s.obstacles[0].shape.kind, ShapeKind::Sphere);
  EXPECT_DOUBLE_EQ(s.obstacles[0].shape.radius, 0.2);
  EXPECT_EQ(s.obstacles[0].motion, ObstacleMotion::Dynamic);
  EXPECT_DOUBLE_EQ(s.obstacles[0].mass, 3.0);
  EXPECT_EQ(s.obstacles[0].translate, Vec3(1, 2, 3));
  EXPECT_EQ(s.obstacles[1].motion, ObstacleMotion::Kinematic);
  EXPECT_EQ(s.obstacles[1].keyframes.size(), 2u);
  EXPECT_EQ(s.obstacles[1].translate, Vec3(0, 1, 0));  // the pose at t = 0 comes from the first key
  EXPECT_EQ(s.obstacles[1].shape.sharpTagsPath.filename(), "sword.sharp.json");  // found beside the mesh
  EXPECT_TRUE(s.ground.enabled);
  EXPECT_DOUBLE_EQ(s.ground.height, -0.5);
  EXPECT_TRUE(s.contact.self);
  EXPECT_DOUBLE_EQ(s.contact.thickness, 0.002);
  EXPECT_EQ(s.contact.ccdIterations, 12);
  EXPECT_FALSE(s.contact.reusePairs);
  EXPECT_TRUE(s.contact.recheckAllPairs);

  // The world builds them: the dynamic ball turns about its centre of mass, the sword's tags are read.
  const World world(s);
  EXPECT_EQ(world.obstacleCount(), 2);
  EXPECT_NEAR(world.obstacle(0).body.mass, 3.0, 1e-12);
  EXPECT_TRUE(world.obstacle(0).body.state.position.isApprox(Vec3(1, 2, 3), 1e-9));
  int sharpVertices = 0, sharpEdges = 0;
  for (char c : world.obstacle(1).sharpVertex) sharpVertices += c;
  for (char c : world.obstacle(1).sharpEdge) sharpEdges += c;
  EXPECT_EQ(sharpVertices, 1);
  EXPECT_GT(sharpEdges, 10);
}

// Sharp tags can live in the scene itself: "sharp_tags": {...} in the mesh shape, the tag file's
// form, read instead of a tag file beside the mesh.
TEST(ContactJson, SharpTagsWrittenInTheSceneAreReadInsteadOfTheFileBesideTheMesh) {
  TempDir dir;
  dir.write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  dir.write("tet.sharp.json", R"({"sharp_vertices": [0, 1, 2]})");
  const fs::path file = dir.write(
      "inline.json",
      sceneWithObstacle(R"({"shape": {"mesh": {"path": "tet.obj", "sharp_tags": {"sharp_edges": [[1, 0]], "sharp_vertices": [3]}}}})")
          .dump(2));
  const World world(loadScene(file));
  const Obstacle& tet = world.obstacle(0);
  EXPECT_EQ(std::vector<char>(tet.sharpVertex.begin(), tet.sharpVertex.end()), (std::vector<char>{0, 0, 0, 1}));
  int sharpEdges = 0;
  for (std::size_t e = 0; e < tet.sharpEdge.size(); ++e) {
    if (!tet.sharpEdge[e]) continue;
    ++sharpEdges;
    EXPECT_EQ(tet.topology.edges[e], (std::array<int, 2>{0, 1}));
  }
  EXPECT_EQ(sharpEdges, 1);
}

struct BadObstacle {
  std::string name;
  std::string obstacle;  // the obstacle's JSON, or a patch for the whole scene when it starts with "scene:"
  std::string field;     // expected InputError::field()
  std::string mentions;  // a word the message must contain
};
std::ostream& operator<<(std::ostream& out, const BadObstacle& c) { return out << c.name; }

class ContactJsonRejects : public ::testing::TestWithParam<BadObstacle> {};

TEST_P(ContactJsonRejects, NamingTheFileAndTheField) {
  const BadObstacle& c = GetParam();
  TempDir dir;
  dir.write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  dir.write("tet.sharp.json", R"({"sharp_edges": [[0, 7]]})");
  json scene;
  if (c.obstacle.rfind("scene:", 0) == 0) {
    scene = sceneWithObstacle(R"({"shape": {"sphere": {"radius": 0.1}}})");
    scene.merge_patch(json::parse(c.obstacle.substr(6)));
  } else {
    scene = sceneWithObstacle(c.obstacle);
  }
  const fs::path file = dir.write("bad-contact.json", scene.dump(2));
  try {
    const Scene s = loadScene(file);
    const World world(s);  // mesh and tag files are read when the world is built
    FAIL() << "accepted without an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad-contact.json"), std::string::npos) << what;
    EXPECT_EQ(e.field().rfind(c.field, 0), 0u) << "field " << e.field() << ", expected " << c.field << "; " << what;
    EXPECT_NE(what.find(c.mentions), std::string::npos) << "expected '" << c.mentions << "' in: " << what;
  }
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, ContactJsonRejects,
    ::testing::Values(
        BadObstacle{"MissingShape", R"({"name": "a"})", "/obstacles/0/shape", "missing"},
        // Sharp tags written in the scene (issue 21, item 4): checked as a tag file is, named
        // by the scene file and the field.
        BadObstacle{"InlineTagOutOfRange", R"({"shape": {"mesh": {"path": "tet.obj", "sharp_tags": {"sharp_vertices": [9]}}}})",
                    "/obstacles/0/shape/mesh/sharp_tags/sharp_vertices/0", "out of range"},
        BadObstacle{"InlineTagNotAnEdge", R"({"shape": {"mesh": {"path": "tet.obj", "sharp_tags": {"sharp_edges": [[0, 0]]}}}})",
                    "/obstacles/0/shape/mesh/sharp_tags/sharp_edges/0", "two different vertices"},
        BadObstacle{"InlineTagsUnknownKey", R"({"shape": {"mesh": {"path": "tet.obj", "sharp_tags": {"sharp_edge": []}}}})",
                    "/obstacles/0/shape/mesh/sharp_tags", "sharp_edge"},
        BadObstacle{"InlineTagsNotAList", R"({"shape": {"mesh": {"path": "tet.obj", "sharp_tags": {"sharp_edges": 3}}}})",
                    "/obstacles/0/shape/mesh/sharp_tags/sharp_edges", "array"},
        BadObstacle{"TagsNeitherPathNorObject", R"({"shape": {"mesh": {"path": "tet.obj", "sharp_tags": 3}}})",
                    "/obstacles/0/shape/mesh/sharp_tags", "sharp-tag file's path or the tags themselves"},
        BadObstacle{"TwoShapes", R"({"shape": {"sphere": {"radius": 1}, "box": {"half_extents": [1, 1, 1]}}})",
                    "/obstacles/0/shape", "exactly one"},
        BadObstacle{"UnknownShape", R"({"shape": {"torus": {}}})", "/obstacles/0/shape/torus", "allowed keys"},
        BadObstacle{"NegativeRadius", R"({"shape": {"sphere": {"radius": -1}}})", "/obstacles/0/shape/sphere/radius", "[0.001, 100] m"},
        // Outside physical sense (scene_limits.h): a 1e-7 m ball once blew a run up unnoticed,
        // a resolution or segment count of 2^31 ran out of memory, a 1000 m/s ball ran for 10 minutes.
        BadObstacle{"TinySphere", R"({"shape": {"sphere": {"radius": 1e-7}}})", "/obstacles/0/shape/sphere/radius",
                    "[0.001, 100] m"},
        BadObstacle{"HugeBoxResolution", R"({"shape": {"box": {"half_extents": [1, 1, 1], "resolution": 2147483647}}})",
                    "/obstacles/0/shape/box/resolution", "[1, 256]"},
        BadObstacle{"HugeSegments", R"({"shape": {"capsule": {"radius": 0.1, "half_length": 0.5, "segments": 1e6}}})",
                    "/obstacles/0/shape/capsule/segments", "[3, 1024]"},
        // Each field in range, together 67 billion triangles (bands as tall as a segment is wide):
        // once std::bad_alloc, exit 1, after minutes of allocating.
        BadObstacle{"ThinLongCylinder",
                    R"({"shape": {"cylinder": {"radius": 0.001, "half_length": 100, "segments": 1024}}})",
                    "/obstacles/0/shape/cylinder", "at most 2097152"},
        BadObstacle{"ThinLongCylinderFewSegments",
                    R"({"shape": {"cylinder": {"radius": 0.001, "half_length": 100, "segments": 32}}})",
                    "/obstacles/0/shape/cylinder", "bands"},
        BadObstacle{"FastBall", R"({"shape": {"sphere": {"radius": 0.1}}, "motion": {"dynamic": {"mass": 1, "velocity": [0, 0, -1000]}}})",
                    "/obstacles/0/motion/dynamic/velocity", "at most 340 m/s"},
        BadObstacle{"HugeContactIterations", R"(scene:{"contact": {"impact_zone_iterations": 1e9}})",
                    "/contact/impact_zone_iterations", "[1, 1000]"},
        BadObstacle{"NaNRadius", R"({"shape": {"sphere": {"radius": "NaN"}}})", "/obstacles/0/shape/sphere/radius", "got"},
        BadObstacle{"FlatBox", R"({"shape": {"box": {"half_extents": [1, 0, 1]}}})", "/obstacles/0/shape/box/half_extents/1",
                    "[0.001, 100] m"},
        BadObstacle{"MissingMeshFile", R"({"shape": {"mesh": {"path": "nowhere.obj"}}})", "/obstacles/0/shape/mesh/path",
                    "nowhere.obj"},
        BadObstacle{"OpenMesh", R"({"shape": {"mesh": {"path": "open.obj"}}})", "/obstacles/0/shape", "open.obj"},
        BadObstacle{"TagNamesANonEdge", R"({"shape": {"mesh": {"path": "tet.obj"}}})", "/obstacles/0/shape",
                    "tet.sharp.json"},
        BadObstacle{"UnknownMotion", R"({"shape": {"sphere": {"radius": 1}}, "motion": "flying"})", "/obstacles/0/motion",
                    "static"},
        BadObstacle{"DynamicWithoutMass", R"({"shape": {"sphere": {"radius": 1}}, "motion": {"dynamic": {}}})",
                    "/obstacles/0/motion/dynamic/mass", "missing"},
        BadObstacle{"ZeroMass", R"({"shape": {"sphere": {"radius": 1}}, "motion": {"dynamic": {"mass": 0}}})",
                    "/obstacles/0/motion/dynamic/mass", "> 0"},
        BadObstacle{"KeysAndVelocity",
                    R"({"shape": {"sphere": {"radius": 1}}, "motion": {"kinematic": {"keyframes": [{"t": 0, "translate": [0,0,0]}], "velocity": [1, 0, 0]}}})",
                    "/obstacles/0/motion/kinematic", "not both"},
        BadObstacle{"KeysNotIncreasing",
                    R"({"shape": {"sphere": {"radius": 1}}, "motion": {"kinematic": {"keyframes": [{"t": 1, "translate": [0,0,0]}, {"t": 0.5, "translate": [0,0,0]}]}}})",
                    "/obstacles/0/motion/kinematic/keyframes/1/t", "increasing"},
        BadObstacle{"KeysAndPlacement",
                    R"({"shape": {"sphere": {"radius": 1}}, "placement": {"translate": [0, 1, 0]}, "motion": {"kinematic": {"keyframes": [{"t": 0, "translate": [0,0,0]}]}}})",
                    "/obstacles/0/placement", "keyframes"},
        BadObstacle{"NegativeFriction", R"({"shape": {"sphere": {"radius": 1}}, "friction": -0.1})", "/obstacles/0/friction",
                    ">= 0"},
        BadObstacle{"UnsafeName", R"({"name": "../x", "shape": {"sphere": {"radius": 1}}})", "/obstacles/0/name", "letters"},
        BadObstacle{"ZeroThickness", R"(scene:{"contact": {"thickness": 0}})", "/contact/thickness", "(0, 0.1] m"},
        BadObstacle{"ThickContact", R"(scene:{"contact": {"thickness": 1e6}})", "/contact/thickness", "(0, 0.1] m"},
        BadObstacle{"UnknownContactKey", R"(scene:{"contact": {"selfie": true}})", "/contact/selfie", "allowed keys"},
        BadObstacle{"ReusePairsNotBool", R"(scene:{"contact": {"reuse_pairs": 1}})", "/contact/reuse_pairs",
                    "true or false"},
        BadObstacle{"RecheckAllPairsNotBool", R"(scene:{"contact": {"recheck_all_pairs": "no"}})",
                    "/contact/recheck_all_pairs", "true or false"},
        BadObstacle{"GroundHeightNaN", R"(scene:{"ground": {"height": "NaN"}})", "/ground/height", "got"},
        BadObstacle{"CollisionStageNotBool", R"(scene:{"stages": {"collision": "yes"}})", "/stages/collision",
                    "true or false"}),
    [](const ::testing::TestParamInfo<BadObstacle>& info) { return info.param.name; });

}  // namespace
}  // namespace weft
