#include "tearing/separation_strength.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "support/random_fan.h"

#include <Eigen/Eigenvalues>

#include "tearing/tensile_stress.h"

namespace weft {
namespace {

constexpr double kPi = std::numbers::pi;

// A closed fan of n equal sectors starting at `offset`, all with the same stress.
StressFan regularFan(int n, const Mat2& stress, double offset = 0.1) {
  StressFan fan;
  for (int k = 0; k < n; ++k) fan.sectors.push_back(makeSector(offset + 2.0 * kPi * k / n, 2.0 * kPi / n, stress));
  fan.closed = true;
  fan.openSpan = 2.0 * kPi;
  return fan;
}

// A border vertex on a straight border along x, material below it (angles from pi to 2 pi).
StressFan borderFan(int n, const Mat2& stress) {
  StressFan fan;
  for (int k = 0; k < n; ++k) fan.sectors.push_back(makeSector(kPi + kPi * k / n, kPi / n, stress));
  fan.closed = false;
  fan.openStart = kPi;
  fan.openSpan = kPi;
  return fan;
}

Mat2 uniaxial(double tension, double angle) {
  const Vec2 d(std::cos(angle), std::sin(angle));
  return tension * d * d.transpose();
}

TEST(SeparationStrength, UniformStressGivesTheTractionAcrossTheLine) {
  // Eq. 2.69-2.71 normalized: zeta = |sigma n| for any fan of a uniform stress.
  const double T = 300.0;
  for (int sectors : {5, 6, 8, 13}) {
    const StressFan fan = regularFan(sectors, uniaxial(T, 0.0));
    for (double beta = 0.0; beta < kPi; beta += 0.1) {
      EXPECT_NEAR(separationStrength(fan, beta), T * std::abs(std::sin(beta)), 1e-9 * T)
          << sectors << " sectors, line at " << beta;
    }
  }
  const StressFan isotropic = regularFan(6, 50.0 * Mat2::Identity());
  for (double beta = 0.0; beta < kPi; beta += 0.3) EXPECT_NEAR(separationStrength(isotropic, beta), 50.0, 1e-9);
}

TEST(SeparationStrength, LinePerpendicularToThePullSeparatesMost) {
  const StressFan fan = regularFan(6, uniaxial(100.0, 0.7));
  const double across = separationStrength(fan, 0.7 + kPi / 2);
  EXPECT_NEAR(across, 100.0, 1e-9);
  EXPECT_NEAR(separationStrength(fan, 0.7), 0.0, 1e-9) << "a line along the pull relieves nothing";
  for (double beta = 0.0; beta < kPi; beta += 0.05) EXPECT_LE(separationStrength(fan, beta), across + 1e-9);
}

TEST(SeparationStrength, ABorderRayCountsOnce) {
  // Tension along the border: the ray straight into the cloth opens it with the full traction.
  const StressFan fan = borderFan(4, uniaxial(80.0, 0.0));
  EXPECT_NEAR(separationStrength(fan, 1.5 * kPi), 80.0, 1e-9);
  // Along the border itself nothing is on one side.
  EXPECT_NEAR(separationStrength(fan, kPi + 1e-12), 0.0, 1e-6);
}

TEST(SeparationStrength, CompressionAndUnbalancedLoadsDoNotSeparate) {
  // sigma+ removes compression: a compressed fan has no tensile stress at all.
  const Mat2 compressed = tensilePart(-200.0 * Mat2::Identity());
  EXPECT_TRUE(compressed.isZero());
  // Only one side pulls (its sectors stressed, the other side's free): an unbalanced load.
  StressFan fan = regularFan(6, Mat2::Zero(), 0.0);
  for (int k = 0; k < 3; ++k) fan.sectors[k].stress = uniaxial(100.0, kPi / 2);
  EXPECT_DOUBLE_EQ(separationStrength(fan, 0.0), 0.0);
}

TEST(SeparationStrength, TensilePartKeepsOnlyPositivePrincipalStresses) {
  Mat2 s;
  s << 100.0, 30.0, 30.0, -50.0;
  const Mat2 plus = tensilePart(s);
  const Eigen::SelfAdjointEigenSolver<Mat2> eigen(plus);
  EXPECT_NEAR(eigen.eigenvalues()[0], 0.0, 1e-9);
  EXPECT_GT(eigen.eigenvalues()[1], 100.0);
  // The kept principal direction is the original's tensile one.
  const Eigen::SelfAdjointEigenSolver<Mat2> original(s);
  EXPECT_NEAR(std::abs(eigen.eigenvectors().col(1).dot(original.eigenvectors().col(1))), 1.0, 1e-12);
}

TEST(SeparationStrength, StressTurnsWithTheWeftAngle) {
  // A pull along the weft U at 30 degrees from material x is a pull at 30 degrees in material space.
  const Mat2 s = stressInMaterialFrame(Vec3(120.0, 0.0, 0.0), 30.0 * kPi / 180.0);
  EXPECT_TRUE(s.isApprox(uniaxial(120.0, 30.0 * kPi / 180.0), 1e-12));
}

TEST(SeparationStrength, TheBoundIsNeverExceeded) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const bool closed = trial % 2 == 0;
    const StressFan fan = test::randomFan(rng, closed);
    const double total = fan.openSpan;
    const double bound = separationStrengthBound(fan);
    for (int k = 1; k < 100; ++k) {
      const double line = closed ? kPi * k / 100.0 : fan.openStart + total * k / 100.0;
      EXPECT_LE(separationStrength(fan, line), bound * (1.0 + 1e-12)) << "trial " << trial;
    }
  }
}

