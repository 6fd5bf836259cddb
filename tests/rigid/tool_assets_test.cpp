// The committed tool meshes (scripts/make_tool_assets.py): closed and outward, sensible mass
// properties, the documented sizes and axes, and the sword's sharp tags.
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "rigid/closed_obj_import.h"
#include "rigid/closed_surface_check.h"
#include "rigid/mass_properties.h"
#include "rigid/shape_meshes.h"
#include "rigid/sharp_tags.h"
#include "rigid_test_support.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

fs::path toolPath(const std::string& name) { return fs::path(WEFT_SOURCE_DIR) / "assets" / "tools" / name; }

struct Bounds {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = Vec3::Constant(-std::numeric_limits<double>::infinity());
};

Bounds boundsOf(const TriangleMesh& mesh) {
  Bounds b;
  for (const Vec3& v : mesh.vertices) {
    b.low = b.low.cwiseMin(v);
    b.high = b.high.cwiseMax(v);
  }
  return b;
}

void expectVecNear(const Vec3& actual, const Vec3& expected, double tolerance) {
  EXPECT_LE((actual - expected).norm(), tolerance)
      << "actual " << actual.transpose() << ", expected " << expected.transpose();
}

// Loading checks closed, 2-manifold and outward; here also: the centre of mass lies inside the
// bounding box and the inertia is symmetric positive definite with principal moments that could
// belong to a solid (each at most the sum of the other two).
MassProperties expectSaneSolid(const TriangleMesh& mesh, const std::string& name) {
  EXPECT_TRUE(closedSurfaceProblems(mesh).empty()) << name;
  const MassProperties p = computeMassProperties(mesh, 1000.0, name);
  const Bounds b = boundsOf(mesh);
  EXPECT_TRUE((p.centreOfMass.array() > b.low.array()).all() && (p.centreOfMass.array() < b.high.array()).all())
      << name;
  EXPECT_LT(p.volume, (b.high - b.low).prod()) << name;
  EXPECT_LE((p.inertia - p.inertia.transpose()).cwiseAbs().maxCoeff(), 0.0) << name;
  const Vec3 principal = Eigen::SelfAdjointEigenSolver<Mat3>(p.inertia).eigenvalues();
  EXPECT_GT(principal[0], 0.0) << name;
  EXPECT_LE(principal[2], principal[0] + principal[1]) << name;
  return p;
}

TEST(ToolAssets, BallIsTheIcosphereOfRadiusOneDecimetre) {
  const TriangleMesh ball = loadClosedObj(toolPath("ball.obj"));
  const TriangleMesh expected = makeSphereMesh({0.1, 3});
  ASSERT_EQ(ball.vertices.size(), expected.vertices.size());
  EXPECT_EQ(ball.triangles, expected.triangles);  // the script builds it the same way, in the same order
  for (size_t v = 0; v < ball.vertices.size(); ++v) expectVecNear(ball.vertices[v], expected.vertices[v], 1e-9);
  const MassProperties p = expectSaneSolid(ball, "ball");
  EXPECT_EQ(ball.triangles.size(), 1280u);
  EXPECT_LT(p.centreOfMass.norm(), 1e-10);
  EXPECT_TRUE(loadSharpTags(sharpTagsPathFor(toolPath("ball.obj")), ball).empty());
}

TEST(ToolAssets, ColumnIsATwoMetreCylinder) {
  const TriangleMesh column = loadClosedObj(toolPath("column.obj"));
  const MassProperties p = expectSaneSolid(column, "column");
  const Bounds b = boundsOf(column);
  expectVecNear(b.low, Vec3(-0.1, -1.0, -0.1), 1e-9);
  expectVecNear(b.high, Vec3(0.1, 1.0, 0.1), 1e-9);
  const double prism = 0.5 * 32 * 0.01 * std::sin(2.0 * kPi / 32) * 2.0;  // 32-gon over 2 m
  EXPECT_NEAR(p.volume, prism, 1e-9);
  EXPECT_LT(p.centreOfMass.norm(), 1e-10);
  EXPECT_TRUE(loadSharpTags(sharpTagsPathFor(toolPath("column.obj")), column).empty());
}

TEST(ToolAssets, HammerHasItsHeadAtPlusY) {
  const TriangleMesh hammer = loadClosedObj(toolPath("hammer.obj"));
  const MassProperties p = expectSaneSolid(hammer, "hammer");
  const Bounds b = boundsOf(hammer);
  EXPECT_NEAR(b.high.y() - b.low.y(), 0.4, 1e-9);
  expectVecNear(b.high, Vec3(0.07, 0.2, 0.025), 1e-9);  // the head's corner
  EXPECT_GT(p.centreOfMass.y(), 0.0);                   // the head outweighs the handle
  EXPECT_NEAR(p.centreOfMass.x(), 0.0, 1e-10);
  EXPECT_TRUE(loadSharpTags(sharpTagsPathFor(toolPath("hammer.obj")), hammer).empty());
}

