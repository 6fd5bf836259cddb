// The membrane element against its energy, its Jacobian against its forces, and a patch test.
#include "forces/membrane.h"

#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "material/material.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

Triangle restTriangle(Vec2 a, Vec2 b, Vec2 c) {
  Triangle t;
  t.v = {0, 1, 2};
  t.rest = {a, b, c};
  return t;
}

std::vector<ElasticitySettings> materialsUnderTest() {
  std::vector<ElasticitySettings> out;
  out.push_back(test::isotropicMaterial(3000.0, 0.3).elasticity);
  for (const char* name : {"royal-target", "gray-interlock", "11oz-black-denim"})
    out.push_back(loadMaterialFile(test::presetPath(name)).elasticity);
  return out;
}

// Deformed states: stretched, sheared, compressed, rotated, out of plane.
std::vector<std::array<Vec3, 3>> deformedStates(const Triangle& t) {
  std::vector<std::array<Vec3, 3>> states;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.03, 0.03);
  const double scales[][3] = {{1.1, 1.0, 0.0}, {1.0, 1.15, 0.05}, {1.2, 1.1, -0.1}, {0.9, 1.05, 0.2}, {1.25, 0.95, 0.0}};
  for (const auto& s : scales) {
    std::array<Vec3, 3> x;
    for (int k = 0; k < 3; ++k) {
      const Vec2& p = t.rest[k];
      x[k] = Vec3(s[0] * p.x() + s[2] * p.y(), s[1] * p.y(), 0.3 * p.x() * p.y());
      x[k] += Vec3(jitter(rng), jitter(rng), jitter(rng)) * 0.1;
    }
    states.push_back(x);
  }
  return states;
}

double energyAt(const MembraneElement& e, const ElasticitySettings& m, const std::array<Vec3, 3>& x) {
  return evaluateMembrane(e, m, x[0], x[1], x[2], HessianMode::None).energy;
}

TEST(Membrane, ForceIsMinusEnergyGradient) {
  const Triangle t = restTriangle({0.0, 0.0}, {0.1, 0.01}, {0.02, 0.09});
  for (double weft : {0.0, 0.4}) {
    const MembraneElement element = makeMembraneElement(t, weft);
    for (const ElasticitySettings& material : materialsUnderTest()) {
      for (auto x : deformedStates(t)) {
        const MembraneResult r = evaluateMembrane(element, material, x[0], x[1], x[2], HessianMode::None);
        const double h = 1e-7;
        for (int i = 0; i < 9; ++i) {
          auto xp = x, xm = x;
          xp[i / 3][i % 3] += h;
          xm[i / 3][i % 3] -= h;
          const double fd = -(energyAt(element, material, xp) - energyAt(element, material, xm)) / (2 * h);
          EXPECT_NEAR(r.force[i], fd, 1e-5 * (1.0 + r.force.cwiseAbs().maxCoeff())) << "dof " << i;
        }
      }
    }
  }
}

TEST(Membrane, ExactHessianIsMinusForceJacobian) {
  const Triangle t = restTriangle({0.0, 0.0}, {0.1, 0.0}, {0.03, 0.1});
  const MembraneElement element = makeMembraneElement(t, 0.3);
  for (const ElasticitySettings& material : materialsUnderTest()) {
    for (auto x : deformedStates(t)) {
      const MembraneResult r = evaluateMembrane(element, material, x[0], x[1], x[2], HessianMode::Exact);
      const double h = 1e-7;
      for (int j = 0; j < 9; ++j) {
        auto xp = x, xm = x;
        xp[j / 3][j % 3] += h;
        xm[j / 3][j % 3] -= h;
        const auto fp = evaluateMembrane(element, material, xp[0], xp[1], xp[2], HessianMode::None).force;
        const auto fm = evaluateMembrane(element, material, xm[0], xm[1], xm[2], HessianMode::None).force;
        const Eigen::Matrix<double, 9, 1> column = -(fp - fm) / (2 * h);
        EXPECT_LT((r.hessian.col(j) - column).norm(), 1e-4 * (1.0 + r.hessian.norm())) << "column " << j;
      }
    }
  }
}

TEST(Membrane, DefiniteHessianIsPositiveSemiDefiniteAndExactInTension) {
  const Triangle t = restTriangle({0.0, 0.0}, {0.1, 0.0}, {0.0, 0.1});
  const MembraneElement element = makeMembraneElement(t, 0.0);
  const ElasticitySettings iso = test::isotropicMaterial(3000.0, 0.3).elasticity;
  for (const ElasticitySettings& material : materialsUnderTest()) {
    for (auto x : deformedStates(t)) {
      const MembraneResult r = evaluateMembrane(element, material, x[0], x[1], x[2], HessianMode::Definite);
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> eig(r.hessian);
      EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-9 * r.hessian.norm());
    }
  }
  // Biaxial tension with an isotropic (convex, constant) material: nothing to clamp.
  std::array<Vec3, 3> x = {Vec3(0, 0, 0), Vec3(0.11, 0, 0), Vec3(0, 0.105, 0)};
  const auto exact = evaluateMembrane(element, iso, x[0], x[1], x[2], HessianMode::Exact).hessian;
  const auto definite = evaluateMembrane(element, iso, x[0], x[1], x[2], HessianMode::Definite).hessian;
  EXPECT_LT((exact - definite).norm(), 1e-9 * exact.norm());
}