// At a straight border under an averaged load (sectors within a few percent of one stress, as the average leaves them), the
// bound is about the largest traction across a ray, not the 1.41 times it that the chord of a
// quarter circle gives; and it still holds on fans a little wider or narrower than a half turn.
TEST(SeparationStrength, TheBoundOfANearlyStraightBorderIsAboutTheTractionAcrossIt) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double along = 300.0 * (0.5 + unit(rng));  // the pull along the border
    const double across = along * 0.3 * unit(rng);
    const Mat2 mean = uniaxial(along, 0.0) + uniaxial(across, 0.5 * kPi);
    const int n = 2 + trial % 4;
    const double total = kPi * (1.0 + 0.02 * (unit(rng) - 0.5));
    StressFan fan;
    fan.closed = false;
    fan.openStart = kPi;  // the border along x, the cloth below it
    fan.openSpan = total;
    double angle = fan.openStart;
    for (int k = 0; k < n; ++k) {
      Mat2 wobble;
      wobble << unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5;
      fan.sectors.push_back(makeSector(angle, total / n, tensilePart(mean + 0.02 * along * (wobble + wobble.transpose()))));
      angle += total / n;
    }
    const double bound = separationStrengthBound(fan);
    double largest = 0.0;
    for (int k = 1; k < 400; ++k) {
      const double zeta = separationStrength(fan, fan.openStart + total * k / 400.0);
      EXPECT_LE(zeta, bound * (1.0 + 1e-12)) << "trial " << trial;
      largest = std::max(largest, zeta);
    }
    EXPECT_LE(bound, 1.25 * largest) << "trial " << trial;
  }
}

TEST(SeparationStrength, TheBoundNearALineHoldsForEveryLineWithinItsDrift) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const StressFan fan = test::randomFan(rng, trial % 2 == 0);
    const double halfWidth = 0.001 + 0.3 * unit(rng);
    // The piece's middle, far enough inside an open fan that the whole piece is.
    const double middle = fan.closed ? kPi * unit(rng)
                                     : fan.openStart + halfWidth + (fan.openSpan - 2.0 * halfWidth) * unit(rng);
    if (!fan.closed && fan.openSpan < 2.0 * halfWidth) continue;
    const double bound = separationBoundNear(fan, lineSides(fan, middle), sideForceRate(fan) * halfWidth);
    for (int k = 0; k <= 40; ++k) {
      const double line = middle - halfWidth + 2.0 * halfWidth * k / 40.0;
      EXPECT_LE(separationStrength(fan, line), bound) << "trial " << trial << ", line " << k;
    }
  }
}

TEST(SeparationStrength, ThePiecesBoundHoldsForEveryLineOfThePiece) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int explicitPieces = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const StressFan fan = test::randomFan(rng, trial % 2 == 0);
    const double halfWidth = 0.0005 + 0.3 * unit(rng) * unit(rng);
    if (!fan.closed && fan.openSpan < 2.0 * halfWidth) continue;
    const double middle = fan.closed ? kPi * unit(rng)
                                     : fan.openStart + halfWidth + (fan.openSpan - 2.0 * halfWidth) * unit(rng);
    const LinePieceBound piece = separationOverPiece(fan, middle, halfWidth);
    EXPECT_NEAR(piece.zeta, separationStrength(fan, middle), 1e-12 * (1.0 + piece.zeta));
    if (!std::isfinite(piece.edge)) ++explicitPieces;
    for (int k = 0; k <= 40; ++k) {
      const double line = middle - halfWidth + 2.0 * halfWidth * k / 40.0;
      EXPECT_LE(separationStrength(fan, line), piece.bound) << "trial " << trial << ", line " << k;
    }
  }
  EXPECT_GT(explicitPieces, 200);
}

