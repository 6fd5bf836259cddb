#include "tearing/tear_candidates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "mesh/grid.h"
#include "support/collision_meshes.h"
#include "support/random_fan.h"
#include "tearing/tear_selection.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

constexpr double kPi = std::numbers::pi;

ClothMesh grid(int n) { return test::gridCloth(n, 1.0); }

// A uniform pull of `tension` N/m along material direction `angle` in every triangle.
std::vector<Mat2> uniformPull(const ClothMesh& mesh, double tension, double angle) {
  const Vec2 d(std::cos(angle), std::sin(angle));
  return std::vector<Mat2>(mesh.tris.size(), tension * d * d.transpose());
}

TearTable isotropicTable(double strength) {
  TearTable table;
  table.strength = {strength};
  return table;
}

TEST(TearCandidates, AngleFromWarpFollowsEquations31To33) {
  // Weft along material x: V is material y. A line along V is alpha 0, along U alpha 90.
  EXPECT_NEAR(angleFromWarpDeg(kPi / 2, 0.0), 0.0, 1e-9);
  EXPECT_NEAR(angleFromWarpDeg(0.0, 0.0), 90.0, 1e-9);
  EXPECT_NEAR(angleFromWarpDeg(kPi, 0.0), 90.0, 1e-9) << "a line has no sense";
  // Eq. 3.1 measures alpha clockwise from V: a line at 45 degrees (x = y) is 45 from V clockwise.
  EXPECT_NEAR(angleFromWarpDeg(kPi / 4, 0.0), 45.0, 1e-9);
  EXPECT_NEAR(angleFromWarpDeg(3 * kPi / 4, 0.0), 135.0, 1e-9);
  // The frame turns with the weft.
  const double weft = 30.0 * kPi / 180.0;
  EXPECT_NEAR(angleFromWarpDeg(weft + kPi / 2, weft), 0.0, 1e-9);
}

// The best line of the vertex at the middle of the grid.
TearCandidate bestAtCentre(const ClothMesh& mesh, const std::vector<Mat2>& stress, const TearTable& table,
                           double weft, CandidateLines lines) {
  TearSearchSettings settings;
  settings.lines = lines;
  std::vector<TearCandidate> found;
  TearSearchCounts counts;
  findTearCandidates(mesh, triangleCorners(mesh), stress, table, weft, settings, found, counts);
  const int n = static_cast<int>(std::lround(std::sqrt(mesh.vertexCount())));
  const int centre = (n / 2) * n + n / 2;  // an interior vertex of the square grid
  for (const TearCandidate& c : found) {
    if (c.vertex == centre) return c;
  }
  ADD_FAILURE() << "the centre vertex has no candidate";
  return {};
}

TEST(TearCandidates, APullAlongTheWarpTearsAcrossItAndAlongTheWeftLikewise) {
  const ClothMesh mesh = grid(8);
  for (const double weftDeg : {0.0, 30.0}) {
    const double weft = weftDeg * kPi / 180.0;
    for (const CandidateLines lines : {CandidateLines::Thesis, CandidateLines::Dense}) {
      // Pull along V (the warp): the tear runs across it, along U: alpha 90.
      const TearCandidate acrossWarp =
          bestAtCentre(mesh, uniformPull(mesh, 200.0, weft + kPi / 2), isotropicTable(100.0), weft, lines);
      // Pull along U (the weft): the tear runs along V: alpha 0.
      const TearCandidate acrossWeft = bestAtCentre(mesh, uniformPull(mesh, 200.0, weft), isotropicTable(100.0), weft, lines);
      // The thesis' lines can only follow the mesh: the grid's edges are at 0, 45 and 90 degrees
      // in material space, so at a 30 degree weft the closest line is 15 degrees off.
      const double tolerance = lines == CandidateLines::Dense ? 1.0 : (weftDeg == 0.0 ? 1e-6 : 15.0 + 1e-6);
      EXPECT_NEAR(acrossWarp.alphaDeg, 90.0, tolerance) << "weft " << weftDeg;
      const double alpha = acrossWeft.alphaDeg > 90.0 ? acrossWeft.alphaDeg - 180.0 : acrossWeft.alphaDeg;
      EXPECT_NEAR(alpha, 0.0, tolerance) << "weft " << weftDeg;
      if (lines == CandidateLines::Dense) {
        EXPECT_NEAR(acrossWarp.separation, 200.0, 1e-3) << "the dense line is the one across the pull";
        EXPECT_NEAR(acrossWarp.ratio, 2.0, 1e-5);
      }
    }
  }
}

