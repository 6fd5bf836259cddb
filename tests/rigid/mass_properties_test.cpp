// Mass properties by the divergence theorem, against closed forms.
#include "rigid/mass_properties.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "rigid/shape_meshes.h"
#include "rigid_test_support.h"
#include "util/input_error.h"

namespace weft {
namespace {

Mat3 boxInertia(double mass, const Vec3& size) {
  const Vec3 s2 = size.cwiseProduct(size);
  return (mass / 12.0 * Vec3(s2.y() + s2.z(), s2.z() + s2.x(), s2.x() + s2.y())).asDiagonal();
}

void expectMatrixNear(const Mat3& actual, const Mat3& expected, double tolerance) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance) << "actual\n" << actual << "\nexpected\n" << expected;
}

TEST(MassProperties, UnitCube) {
  const MassProperties p = computeMassProperties(makeBoxMesh({Vec3::Constant(0.5), 0.0}), 1.0, "cube");
  EXPECT_NEAR(p.volume, 1.0, 1e-15);
  EXPECT_NEAR(p.mass, 1.0, 1e-15);
  EXPECT_NEAR(p.centreOfMass.norm(), 0.0, 1e-15);
  expectMatrixNear(p.inertia, Mat3::Identity() / 6.0, 1e-15);
}

TEST(MassProperties, BoxWithDensityAndSplitFaces) {
  const Vec3 size(0.2, 0.4, 0.6);
  for (const double cell : {0.0, 0.07}) {
    const MassProperties p = computeMassProperties(makeBoxMesh({size / 2, cell}), 1000.0, "box");
    EXPECT_NEAR(p.mass, 48.0, 1e-12);
    expectMatrixNear(p.inertia, boxInertia(48.0, size), 1e-13);
  }
}

// Moving and turning a mesh moves its centre of mass with it and turns its inertia, R I Rᵀ; a
// translation far from the origin does not cost digits (the reference point follows the mesh).
TEST(MassProperties, RigidMotionOfTheMesh) {
  const Vec3 size(0.2, 0.4, 0.6);
  const TriangleMesh box = makeBoxMesh({size / 2, 0.1});
  const Eigen::Quaterniond rotation(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  for (const Vec3& offset : {Vec3(0.3, -1.2, 2.5), Vec3(1e4, -2e4, 3e4)}) {
    TriangleMesh moved = box;
    for (Vec3& v : moved.vertices) v = rotation * v + offset;
    const MassProperties p = computeMassProperties(moved, 1000.0, "box");
    EXPECT_NEAR((p.centreOfMass - offset).norm(), 0.0, 1e-15 * (1.0 + offset.norm()) * 10);
    EXPECT_NEAR(p.mass, 48.0, 1e-12 * (1.0 + offset.norm()));
    const Mat3 r = rotation.toRotationMatrix();
    expectMatrixNear(p.inertia, r * boxInertia(48.0, size) * r.transpose(), 1e-12 * (1.0 + offset.norm()));
  }
}

TEST(MassProperties, TranslationLeavesInertiaAboutTheCentreOfMassUnchanged) {
  const TriangleMesh capsule = makeCapsuleMesh({0.05, 0.2, 16});
  const MassProperties here = computeMassProperties(capsule, 800.0, "capsule");
  const MassProperties there =
      computeMassProperties(test::translated(capsule, Vec3(3.0, -7.0, 11.0)), 800.0, "capsule");
  EXPECT_NEAR(there.mass, here.mass, 1e-13 * here.mass);
  expectMatrixNear(there.inertia, here.inertia, 1e-12 * here.inertia.norm());
  EXPECT_NEAR((there.centreOfMass - here.centreOfMass - Vec3(3.0, -7.0, 11.0)).norm(), 0.0, 1e-13);
}

// A hollow box (an outer surface facing out, an inner one facing in) has the mass and inertia of
// the outer box minus the inner one: the signed integrals over both surfaces add up to the shell.
TEST(MassProperties, HollowSolidSubtractsItsCavity) {
  const Vec3 outer(1.0, 0.8, 0.6), inner(0.6, 0.4, 0.2);
  TriangleMesh shell = makeBoxMesh({outer / 2, 0.0});
  const TriangleMesh cavity = test::reversed(test::translated(makeBoxMesh({inner / 2, 0.0}), Vec3(0.1, 0.0, 0.05)));
  const int base = static_cast<int>(shell.vertices.size());
  shell.vertices.insert(shell.vertices.end(), cavity.vertices.begin(), cavity.vertices.end());
  for (const auto& t : cavity.triangles) shell.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});

  const MassProperties p = computeMassProperties(shell, 1.0, "shell");
  const double mOuter = outer.prod(), mInner = inner.prod();
  EXPECT_NEAR(p.mass, mOuter - mInner, 1e-15);
  const Vec3 com = -mInner * Vec3(0.1, 0.0, 0.05) / (mOuter - mInner);
  EXPECT_NEAR((p.centreOfMass - com).norm(), 0.0, 1e-15);
  // Each part's inertia shifted to the common centre of mass (parallel-axis theorem).
  auto shifted = [&](double m, const Vec3& size, const Vec3& centre) {
    const Vec3 d = centre - com;
    return Mat3(boxInertia(m, size) + m * (d.squaredNorm() * Mat3::Identity() - d * d.transpose()));
  };
  expectMatrixNear(p.inertia, shifted(mOuter, outer, Vec3::Zero()) - shifted(mInner, inner, Vec3(0.1, 0.0, 0.05)),
                   1e-15);
}