TEST(SeparationStrength, UnderAUniformLoadThePiecesBoundIsOfSecondOrderInItsWidth) {
  // Uneven sectors, one stress: zeta peaks across the pull, where the bound must not exceed the
  // piece's largest zeta by more than a multiple of the width squared (a drift bound exceeds it by
  // sigma times the width).
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    StressFan fan = test::randomFan(rng, true);
    const double pull = 2.0 * kPi * unit(rng);
    const Mat2 sigma = uniaxial(100.0, pull);
    for (FanSector& sector : fan.sectors) sector.stress = sigma;
    for (const double halfWidth : {0.04, 0.02, 0.01}) {
      const double middle = pull + 0.5 * kPi + halfWidth * (unit(rng) - 0.5);  // across the pull
      const LinePieceBound piece = separationOverPiece(fan, middle, halfWidth);
      if (std::isfinite(piece.edge)) continue;
      double largest = 0.0;
      for (int k = 0; k <= 40; ++k) {
        largest = std::max(largest, separationStrength(fan, middle - halfWidth + 2.0 * halfWidth * k / 40.0));
      }
      EXPECT_LE(piece.bound - largest, 100.0 * halfWidth * halfWidth) << "trial " << trial << ", half width " << halfWidth;
    }
  }
}

TEST(SeparationStrength, TheBoundNearALineTendsToItsSeparation) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 100; ++trial) {
    const StressFan fan = test::randomFan(rng, trial % 2 == 0);
    const double line = fan.closed ? 1.0 : fan.openStart + 0.5 * fan.openSpan;
    const LineSides sides = lineSides(fan, line);
    EXPECT_NEAR(separationBoundNear(fan, sides, 0.0), separationStrength(fan, line),
                1e-8 * (1.0 + separationStrength(fan, line)));
    EXPECT_NEAR(separationFromSides(fan, sides), separationStrength(fan, line), 1e-12);
  }
}


// A closed fan whose sectors all read one stress S (the vertex's averaged stress) is read as S
// alone: zeta = |S n| without the sectors, as the sectors give it; the bound over a piece of lines
// is the largest |S n| in it (exact, not of second order), and never below a line of the piece.
TEST(SeparationStrength, AUniformFanReadsTheTractionAcrossEachLineAsItsSectorsDo) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    StressFan bySectors = test::randomFan(rng, true);
    const Mat2 stress = tensilePart(uniaxial(300.0 * unit(rng), 2.0 * kPi * unit(rng)) +
                                    uniaxial(100.0 * unit(rng), 2.0 * kPi * unit(rng)));
    for (FanSector& sector : bySectors.sectors) sector.stress = stress;
    StressFan uniform = bySectors;
    makeUniform(uniform, stress);
    ASSERT_TRUE(uniform.uniform);
    EXPECT_NEAR(separationStrengthBound(uniform), spectralNorm(stress), 1e-12 * (1.0 + spectralNorm(stress)));
    for (double beta = 0.0; beta < kPi; beta += 0.05) {
      EXPECT_NEAR(separationStrength(uniform, beta), separationStrength(bySectors, beta), 1e-9 * (1.0 + spectralNorm(stress)))
          << "trial " << trial << ", line at " << beta;
      EXPECT_LE(separationStrength(uniform, beta), separationStrengthBound(uniform) * (1.0 + 1e-12));
    }
    for (const double halfWidth : {0.3, 0.05, 0.001}) {
      const double middle = kPi * unit(rng);
      const LinePieceBound piece = separationOverPiece(uniform, middle, halfWidth);
      EXPECT_FALSE(std::isfinite(piece.edge));  // no sector edges to split at
      EXPECT_NEAR(piece.zeta, separationStrength(uniform, middle), 1e-12 * (1.0 + piece.zeta));
      double largest = 0.0;
      for (int k = 0; k <= 400; ++k) {
        largest = std::max(largest, separationStrength(uniform, middle - halfWidth + 2.0 * halfWidth * k / 400.0));
      }
      EXPECT_GE(piece.bound, largest) << "trial " << trial << ", half width " << halfWidth;
      // Exact: within the sampling's own error of the largest line (a sample is at most
      // halfWidth / 400 from the peak, where |S n| is flat to second order).
      EXPECT_LE(piece.bound - largest, 1e-6 * (1.0 + largest) + spectralNorm(stress) * std::pow(halfWidth / 400.0, 2))
          << "trial " << trial << ", half width " << halfWidth;
    }
  }
}

}  // namespace
}  // namespace weft
