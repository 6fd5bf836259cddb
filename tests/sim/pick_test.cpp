// Picking: a ray hits the expected triangle of a flat sheet and misses beside it; the nearest of
// two sheets wins; obstacle features near the hit are found within the tolerance only.
#include <gtest/gtest.h>

#include "contact/obstacle.h"
#include "sim/pick.h"
#include "sim/world.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

// An 11 x 11 flat sheet (spacing 0.1 m) in the x-y plane at z = 0, no forces.
Scene flatSheet() {
  Scene scene = test::hangingSheet(test::isotropicMaterial(), 11, 1.0 / 60);
  scene.forces.gravity = Vec3::Zero();
  return scene;
}

bool inTriangleXY(const ClothMesh& mesh, int t, const Vec3& p) {
  const Triangle& tri = mesh.tris[t];
  const Vec3& a = mesh.x[tri.v[0]];
  const Vec3& b = mesh.x[tri.v[1]];
  const Vec3& c = mesh.x[tri.v[2]];
  auto side = [&](const Vec3& u, const Vec3& v) { return (v - u).x() * (p - u).y() - (v - u).y() * (p - u).x(); };
  const double s0 = side(a, b), s1 = side(b, c), s2 = side(c, a);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

TEST(PickCloth, HitsTriangleUnderTheRay) {
  World world(flatSheet());
  const Vec3 aim(0.32, 0.41, 0.0);
  const auto hit = pickCloth(world, aim + Vec3(0, 0, 2), Vec3(0, 0, -1));
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->cloth, 0);
  EXPECT_LT((hit->point - aim).norm(), 1e-12);
  EXPECT_NEAR(hit->distance, 2.0, 1e-12);
  EXPECT_TRUE(inTriangleXY(world.cloth(0), hit->triangle, aim));
  EXPECT_LT((world.cloth(0).x[hit->vertex] - Vec3(0.3, 0.4, 0)).norm(), 1e-12);  // the nearest grid vertex
  // From behind the sheet too (both faces count).
  const auto back = pickCloth(world, aim - Vec3(0, 0, 1), Vec3(0, 0, 3));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->triangle, hit->triangle);
}

TEST(PickCloth, MissesBesideAndBehind) {
  World world(flatSheet());
  EXPECT_FALSE(pickCloth(world, Vec3(1.2, 0.5, 2), Vec3(0, 0, -1)).has_value());
  EXPECT_FALSE(pickCloth(world, Vec3(0.5, 0.5, 2), Vec3(0, 0, 1)).has_value());  // pointing away
  EXPECT_FALSE(pickCloth(world, Vec3(0.5, 0.5, 2), Vec3(1, 0, 0)).has_value());  // parallel, above
}

TEST(PickCloth, NearestOfTwoSheets) {
  Scene scene = flatSheet();
  scene.cloths.push_back(scene.cloths[0]);
  scene.cloths[1].placement.translate = Vec3(0, 0, 0.5);
  World world(scene);
  const auto fromFront = pickCloth(world, Vec3(0.5, 0.5, 2), Vec3(0, 0, -1));
  ASSERT_TRUE(fromFront.has_value());
  EXPECT_EQ(fromFront->cloth, 1);
  const auto fromBack = pickCloth(world, Vec3(0.55, 0.55, -2), Vec3(0, 0, 1));
  ASSERT_TRUE(fromBack.has_value());
  EXPECT_EQ(fromBack->cloth, 0);
}

Scene boxScene() {
  Scene scene = flatSheet();
  ObstacleSpec box;
  box.shape.kind = ShapeKind::Box;
  box.shape.halfExtents = Vec3(0.1, 0.1, 0.1);
  box.translate = Vec3(0.5, 0.5, 1.0);  // in front of the sheet
  scene.obstacles.push_back(box);
  return scene;
}

TEST(PickObstacleFeature, CornerVertexAndEdgeWithinTolerance) {
  World world(boxScene());
  const Vec3 corner(0.6, 0.6, 1.1);
  const Vec3 aim = corner + Vec3(-0.003, -0.0005, 0);
  const auto hit = pickObstacleFeature(world, aim + Vec3(0, 0, 2), Vec3(0, 0, -1), 0.01);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->obstacle, 0);
  EXPECT_LT((hit->point - aim).norm(), 1e-12);  // the box, not the sheet behind it
  ASSERT_NE(hit->vertex, kNone);
  const std::vector<Vec3> x = world.obstacleVertices(0);
  EXPECT_LT((x[hit->vertex] - corner).norm(), 1e-12);
  ASSERT_NE(hit->edge, kNone);
  // The nearest edge is the box edge along x through the corner (0.0005 m away; the one along y
  // is 0.003 m away, the face diagonals at least 0.0017 m).
  const auto& edge = world.obstacle(0).topology.edges[hit->edge];
  EXPECT_TRUE(edge[0] == hit->vertex || edge[1] == hit->vertex);
  const Vec3 along = x[edge[1]] - x[edge[0]];
  EXPECT_NEAR(std::abs(along.normalized().x()), 1.0, 1e-12);
}

TEST(PickObstacleFeature, NothingNearOrNoHit) {
  World world(boxScene());
  // Far from every vertex and edge of the top face's 4 x 4 grid and its diagonals.
  const auto hit = pickObstacleFeature(world, Vec3(0.51, 0.53, 3), Vec3(0, 0, -1), 0.001);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->vertex, kNone);
  EXPECT_EQ(hit->edge, kNone);
  EXPECT_FALSE(pickObstacleFeature(world, Vec3(2, 2, 3), Vec3(0, 0, -1), 0.01).has_value());
}

}  // namespace
}  // namespace weft