TEST(MassProperties, InertiaIsSymmetricPositiveDefiniteAndObeysTheTriangleInequality) {
  TriangleMesh capsule = makeCapsuleMesh({0.05, 0.3, 12});
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.4, Vec3(0.2, 1.0, -0.5).normalized()));
  for (Vec3& v : capsule.vertices) v = turn * v + Vec3(0.1, 0.2, 0.3);
  const MassProperties p = computeMassProperties(capsule, 500.0, "capsule");
  EXPECT_EQ(p.inertia, p.inertia.transpose());
  const Vec3 principal = Eigen::SelfAdjointEigenSolver<Mat3>(p.inertia).eigenvalues();  // ascending
  EXPECT_GT(principal.minCoeff(), 0.0);
  EXPECT_LE(principal[2], principal[0] + principal[1]);
}

TEST(MassProperties, InwardMeshIsRejectedWithItsName) {
  const TriangleMesh inward = test::reversed(makeBoxMesh({Vec3::Constant(0.5), 0.0}));
  EXPECT_NEAR(signedVolume(inward), -1.0, 1e-15);
  try {
    computeMassProperties(inward, 1.0, "tools/box.obj");
    ADD_FAILURE() << "an inward mesh was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "tools/box.obj");
    EXPECT_NE(std::string(e.what()).find("turned inward"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("-1"), std::string::npos) << e.what();
  }
  TriangleMesh copy = inward;
  EXPECT_THROW(recentreAtCentreOfMass(copy, "box"), InputError);
  EXPECT_THROW(computeMassProperties(TriangleMesh{}, 1.0, "empty"), InputError);
}

TEST(MassProperties, RecentringMovesTheCentreOfMassToTheOrigin) {
  TriangleMesh mesh = test::translated(makeCapsuleMesh({0.05, 0.2, 16}), Vec3(0.5, -0.25, 2.0));
  const MassProperties before = computeMassProperties(mesh, 1.0, "capsule");
  const Vec3 oldCentre = recentreAtCentreOfMass(mesh, "capsule");
  EXPECT_NEAR((oldCentre - Vec3(0.5, -0.25, 2.0)).norm(), 0.0, 1e-14);
  const MassProperties after = computeMassProperties(mesh, 1.0, "capsule");
  EXPECT_NEAR(after.centreOfMass.norm(), 0.0, 1e-15);
  expectMatrixNear(after.inertia, before.inertia, 1e-15);
}

}  // namespace
}  // namespace weft
