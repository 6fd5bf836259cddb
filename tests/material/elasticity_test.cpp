// The membrane law: derivatives against finite differences, the isotropic matrix of thesis
// Eq. 2.11, and the measured model's interpolation at the sample points (FORMAT.md rows).
#include "material/elasticity.h"

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "material/material.h"

namespace weft {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

ElasticitySettings measuredFabric(const std::string& name) {
  return loadMaterialFile(std::string(WEFT_SOURCE_DIR) + "/presets/materials/" + name + ".json").elasticity;
}

ElasticitySettings isotropic(double youngModulus, double poissonRatio) {
  ElasticitySettings s;
  s.model = ElasticitySettings::Model::Isotropic;
  s.youngModulus = youngModulus;
  s.poissonRatio = poissonRatio;
  return s;
}

// Green strain (e_uu, e_vv, g) of a uniaxial stretch lambda along the direction at angleDeg from U:
// F = I + (lambda - 1) n n^T, so G = 1/2 (lambda^2 - 1) n n^T and g = 2 G_uv.
Vector3d uniaxialStrain(double lambda, double angleDeg) {
  const double a = angleDeg * kPi / 180.0;
  const double k = 0.5 * (lambda * lambda - 1.0);
  return {k * std::cos(a) * std::cos(a), k * std::sin(a) * std::sin(a), 2.0 * k * std::cos(a) * std::sin(a)};
}

// The file row mapped onto (e_uu, e_vv, g): [[2c11, 2c12, 0], [2c12, 2c22, 0], [0, 0, c33]].
Matrix3d mapped(double c11, double c12, double c22, double c33) {
  Matrix3d m;
  m << 2 * c11, 2 * c12, 0, 2 * c12, 2 * c22, 0, 0, 0, c33;
  return m;
}

Matrix3d mappedClamped(const StretchCoefficients& c) {
  return mapped(std::max(c[0], 0.0), std::max(c[1], 0.0), std::max(c[2], 0.0), std::max(c[3], 0.0));
}

// Strain states away from every kink (fold at 0/90 deg, row knots, clamps of s, d = 0).
struct StrainCase {
  std::string label;
  Vector3d strain;
};

std::vector<StrainCase> strainCases() {
  return {
      {"uniaxial along U", {0.05, 0.0, 1e-3}},
      {"uniaxial along V", {0.0, 0.05, 1e-3}},
      {"uniaxial at 30 deg", uniaxialStrain(1.08, 30.0)},
      {"uniaxial at -50 deg", uniaxialStrain(1.1, -50.0)},
      {"biaxial unequal", {0.06, 0.02, 0.004}},
      {"mostly shear", {0.01, 0.005, 0.08}},
      {"negative shear", {0.02, 0.035, -0.05}},
      {"beyond the reference stretch", {0.2, 0.03, 0.05}},
      {"beyond the reference stretch along V", {0.01, 0.3, -0.02}},
      {"compression", {-0.03, -0.01, 0.005}},
      {"stretch and compression", {0.04, -0.03, 0.01}},
      {"near equibiaxial inside the blend", {0.051, 0.048, 0.004}},
      {"near equibiaxial, other side", {0.040, 0.043, -0.002}},
      {"near equibiaxial beyond reference", {0.2, 0.196, 0.003}},
  };
}

double energyAt(const ElasticitySettings& s, const Vector3d& e) { return evaluateElasticity(s, e, false).energyDensity; }

void expectDerivativesMatchFiniteDifferences(const ElasticitySettings& settings, const std::string& what) {
  constexpr double step = 1e-6;
  constexpr double tolerance = 1e-5;
  for (const StrainCase& c : strainCases()) {
    SCOPED_TRACE(what + ", " + c.label);
    const ElasticityResponse r = evaluateElasticity(settings, c.strain, true);
    Vector3d fdStress;
    Matrix3d fdTangent;
    for (int i = 0; i < 3; ++i) {
      Vector3d plus = c.strain, minus = c.strain;
      plus[i] += step;
      minus[i] -= step;
      fdStress[i] = (energyAt(settings, plus) - energyAt(settings, minus)) / (2 * step);
      fdTangent.col(i) = (evaluateElasticity(settings, plus, false).stress -
                          evaluateElasticity(settings, minus, false).stress) / (2 * step);
    }
    EXPECT_LE((fdStress - r.stress).norm(), tolerance * r.stress.norm())
        << "stress " << r.stress.transpose() << "\nfinite differences " << fdStress.transpose();
    EXPECT_LE((fdTangent - r.tangent).norm(), tolerance * r.tangent.norm())
        << "tangent\n" << r.tangent << "\nfinite differences\n" << fdTangent;
    EXPECT_LE((r.tangent - r.tangent.transpose()).norm(), 1e-12 * r.tangent.norm());
  }
}

const std::vector<std::string> kFabrics{"royal-target",      "11oz-black-denim", "gray-interlock",
                                        "navy-sparkle-sweat", "white-swim-solid", "tango-red-jet-set",
                                        "camel-ponte-roma"};

TEST(Elasticity, IsotropicDerivativesMatchFiniteDifferences) {
  expectDerivativesMatchFiniteDifferences(isotropic(5000.0, 0.3), "isotropic");
}

TEST(Elasticity, MeasuredDerivativesMatchFiniteDifferences) {
  for (const std::string& fabric : kFabrics) expectDerivativesMatchFiniteDifferences(measuredFabric(fabric), fabric);
  ElasticitySettings scaled = measuredFabric("gray-interlock");
  scaled.stiffnessScale = 3.5;
  expectDerivativesMatchFiniteDifferences(scaled, "gray-interlock scaled");
}

TEST(Elasticity, ZeroStrainHasNoEnergyAndNoStress) {
  std::vector<ElasticitySettings> models{isotropic(5000.0, 0.3)};
  for (const std::string& fabric : kFabrics) models.push_back(measuredFabric(fabric));
  for (const ElasticitySettings& s : models) {
    const ElasticityResponse r = evaluateElasticity(s, Vector3d::Zero(), true);
    EXPECT_EQ(r.energyDensity, 0.0);
    EXPECT_EQ(r.stress, Vector3d::Zero());
    EXPECT_TRUE(r.tangent.allFinite());
  }
}

TEST(Elasticity, IsotropicIsThesisEquation2_11) {
  const double eh = 5000.0, nu = 0.3;
  ElasticitySettings s = isotropic(eh, nu);
  Matrix3d expected;
  const double f = eh / (1 - nu * nu);
  expected << f, f * nu, 0, f * nu, f, 0, 0, 0, f * (1 - nu) / 2;
  const Vector3d e(0.03, -0.01, 0.02);
  EXPECT_LE((elasticityMatrix(s, e) - expected).norm(), 1e-12 * expected.norm());
  const ElasticityResponse r = evaluateElasticity(s, e, true);
  EXPECT_LE((r.tangent - expected).norm(), 1e-12 * expected.norm());
  EXPECT_LE((r.stress - expected * e).norm(), 1e-12 * (expected * e).norm());  // Eq. 2.12
  EXPECT_NEAR(r.energyDensity, 0.5 * e.dot(expected * e), 1e-12);

  s.stiffnessScale = 2.0;
  EXPECT_LE((elasticityMatrix(s, e) - 2.0 * expected).norm(), 1e-12 * expected.norm());
}

TEST(Elasticity, MeasuredAtSmallStrainIsTheZeroStrainRow) {
  for (const std::string& fabric : kFabrics) {
    SCOPED_TRACE(fabric);
    const ElasticitySettings s = measuredFabric(fabric);
    const Matrix3d row0 = mappedClamped(s.measured.zeroStrain);
    // Largest principal stretch <= 1: exactly row 0.
    EXPECT_EQ(elasticityMatrix(s, Vector3d(-0.02, -0.01, 0.003)), row0);
    EXPECT_EQ(elasticityMatrix(s, Vector3d::Zero()), row0);
    const ElasticityResponse r = evaluateElasticity(s, Vector3d(-0.02, -0.01, 0.003), true);
    EXPECT_LE((r.tangent - row0).norm(), 1e-12 * row0.norm());
    // A tiny stretch: row 0 up to the tiny interpolation weight.
    EXPECT_LE((elasticityMatrix(s, uniaxialStrain(1.0 + 1e-9, 30.0)) - row0).norm(), 1e-6 * row0.norm());
  }
}

TEST(Elasticity, MeasuredBeyondReferenceStretchIsTheDirectionRow) {
  const double lambda = 1.25;  // beyond the reference stretch 7/6
  for (const std::string& fabric : kFabrics) {
    SCOPED_TRACE(fabric);
    const ElasticitySettings s = measuredFabric(fabric);
    const auto& rows = s.measured.directions;
    const auto check = [&](double angleDeg, const StretchCoefficients& row) {
      SCOPED_TRACE("angle " + std::to_string(angleDeg));
      StretchCoefficients limited = row;  // the c12 guard (exercised on its own below)
      for (double& c : limited) c = std::max(c, 0.0);
      limited[1] = std::min(limited[1], 0.95 * std::sqrt(limited[0] * limited[2]));
      const Matrix3d expected = mapped(limited[0], limited[1], limited[2], limited[3]);
      EXPECT_LE((elasticityMatrix(s, uniaxialStrain(lambda, angleDeg)) - expected).norm(), 1e-9 * expected.norm());
    };
    check(0.0, rows[0]);
    check(22.5, rows[1]);
    check(45.0, rows[2]);
    check(67.5, rows[3]);
    check(90.0, rows[4]);
  }
  // Negative samples count as 0: gray-interlock's 0 and 67.5 deg rows have negative c33.
  const ElasticitySettings gray = measuredFabric("gray-interlock");
  EXPECT_EQ(elasticityMatrix(gray, uniaxialStrain(lambda, 0.0))(2, 2), 0.0);
  EXPECT_EQ(elasticityMatrix(gray, uniaxialStrain(lambda, 67.5))(2, 2), 0.0);
  EXPECT_EQ(elasticityMatrix(gray, Vector3d::Zero())(0, 1), 0.0);  // row 0 has c12 < 0
}

TEST(Elasticity, MeasuredLinearBetweenDirectionRows) {
  const ElasticitySettings s = measuredFabric("11oz-black-denim");
  const auto& rows = s.measured.directions;
  const double f = (30.0 - 22.5) / 22.5;
  StretchCoefficients blend;
  for (int k = 0; k < 4; ++k) blend[k] = (1 - f) * rows[1][k] + f * rows[2][k];
  const Matrix3d expected = mapped(blend[0], blend[1], blend[2], blend[3]);
  EXPECT_LE((elasticityMatrix(s, uniaxialStrain(1.25, 30.0)) - expected).norm(), 1e-9 * expected.norm());
  // Halfway to the reference stretch: halfway between row 0 and that blend.
  const Matrix3d row0 = mappedClamped(s.measured.zeroStrain);
  const Matrix3d half = elasticityMatrix(s, uniaxialStrain(1.0 + 0.5 / 6.0, 30.0));
  EXPECT_LE((half - 0.5 * (row0 + expected)).norm(), 1e-9 * expected.norm());
}

TEST(Elasticity, MeasuredCouplingIsLimitedForStability) {
  // navy-sparkle-sweat at 22.5 deg: c12 = 94.126335 > sqrt(48.565407 * 180.101227).
  const ElasticitySettings s = measuredFabric("navy-sparkle-sweat");
  const StretchCoefficients& row = s.measured.directions[1];
  const Matrix3d c = elasticityMatrix(s, uniaxialStrain(1.25, 22.5));
  EXPECT_NEAR(c(0, 1), 2 * 0.95 * std::sqrt(row[0] * row[2]), 1e-9 * c(0, 1));
  const double determinant = c.topLeftCorner<2, 2>().determinant();
  EXPECT_GT(determinant, 0.0);
}

TEST(Elasticity, MeasuredEquibiaxialUsesTheDirectionMean) {
  // At an equibiaxial strain the principal direction is undefined: C is row 0 blended with the
  // mean of the direction rows (trapezoid weights 1/8, 1/4, 1/4, 1/4, 1/8), never one row.
  const ElasticitySettings s = measuredFabric("gray-interlock");
  Matrix3d mean = Matrix3d::Zero();
  const double weights[5] = {0.125, 0.25, 0.25, 0.25, 0.125};
  for (int i = 0; i < 5; ++i) mean += weights[i] * mappedClamped(s.measured.directions[i]);
  EXPECT_LE((elasticityMatrix(s, Vector3d(0.2, 0.2, 0.0)) - mean).norm(), 1e-9 * mean.norm());
  // Approaching the equibiaxial line from two different directions gives the same C.
  const Matrix3d a = elasticityMatrix(s, Vector3d(0.2 + 1e-7, 0.2, 0.0));
  const Matrix3d b = elasticityMatrix(s, Vector3d(0.2, 0.2, 1e-7));
  EXPECT_LE((a - mean).norm(), 1e-6 * mean.norm());
  EXPECT_LE((b - mean).norm(), 1e-6 * mean.norm());
}

TEST(Elasticity, MeasuredIsMirrorSymmetricAboutU) {
  for (const std::string& fabric : kFabrics) {
    SCOPED_TRACE(fabric);
    const ElasticitySettings s = measuredFabric(fabric);
    for (double angle : {10.0, 30.0, 60.0, 80.0}) {
      SCOPED_TRACE("angle " + std::to_string(angle));
      const Vector3d e = uniaxialStrain(1.12, angle);
      const Vector3d mirrored(e[0], e[1], -e[2]);  // principal direction at -angle
      EXPECT_LE((elasticityMatrix(s, e) - elasticityMatrix(s, mirrored)).norm(), 1e-12 * elasticityMatrix(s, e).norm());
      // A direction at 180 - angle is the same line as -angle: folded, not clamped to 90 deg.
      EXPECT_LE((elasticityMatrix(s, uniaxialStrain(1.12, 180.0 - angle)) - elasticityMatrix(s, e)).norm(),
                1e-9 * elasticityMatrix(s, e).norm());
      const ElasticityResponse r = evaluateElasticity(s, e, true);
      const ElasticityResponse m = evaluateElasticity(s, mirrored, true);
      EXPECT_NEAR(r.energyDensity, m.energyDensity, 1e-12 * r.energyDensity);
      EXPECT_NEAR(r.stress[0], m.stress[0], 1e-12 * r.stress.norm());
      EXPECT_NEAR(r.stress[1], m.stress[1], 1e-12 * r.stress.norm());
      EXPECT_NEAR(r.stress[2], -m.stress[2], 1e-12 * r.stress.norm());
      const Matrix3d flip = Vector3d(1, 1, -1).asDiagonal();
      EXPECT_LE((r.tangent - flip * m.tangent * flip).norm(), 1e-12 * r.tangent.norm());
    }
  }
}

TEST(Elasticity, StiffnessScaleMultipliesEverything) {
  ElasticitySettings s = measuredFabric("royal-target");
  const Vector3d e(0.05, 0.02, 0.01);
  const ElasticityResponse base = evaluateElasticity(s, e, true);
  s.stiffnessScale = 2.5;
  const ElasticityResponse scaled = evaluateElasticity(s, e, true);
  EXPECT_NEAR(scaled.energyDensity, 2.5 * base.energyDensity, 1e-12 * scaled.energyDensity);
  EXPECT_LE((scaled.stress - 2.5 * base.stress).norm(), 1e-12 * scaled.stress.norm());
  EXPECT_LE((scaled.tangent - 2.5 * base.tangent).norm(), 1e-12 * scaled.tangent.norm());
}

}  // namespace
}  // namespace weft