TEST(ToolAssets, SwordBladeAlongPlusYWithOriginAtTheGrip) {
  const TriangleMesh sword = loadClosedObj(toolPath("sword.obj"));
  const MassProperties p = expectSaneSolid(sword, "sword");
  const Bounds b = boundsOf(sword);
  EXPECT_NEAR(b.high.y(), 0.91, 1e-9);  // the tip: 0.8 m of blade above the guard at y = 0.11
  EXPECT_NEAR(b.low.y(), -0.125, 1e-9);
  EXPECT_NEAR(b.high.x(), 0.1, 1e-9);  // the guard
  // The origin is the centre of the grip: the section through it is the grip's, radius 0.0155.
  int gripSection = 0;
  for (const Vec3& v : sword.vertices) {
    if (v.y() != 0.0) continue;
    EXPECT_NEAR(std::hypot(v.x(), v.z()), 0.0155, 1e-9);
    ++gripSection;
  }
  EXPECT_EQ(gripSection, 16);
  // Blade and guard outweigh pommel and grip; the sword is symmetric about x = 0 and z = 0.
  EXPECT_GT(p.centreOfMass.y(), 0.0);
  EXPECT_NEAR(p.centreOfMass.x(), 0.0, 1e-10);
  EXPECT_NEAR(p.centreOfMass.z(), 0.0, 1e-10);
}

TEST(ToolAssets, SwordTagsItsTipAndTwoCuttingEdges) {
  const TriangleMesh sword = loadClosedObj(toolPath("sword.obj"));
  const SharpTags tags = loadSharpTags(sharpTagsPathFor(toolPath("sword.obj")), sword);

  // The tip: the one tagged vertex, the last vertex, and the highest one by a clear margin.
  ASSERT_EQ(tags.vertices.size(), 1u);
  const int tip = tags.vertices[0];
  EXPECT_EQ(tip, static_cast<int>(sword.vertices.size()) - 1);
  for (int v = 0; v < static_cast<int>(sword.vertices.size()); ++v) {
    if (v != tip) EXPECT_LT(sword.vertices[v].y(), sword.vertices[tip].y() - 0.01) << "vertex " << v;
  }
  expectVecNear(sword.vertices[tip], Vec3(0, 0.91, 0), 1e-12);

  // The edges form two chains, one on each side (x > 0, x < 0) in the blade's middle plane z = 0,
  // each running from the blade's base at the guard (y = 0.11) up to the tip.
  std::map<int, std::vector<int>> neighbours;
  for (const auto& e : tags.edges) {
    neighbours[e[0]].push_back(e[1]);
    neighbours[e[1]].push_back(e[0]);
  }
  EXPECT_EQ(neighbours[tip].size(), 2u);
  double sides = 1.0;  // the product of the two chains' x: negative when they lie on opposite sides
  for (const int start : neighbours[tip]) {
    sides *= sword.vertices[start].x();
    int previous = tip, at = start, length = 1;
    while (neighbours[at].size() == 2 && length < 100) {  // bounded, should the tags form a loop
      const int next = neighbours[at][0] == previous ? neighbours[at][1] : neighbours[at][0];
      EXPECT_LT(sword.vertices[next].y(), sword.vertices[at].y());           // descending from the tip
      EXPECT_GT(sword.vertices[next].x() * sword.vertices[start].x(), 0.0);  // on one side all along
      previous = at;
      at = next;
      ++length;
    }
    EXPECT_EQ(neighbours[at].size(), 1u);
    EXPECT_NEAR(sword.vertices[at].y(), 0.11, 1e-9);
    EXPECT_NEAR(std::abs(sword.vertices[at].x()), 0.025, 1e-9);
    EXPECT_EQ(length, 16);  // sections every 5 cm over the 0.8 m blade
  }
  EXPECT_LT(sides, 0.0);
  EXPECT_EQ(tags.edges.size(), 32u);
  for (const auto& e : tags.edges) {
    for (const int v : e) {
      EXPECT_NEAR(sword.vertices[v].z(), 0.0, 1e-12);
      // Each edge vertex is the widest point of its section: nothing at its height reaches further out.
      if (v == tip) continue;
      for (const Vec3& other : sword.vertices)
        if (std::abs(other.y() - sword.vertices[v].y()) < 1e-12 && other.y() > 0.11 + 1e-9)
          EXPECT_LE(std::abs(other.x()), std::abs(sword.vertices[v].x()) + 1e-12);
    }
  }
}

// The script writes the tag file in the layout saveSharpTags writes, so a tool's tags can be
// edited in the program and saved back without reformatting the whole file.
TEST(ToolAssets, SwordTagFileIsInTheSavedLayout) {
  const fs::path file = sharpTagsPathFor(toolPath("sword.obj"));
  const TriangleMesh sword = loadClosedObj(toolPath("sword.obj"));
  const fs::path copy = test::scratchDir() / "sword.sharp.json";
  saveSharpTags(copy, loadSharpTags(file, sword));
  auto read = [](const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  };
  EXPECT_EQ(read(copy), read(file));
}

}  // namespace
}  // namespace weft
