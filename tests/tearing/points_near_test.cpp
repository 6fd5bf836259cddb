#include "tearing/points_near.h"

#include <gtest/gtest.h>

#include <random>

namespace weft {
namespace {

// The exact answer of a scan over every point, for centres inside, at and beyond the points'
// spread, and points exactly at the distance (which count).
TEST(PointsNear, AnswersAsAScanOfEveryPointDoes) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec2> points(1 + trial * 7);
    for (Vec2& p : points) p = Vec2(2.0 * unit(rng) - 0.5, unit(rng));
    const double distance = 0.02 + 0.2 * unit(rng);
    PointsNear near;
    near.build(points, distance);
    for (int q = 0; q < 500; ++q) {
      const Vec2 centre(4.0 * unit(rng) - 1.5, 3.0 * unit(rng) - 1.0);
      bool any = false;
      for (const Vec2& p : points) any = any || (p - centre).squaredNorm() <= distance * distance;
      ASSERT_EQ(near.anyWithin(centre), any) << "trial " << trial << " query " << q;
    }
  }
  PointsNear one;
  one.build({Vec2(0.25, 0.5)}, 0.25);
  EXPECT_TRUE(one.anyWithin(Vec2(0.5, 0.5)));  // exactly at the distance
  EXPECT_FALSE(one.anyWithin(Vec2(0.5, 0.75)));
  PointsNear none;
  none.build({}, 0.1);
  EXPECT_FALSE(none.anyWithin(Vec2(0, 0)));
}

}  // namespace
}  // namespace weft