TEST(Membrane, NoForceUnderRigidMotion) {
  const Triangle t = restTriangle({0.0, 0.0}, {0.1, 0.02}, {0.03, 0.08});
  const MembraneElement element = makeMembraneElement(t, 0.7);
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.8, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(2.0, Vec3::UnitZ())).toRotationMatrix();
  const Vec3 translation(3.0, -2.0, 5.0);
  for (const ElasticitySettings& material : materialsUnderTest()) {
    std::array<Vec3, 3> x;
    for (int k = 0; k < 3; ++k) x[k] = rotation * Vec3(t.rest[k].x(), t.rest[k].y(), 0.0) + translation;
    const MembraneResult r = evaluateMembrane(element, material, x[0], x[1], x[2], HessianMode::None);
    EXPECT_NEAR(r.energy, 0.0, 1e-15);
    EXPECT_LT(r.force.norm(), 1e-9);
    EXPECT_LT(r.strain.norm(), 1e-12);
  }
}

TEST(Membrane, ForcesSumToZero) {
  const Triangle t = restTriangle({0.0, 0.0}, {0.1, 0.02}, {0.03, 0.08});
  const MembraneElement element = makeMembraneElement(t, 0.2);
  for (const ElasticitySettings& material : materialsUnderTest())
    for (auto x : deformedStates(t)) {
      const MembraneResult r = evaluateMembrane(element, material, x[0], x[1], x[2], HessianMode::None);
      const Vec3 sum = r.force.segment<3>(0) + r.force.segment<3>(3) + r.force.segment<3>(6);
      EXPECT_LT(sum.norm(), 1e-9 * (1.0 + r.force.norm()));
      Vec3 torque = Vec3::Zero();
      for (int k = 0; k < 3; ++k) torque += x[k].cross(Vec3(r.force.segment<3>(3 * k)));
      EXPECT_LT(torque.norm(), 1e-9 * (1.0 + r.force.norm()));
    }
}

// Uniaxial stretch of a patch of triangles along U: uniform strain, sigma = C eps, no force on
// interior vertices, and the boundary forces add up to the traction the stress implies.
TEST(Membrane, UniaxialPatchTestMatchesSigmaEqualsCEpsilon) {
  const int n = 4;
  const double size = 0.3, stretch = 1.08;
  std::vector<Vec2> rest;
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) rest.emplace_back(size * ix / (n - 1), size * iy / (n - 1));
  std::vector<Vec3> x(rest.size());
  for (size_t i = 0; i < rest.size(); ++i) x[i] = Vec3(stretch * rest[i].x(), rest[i].y(), 0.0);
  std::vector<Vec3> force(rest.size(), Vec3::Zero());
  const ElasticitySettings material = test::isotropicMaterial(4000.0, 0.25).elasticity;
  for (int iy = 0; iy + 1 < n; ++iy)
    for (int ix = 0; ix + 1 < n; ++ix) {
      const int a = iy * n + ix, b = a + 1, c = a + n, d = c + 1;
      for (const std::array<int, 3>& tri : {std::array<int, 3>{a, b, d}, std::array<int, 3>{a, d, c}}) {
        Triangle t = restTriangle(rest[tri[0]], rest[tri[1]], rest[tri[2]]);
        t.v = tri;
        const MembraneElement element = makeMembraneElement(t, 0.0);
        const MembraneResult r = evaluateMembrane(element, material, x[tri[0]], x[tri[1]], x[tri[2]], HessianMode::None);
        const double eUU = 0.5 * (stretch * stretch - 1.0);
        EXPECT_NEAR(r.strain[0], eUU, 1e-12);
        EXPECT_NEAR(r.strain[1], 0.0, 1e-12);
        EXPECT_NEAR(r.strain[2], 0.0, 1e-12);
        // Eq. 2.11-2.12.
        const double k = 4000.0 / (1.0 - 0.25 * 0.25);
        EXPECT_NEAR(r.stress[0], k * eUU, 1e-9 * k);
        EXPECT_NEAR(r.stress[1], k * 0.25 * eUU, 1e-9 * k);
        for (int i = 0; i < 3; ++i) force[tri[i]] += r.force.segment<3>(3 * i);
      }
    }
  const double eUU = 0.5 * (stretch * stretch - 1.0);
  const double sUU = 4000.0 / (1.0 - 0.0625) * eUU, sVV = 0.25 * sUU;
  Vec3 right = Vec3::Zero(), top = Vec3::Zero();
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      const int i = iy * n + ix;
      const bool interior = ix > 0 && ix < n - 1 && iy > 0 && iy < n - 1;
      if (interior) EXPECT_LT(force[i].norm(), 1e-9);
      if (ix == n - 1) right += force[i];
      if (iy == n - 1) top += force[i];
    }
  // Traction: first Piola-Kirchhoff stress P = F S times the rest edge length (corners shared).
  EXPECT_NEAR(right.x(), -stretch * sUU * size, 1e-9 * sUU);
  EXPECT_NEAR(top.y(), -sVV * size, 1e-9 * sUU);
}

}  // namespace
}  // namespace weft
