// The crack-tip criterion of propagating cracks (tearing/crack_tip_stress.h): the traction
// averaged over a length of material ahead of the tip, and the tip's rays limited to the largest
// kink a crack takes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "support/tear_scenes.h"
#include "support/test_scenes.h"
#include "tearing/crack_tip_stress.h"
#include "tearing/tear_mesh.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

// An n x n sheet of 1 m with a notch from the bottom border's middle, `cells` cells up; returns the
// notch's tip.
int notchedSheet(int n, int cells, Cloth& cloth) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-5), n, 1.0 / 240);
  scene.cloths[0].pins.clear();
  cloth = buildCloth(scene.cloths[0], "test", 0);
  int tip = kNone;
  for (const Triangle& t : cloth.mesh.tris) {
    for (int k = 0; k < 3; ++k) {
      if ((t.rest[k] - Vec2(0.5, 0.0)).norm() < 1e-9) tip = t.v[k];
    }
  }
  for (int k = 0; k < cells; ++k) {
    TopologyChange change;
    EXPECT_TRUE(tearThroughVertex(cloth.mesh, tip, Vec2(0, 1), TearGuards{}, cloth.material.areaDensity, change));
    applyTopologyChange(cloth, change);
    tip = change.crackEnds.at(0);
  }
  return tip;
}

Mat2 stressOf(double xx, double yy, double xy) {
  Mat2 s;
  s << xx, xy, xy, yy;
  return s;
}

TEST(CrackTipStress, InAUniformStressTheMeanTractionIsTheTractionAtAnyLength) {
  Cloth cloth;
  const int tip = notchedSheet(11, 3, cloth);
  const VertexFan fan = walkFan(cloth.mesh, tip, findTriangleAt(cloth.mesh, tip));
  const Mat2 sigma = stressOf(120.0, 30.0, 10.0);
  const std::vector<Mat2> stress(cloth.mesh.tris.size(), sigma);
  for (const double degrees : {20.0, 60.0, 90.0, 135.0, 160.0}) {
    const double a = degrees * std::numbers::pi / 180.0;
    const Vec2 d(std::cos(a), std::sin(a));
    const Vec2 expected = sigma * Vec2(-d.y(), d.x());
    for (const double length : {0.02, 0.1, 0.35}) {
      const Vec2 mean = meanTractionAhead(cloth.mesh, fan, stress, d, length);
      EXPECT_NEAR((mean - expected).norm(), 0.0, 1e-9) << degrees << " deg over " << length << " m";
    }
  }
}

TEST(CrackTipStress, TheMeanIsOverTheLengthAheadNotTheTipsTriangles) {
  // A load concentrated in the row of cells the tip opens into (ten times the rest, as a tip's
  // own triangles read it): the mean over 0.3 m ahead reads it in proportion to the length of the
  // ray inside that row.
  Cloth cloth;
  const int tip = notchedSheet(11, 3, cloth);  // the tip at (0.5, 0.3), cells of 0.1 m
  const VertexFan fan = walkFan(cloth.mesh, tip, findTriangleAt(cloth.mesh, tip));
  std::vector<Mat2> stress(cloth.mesh.tris.size());
  for (std::size_t t = 0; t < stress.size(); ++t) {
    const Triangle& tri = cloth.mesh.tris[t];
    const double y = (tri.rest[0].y() + tri.rest[1].y() + tri.rest[2].y()) / 3.0;
    stress[t] = stressOf(y > 0.3 && y < 0.4 ? 1000.0 : 100.0, 0.0, 0.0);
  }
  const double a = 80.0 * std::numbers::pi / 180.0;  // off the grid lines
  const Vec2 d(std::cos(a), std::sin(a));
  const double inRow = 0.1 / std::sin(a);
  EXPECT_NEAR(meanTractionAhead(cloth.mesh, fan, stress, d, 0.05).norm(), 1000.0 * std::sin(a), 1e-6);
  EXPECT_NEAR(meanTractionAhead(cloth.mesh, fan, stress, d, 0.3).norm(),
              std::sin(a) * (inRow * 1000.0 + (0.3 - inRow) * 100.0) / 0.3, 1e-6);
}

TEST(CrackTipStress, AnOpeningLoadRunsTheCrackStraightOnAndNoRayTurnsPastTheKinkLimit) {
  Cloth cloth;
  const int tip = notchedSheet(21, 6, cloth);
  const VertexFan fan = walkFan(cloth.mesh, tip, findTriangleAt(cloth.mesh, tip));
  const TearTable table = test::tearTable({1.0}, 50.0);
  // A pull across the notch (along x): straight on, omega = 100 / 50.
  {
    const std::vector<Mat2> stress(cloth.mesh.tris.size(), stressOf(100.0, 0.0, 0.0));
    const TearCandidate line = bestTipLine(cloth.mesh, fan, stress, table, 0.0, 1.0, 0.05, 72);
    EXPECT_NEAR(line.angle * 180.0 / std::numbers::pi, 90.0, 0.5);
    EXPECT_NEAR(line.ratio, 2.0, 1e-3);
    EXPECT_TRUE(line.crackTip);
  }
  // A pull along the notch (along y) asks for a line across it: the tip turns by the largest kink
  // (70.5 degrees), never further, whichever side.
  {
    const std::vector<Mat2> stress(cloth.mesh.tris.size(), stressOf(0.0, 100.0, 0.0));
    const TearCandidate line = bestTipLine(cloth.mesh, fan, stress, table, 0.0, 1.0, 0.05, 72);
    const double turn = std::abs(line.angle * 180.0 / std::numbers::pi - 90.0);
    EXPECT_LE(turn, 70.5 + 1e-6);
    EXPECT_GT(turn, 65.0);
    for (const TearCandidate& other : tipLinesAboveOne(cloth.mesh, fan, stress, table, 0.0, 1.0, 0.05, 72)) {
      EXPECT_LE(std::abs(other.angle * 180.0 / std::numbers::pi - 90.0), 70.5 + 1e-6);
    }
  }
}

}  // namespace
}  // namespace weft