TEST(TearCandidates, TheWeakDirectionOfTheTableWinsUnderAnEqualPullInAllDirections) {
  // Table 4.1, Cloth 2: strong at 0, weak at 90 degrees from V: an isotropic stress tears along U.
  const ClothMesh mesh = grid(8);
  TearTable table;
  table.strength = {35.0, 25.0, 12.0, 25.0};
  table.unitNPerM = 10.0;
  const std::vector<Mat2> stress(mesh.tris.size(), 150.0 * Mat2::Identity());
  for (const CandidateLines lines : {CandidateLines::Thesis, CandidateLines::Dense}) {
    const TearCandidate best = bestAtCentre(mesh, stress, table, 0.0, lines);
    EXPECT_NEAR(best.alphaDeg, 90.0, 1e-6);
    EXPECT_NEAR(best.ratio, 150.0 / 120.0, 1e-9);
  }
}

TEST(TearCandidates, SkippingByTheBoundChangesNothing) {
  const ClothMesh mesh = grid(12);
  // A stress that varies over the sheet: only some vertices can reach the table.
  std::vector<Mat2> stress(mesh.tris.size());
  for (std::size_t t = 0; t < stress.size(); ++t) {
    const double a = 0.37 * static_cast<double>(t);
    const Vec2 d(std::cos(a), std::sin(a));
    stress[t] = (40.0 + 160.0 * std::abs(std::sin(0.05 * t))) * d * d.transpose() + 10.0 * Mat2::Identity();
  }
  TearTable table;
  table.strength = {12.0, 25.0, 35.0, 25.0};
  table.unitNPerM = 10.0;
  for (const CandidateLines lines : {CandidateLines::Thesis, CandidateLines::Dense}) {
   for (const bool asOne : {false, true}) {
    TearSearchSettings with, without;
    with.lines = without.lines = lines;
    with.closedFanAsOne = without.closedFanAsOne = asOne;
    without.skipByBound = false;
    std::vector<TearCandidate> a, b;
    TearSearchCounts countsWith, countsWithout;
    findTearCandidates(mesh, triangleCorners(mesh), stress, table, 0.2, with, a, countsWith);
    findTearCandidates(mesh, triangleCorners(mesh), stress, table, 0.2, without, b, countsWithout);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_GT(a.size(), 0u) << "some vertex should tear";
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].vertex, b[k].vertex);
      EXPECT_EQ(a[k].angle, b[k].angle);
      EXPECT_EQ(a[k].ratio, b[k].ratio);
    }
    EXPECT_GT(countsWith.skipped, 0) << "the bound should skip the quiet vertices";
    EXPECT_LT(countsWith.linesEvaluated, countsWithout.linesEvaluated);
   }
  }
}

// Read as one (the averaged stress's mode, tear_search.h), a closed fan's lines read the traction
// of its sectors' mean stress, weighted by their angles: an interior vertex's best line is the one
// across that mean's pull as the table weighs it, whatever its sectors' own stresses.
TEST(TearCandidates, AClosedFanReadAsOneTearsAsItsSectorsMeanStress) {
  const ClothMesh mesh = grid(12);
  const std::vector<TriangleCorners> corners = triangleCorners(mesh);
  // Each triangle pulled its own way: the fans' sectors differ widely.
  std::vector<Mat2> stress(mesh.tris.size());
  for (std::size_t t = 0; t < stress.size(); ++t) {
    const double a = 0.9 * static_cast<double>(t);
    const Vec2 d(std::cos(a), std::sin(a));
    stress[t] = 400.0 * d * d.transpose() + 60.0 * Mat2::Identity();
  }
  TearTable table;
  table.strength = {12.0, 25.0, 35.0, 25.0};
  table.unitNPerM = 10.0;
  TearSearchSettings asOne;
  asOne.closedFanAsOne = true;
  std::vector<TearCandidate> found;
  TearSearchCounts counts;
  findTearCandidates(mesh, corners, stress, table, 0.3, asOne, found, counts);
  int interior = 0;
  for (const TearCandidate& line : found) {
    if (line.ray) continue;
    ++interior;
    // The mean over the vertex's triangles, weighted by its corner angle in each.
    Mat2 sum = Mat2::Zero();
    double spans = 0.0;
    for (int t = 0; t < mesh.triangleCount(); ++t) {
      const int k = cornerOf(mesh.tris[t], line.vertex);
      if (k == kNone) continue;
      sum += corners[t][k].span * stress[t];
      spans += corners[t][k].span;
    }
    const Mat2 mean = sum / spans;
    const Vec2 normal(-std::sin(line.angle), std::cos(line.angle));
    EXPECT_NEAR(line.separation, (mean * normal).norm(), 1e-9 * (mean * normal).norm()) << "vertex " << line.vertex;
    // No other line through the vertex does better against the table.
    for (double angle = 0.0; angle < kPi; angle += kPi / 360.0) {
      const Vec2 n(-std::sin(angle), std::cos(angle));
      const double ratio = (mean * n).norm() / requiredStrength(table, angleFromWarpDeg(angle, 0.3));
      EXPECT_LE(ratio, line.ratio * (1.0 + 1e-9)) << "vertex " << line.vertex << ", line at " << angle;
    }
  }
  EXPECT_GT(interior, 10);
}

