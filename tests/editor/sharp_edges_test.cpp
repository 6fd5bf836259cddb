// "Tag all edges sharper than N degrees" for blades: the fold angle between an edge's two faces
// decides, and the whole tagging is one undo step applied to the running world.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "contact/obstacle.h"
#include "editor/editor_session.h"
#include "editor/sharp_tag_edits.h"
#include "support/temp_dir.h"

namespace weft::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A unit cube: 12 edges where faces meet at 90 degrees, 6 face diagonals where they are flat.
CollisionMesh cube(std::vector<Vec3>& vertices) {
  vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
              Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  return makeCollisionMesh(8, {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                               {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}});
}

TEST(SharpEdges, OnlyEdgesFoldedMoreThanTheAngleCount) {
  std::vector<Vec3> vertices;
  const CollisionMesh mesh = cube(vertices);
  ASSERT_EQ(mesh.edges.size(), 18u);
  EXPECT_EQ(edgesSharperThan(mesh, vertices, 45.0).size(), 12u) << "the cube's edges, not its diagonals";
  EXPECT_EQ(edgesSharperThan(mesh, vertices, 89.0).size(), 12u);
  EXPECT_TRUE(edgesSharperThan(mesh, vertices, 91.0).empty());
}

TEST(SharpEdges, TaggingTheSwordsBladeIsOneUndoStepAppliedLive) {
  test::TempDir dir;
  std::ifstream in(fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sword-into-sheet.json");
  json scene = json::parse(in);
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({6, 6});
  EditorSession session(dir.write("scenes/sword.json", scene.dump(2)));
  ToolTagEditor tool(session, 0);
  const SharpTags before = tool.tags();
  const int added = tool.tagEdgesSharperThan(session, 60.0);
  const Obstacle& sword = session.world().obstacle(0);
  EXPECT_GT(added, 0);
  EXPECT_LT(tool.tags().edges.size(), sword.topology.edges.size()) << "not every edge of the sword";
  const long long sharpInWorld = std::count(sword.sharpEdge.begin(), sword.sharpEdge.end(), 1);
  EXPECT_EQ(sharpInWorld, static_cast<long long>(tool.tags().edges.size())) << "applied to the running world";
  tool.undo(session);
  EXPECT_EQ(tool.tags().edges, before.edges) << "one step";
}

}  // namespace
}  // namespace weft::editor