TEST(TearSelection, TheThesisRatioExampleAWithTenOverEightBeatsBWithTwentyOverNineteen) {
  // Thesis §3.2: omega_A = 10 / 8 = 1.25 beats omega_B = 20 / 19 = 1.053, though B separates more.
  const ClothMesh mesh = grid(4);
  TearCandidate a, b;
  a.vertex = 7;
  a.separation = 10.0;
  a.required = 8.0;
  a.ratio = a.separation / a.required;
  b.vertex = 8;
  b.separation = 20.0;
  b.required = 19.0;
  b.ratio = b.separation / b.required;
  const std::vector<TearCandidate> chosen = selectTears({b, a}, TearSelectionSettings{});
  ASSERT_EQ(chosen.size(), 1u);
  EXPECT_EQ(chosen[0].vertex, 7);
}

TEST(TearSelection, SeveralTearsPerStepKeepTheirSpacingAndNothingBelowOneTears) {
  const ClothMesh mesh = grid(10);  // 1/9 m cells
  std::vector<TearCandidate> candidates;
  for (int v : {12, 13, 50, 88}) {
    TearCandidate c;
    c.vertex = v;
    c.restPosition = mesh.tris.empty() ? Vec2::Zero() : Vec2((v % 10) / 9.0, (v / 10) / 9.0);
    c.ratio = 2.0 - 0.01 * v;
    candidates.push_back(c);
  }
  candidates.push_back(candidates[0]);
  candidates.back().vertex = 99;
  candidates.back().restPosition = Vec2(1.0, 1.0);
  candidates.back().ratio = 0.9;
  TearSelectionSettings settings;
  settings.maxTearsPerStep = 10;
  settings.minSpacing = 0.25;
  const std::vector<TearCandidate> chosen = selectTears(candidates, settings);
  // 13 is a neighbour of 12 (1/9 m away): dropped; 99 is below 1.
  ASSERT_EQ(chosen.size(), 3u);
  EXPECT_EQ(chosen[0].vertex, 12);
  EXPECT_EQ(chosen[1].vertex, 50);
  EXPECT_EQ(chosen[2].vertex, 88);
}

// A table weak only at 30 degrees from V, on a cloth whose weft is turned by `weft`.
TearTable weakAtThirtyDegrees() {
  TearTable table;
  table.strength.assign(12, 300.0);
  table.strength[2] = 60.0;
  return table;
}

TEST(TearCandidates, TheFansOmegaBoundIsNeverBelowItsBestLine) {
  std::mt19937 rng(21);
  const TearTable table = weakAtThirtyDegrees();
  TearSearchSettings dense;
  dense.lines = CandidateLines::Dense;
  for (int trial = 0; trial < 200; ++trial) {
    const StressFan fan = test::randomFan(rng, trial % 2 == 0);
    const double weft = 0.1 * trial;
    TearSearchCounts counts;
    const double best = bestLineAt(fan, table, weft, dense, 1.0, counts).ratio;
    EXPECT_GE(omegaBoundAt(fan, table, weft, 1.0, counts), best) << "trial " << trial;
  }
}

TEST(TearCandidates, AnyLineAboveOneAgreesWithTheBestLine) {
  // The overload check of the incubation against the full search: the same answer wherever the
  // best line is not within the dense sampling's resolution of 1, and a line it finds is above 1.
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const TearTable table = weakAtThirtyDegrees();
  TearSearchSettings dense;
  dense.lines = CandidateLines::Dense;
  int above = 0, below = 0;
  for (int trial = 0; trial < 400; ++trial) {
    StressFan fan = test::randomFan(rng, trial % 2 == 0);
    const double weft = 0.1 * trial;
    TearSearchCounts counts;
    // Scaled so that the best line's omega lies between 0.8 and 1.2.
    const double scale = (0.8 + 0.4 * unit(rng)) / bestLineAt(fan, table, weft, dense, 1.0, counts).ratio;
    if (!std::isfinite(scale)) continue;
    for (FanSector& sector : fan.sectors) sector.stress *= scale;
    const double best = bestLineAt(fan, table, weft, dense, 1.0, counts).ratio;
    double angle = 0.0;
    const bool found = anyLineAboveOneAt(fan, table, weft, 0.0, angle, counts);
    if (found) {
      EXPECT_GT(separationStrength(fan, angle) / requiredStrength(table, angleFromWarpDeg(angle, weft)), 1.0);
    }
    if (std::abs(best - 1.0) < 1e-3) continue;
    EXPECT_EQ(found, best > 1.0) << "trial " << trial << ": best line's omega " << best;
    (best > 1.0 ? above : below)++;
  }
  EXPECT_GT(above, 100);
  EXPECT_GT(below, 100);
}

}  // namespace
}  // namespace weft
