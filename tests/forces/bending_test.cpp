// Bending hinges: derivatives against finite differences, invariances, the small-angle energy
// of ARCSim, the measured-table lookup, and degenerate input.
#include "forces/bending.h"

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "support/mesh_helpers.h"

namespace weft {
namespace {

using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

Vec3 vertexOf(const Vec12& x, int i) { return x.segment<3>(3 * i); }

HingeResult evaluateAt(const BendingHinge& hinge, const BendingSettings& settings, const Vec12& x, HessianMode mode) {
  return evaluateHinge(hinge, settings, vertexOf(x, 0), vertexOf(x, 1), vertexOf(x, 2), vertexOf(x, 3), mode);
}

// A hinge along x with its wings at heights 0.9 and 0.8, the first wing turned by `fold` (rad)
// about the edge: the dihedral angle is then +-fold.
Vec12 foldedHinge(double fold) {
  Vec12 x;
  x << 0.0, 0.0, 0.0,  //
      1.0, 0.0, 0.0,   //
      0.4, 0.9 * std::cos(fold), 0.9 * std::sin(fold),  //
      0.6, -0.8, 0.0;
  return x;
}

// A random, generally folded hinge: wings turned about the edge by up to 1.2 rad each, every
// vertex jittered, the whole rigidly rotated and moved.
Vec12 randomHinge(std::mt19937& rng) {
  std::uniform_real_distribution<double> turn(-1.2, 1.2);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  const double turn1 = turn(rng);
  const double turn2 = turn(rng);
  Vec12 x;
  x << 0.0, 0.0, 0.0,  //
      1.0, 0.0, 0.0,   //
      0.4, 0.9 * std::cos(turn1), 0.9 * std::sin(turn1),  //
      0.6, -0.8 * std::cos(turn2), -0.8 * std::sin(turn2);
  for (int i = 0; i < 12; ++i) x[i] += jitter(rng);
  std::normal_distribution<double> gaussian;
  const Vec3 axis = Vec3(gaussian(rng), gaussian(rng), gaussian(rng)).normalized();
  const Mat3 rotation = Eigen::AngleAxisd(3.0 * turn(rng), axis).toRotationMatrix();
  const Vec3 shift(jitter(rng), jitter(rng), jitter(rng));
  for (int i = 0; i < 4; ++i) x.segment<3>(3 * i) = rotation * vertexOf(x, i) + shift;
  return x;
}

// Hinge parameters chosen so that the measured table's knots (tau_j = 10 j (A0+A1)/l0 = 0.3 j
// rad) fall inside the angles the random hinges reach; evaluateHinge only reads these numbers.
BendingHinge testHinge(double restAngle = 0.0, double edgeAngle = 0.3) {
  BendingHinge hinge;
  hinge.v = {0, 1, 2, 3};
  hinge.restLength = 1.0;
  hinge.restAreaSum = 0.03;
  hinge.restAngle = restAngle;
  hinge.edgeAngle = edgeAngle;
  return hinge;
}

BendingSettings constantStiffness(double k = 2e-3) {
  BendingSettings s;
  s.model = BendingSettings::Model::Constant;
  s.stiffness = k;
  s.stiffnessScale = 1.5;
  return s;
}

// Non-monotone in curvature and different per row, so every interpolation weight matters.
BendingSettings measuredStiffness() {
  BendingSettings s;
  s.model = BendingSettings::Model::Measured;
  s.measured = {{{1e-3, 3e-3, 2e-3, 5e-3, 4e-3}, {2e-3, 2.5e-3, 6e-3, 1e-3, 3e-3}, {4e-3, 1e-3, 1e-3, 7e-3, 2e-3}}};
  s.stiffnessScale = 0.8;
  return s;
}

// Same table value in every column: a row is then one number.
BendingSettings measuredByRow(double row0, double row1, double row2) {
  BendingSettings s;
  s.model = BendingSettings::Model::Measured;
  for (int j = 0; j < 5; ++j) {
    s.measured[0][j] = row0;
    s.measured[1][j] = row1;
    s.measured[2][j] = row2;
  }
  return s;
}

Vec12 energyGradientByDifferences(const BendingHinge& hinge, const BendingSettings& s, const Vec12& x) {
  const double h = 1e-6;
  Vec12 grad;
  for (int i = 0; i < 12; ++i) {
    Vec12 plus = x, minus = x;
    plus[i] += h;
    minus[i] -= h;
    grad[i] = (evaluateAt(hinge, s, plus, HessianMode::None).energy -
               evaluateAt(hinge, s, minus, HessianMode::None).energy) /
              (2.0 * h);
  }
  return grad;
}

Mat12 forceJacobianByDifferences(const BendingHinge& hinge, const BendingSettings& s, const Vec12& x) {
  const double h = 1e-6;
  Mat12 jacobian;
  for (int i = 0; i < 12; ++i) {
    Vec12 plus = x, minus = x;
    plus[i] += h;
    minus[i] -= h;
    jacobian.col(i) = (evaluateAt(hinge, s, plus, HessianMode::None).force -
                       evaluateAt(hinge, s, minus, HessianMode::None).force) /
                      (2.0 * h);
  }
  return jacobian;
}

// A mesh of two triangles sharing the edge (a, b), with wings c (left of a->b) and d (right),
// all given in material space and laid flat in the world (z = 0) unless `lift` raises c.
ClothMesh twoTriangles(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double liftC = 0.0) {
  ClothMesh mesh;
  mesh.addVertex(Vec3(a.x(), a.y(), 0.0));
  mesh.addVertex(Vec3(b.x(), b.y(), 0.0));
  mesh.addVertex(Vec3(c.x(), c.y(), liftC));
  mesh.addVertex(Vec3(d.x(), d.y(), 0.0));
  Triangle left;  // counter-clockwise: a, b, c
  left.v = {0, 1, 2};
  left.rest = {a, b, c};
  Triangle right;  // counter-clockwise: b, a, d
  right.v = {1, 0, 3};
  right.rest = {b, a, d};
  mesh.tris = {left, right};
  buildEdges(mesh);
  return mesh;
}

// The hinge of a two-triangle mesh with its edge along `direction` (material space).
BendingHinge hingeAlong(const Vec2& direction, double weftAngleRad) {
  const Vec2 normal(-direction.y(), direction.x());
  const ClothMesh mesh = twoTriangles(Vec2::Zero(), direction, 0.5 * direction + 0.5 * normal,
                                      0.5 * direction - 0.5 * normal);
  const std::vector<BendingHinge> hinges = buildBendingHinges(mesh, weftAngleRad);
  EXPECT_EQ(hinges.size(), 1u);
  return hinges.at(0);
}

// Small-angle stiffness seen by a hinge: the energy at a 1e-4 rad fold over the quadratic form.
double effectiveStiffness(const BendingHinge& hinge, const BendingSettings& s) {
  const double theta = 1e-4;
  const double energy = evaluateAt(hinge, s, foldedHinge(theta), HessianMode::None).energy;
  return energy * 8.0 * hinge.restAreaSum / (hinge.restLength * hinge.restLength * theta * theta);
}

TEST(Bending, ForceIsMinusEnergyGradientWithConstantStiffness) {
  std::mt19937 rng(7);
  const BendingSettings s = constantStiffness();
  for (int trial = 0; trial < 20; ++trial) {
    const Vec12 x = randomHinge(rng);
    const BendingHinge hinge = testHinge(trial % 2 ? 0.0 : 0.4);
    const HingeResult r = evaluateAt(hinge, s, x, HessianMode::None);
    const Vec12 expected = -energyGradientByDifferences(hinge, s, x);
    EXPECT_LT((r.force - expected).norm(), 1e-6 * expected.norm() + 1e-12) << "trial " << trial;
  }
  // Both signs of the dihedral angle, with and without a rest fold.
  for (double fold : {0.7, -0.7, 1.9, -1.9}) {
    for (double restAngle : {0.0, 0.5}) {
      const Vec12 x = foldedHinge(fold);
      const BendingHinge hinge = testHinge(restAngle);
      const HingeResult r = evaluateAt(hinge, s, x, HessianMode::None);
      EXPECT_GT(r.force.norm(), 0.0);
      EXPECT_LT((r.force + energyGradientByDifferences(hinge, s, x)).norm(), 1e-6 * r.force.norm());
    }
  }
}

TEST(Bending, ForceIsMinusEnergyGradientWithMeasuredStiffness) {
  std::mt19937 rng(11);
  const BendingSettings s = measuredStiffness();
  for (int trial = 0; trial < 30; ++trial) {
    const Vec12 x = randomHinge(rng);
    const BendingHinge hinge = testHinge(trial % 3 == 0 ? -0.3 : 0.0, std::fmod(0.2 * trial, 1.5));
    const HingeResult r = evaluateAt(hinge, s, x, HessianMode::None);
    const Vec12 expected = -energyGradientByDifferences(hinge, s, x);
    EXPECT_LT((r.force - expected).norm(), 1e-6 * expected.norm() + 1e-12) << "trial " << trial;
  }
  // Folds on both sides and across several table pieces (knots every 0.3 rad).
  for (double fold : {-2.0, -1.0, -0.45, -0.1, 0.1, 0.45, 1.0, 2.0}) {
    const Vec12 x = foldedHinge(fold);
    const BendingHinge hinge = testHinge();
    const HingeResult r = evaluateAt(hinge, s, x, HessianMode::None);
    const Vec12 expected = -energyGradientByDifferences(hinge, s, x);
    EXPECT_LT((r.force - expected).norm(), 1e-6 * expected.norm()) << "fold " << fold;
  }
}

TEST(Bending, ExactHessianMatchesForceDifferences) {
  std::mt19937 rng(3);
  for (const BendingSettings& s : {constantStiffness(), measuredStiffness()}) {
    for (int trial = 0; trial < 15; ++trial) {
      const Vec12 x = randomHinge(rng);
      const BendingHinge hinge = testHinge(trial % 2 ? 0.25 : 0.0);
      const Mat12 hessian = evaluateAt(hinge, s, x, HessianMode::Exact).hessian;
      const Mat12 expected = -forceJacobianByDifferences(hinge, s, x);
      EXPECT_LT((hessian - expected).norm(), 1e-5 * expected.norm()) << "trial " << trial;
      EXPECT_LT((hessian - hessian.transpose()).norm(), 1e-12 * hessian.norm());
    }
  }
}

TEST(Bending, DefiniteHessianIsSymmetricPositiveSemiDefinite) {
  std::mt19937 rng(5);
  for (const BendingSettings& s : {constantStiffness(), measuredStiffness()}) {
    for (int trial = 0; trial < 15; ++trial) {
      const Mat12 h = evaluateAt(testHinge(), s, randomHinge(rng), HessianMode::Definite).hessian;
      EXPECT_LT((h - h.transpose()).norm(), 1e-14 * h.norm());
      const Eigen::SelfAdjointEigenSolver<Mat12> eigen(h);
      EXPECT_GE(eigen.eigenvalues().minCoeff(), -1e-12 * h.norm()) << "trial " << trial;
    }
  }
}

TEST(Bending, DefiniteHessianDropsNegativeEnergyCurvature) {
  // A table that softens steeply between alpha = 15 and 20 1/m (tau = 0.9 .. 1.2 rad here):
  // W'' = c (k' sin(tau/2) + k cos(phi/2)/2) < 0 at tau = 1.1, which Definite clamps to zero.
  BendingSettings s;
  s.model = BendingSettings::Model::Measured;
  s.measured = {{{1e-3, 1e-3, 1e-3, 1e-2, 1e-4}, {1e-3, 1e-3, 1e-3, 1e-2, 1e-4}, {1e-3, 1e-3, 1e-3, 1e-2, 1e-4}}};
  const Vec12 x = foldedHinge(1.1);
  const Mat12 definite = evaluateAt(testHinge(), s, x, HessianMode::Definite).hessian;
  const Mat12 exact = evaluateAt(testHinge(), s, x, HessianMode::Exact).hessian;
  EXPECT_GT(exact.norm(), 0.0);
  EXPECT_EQ(definite.norm(), 0.0);
}

TEST(Bending, DefiniteHessianEqualsExactAtRest) {
  for (const BendingSettings& s : {constantStiffness(), measuredStiffness()}) {
    // Flat rest, flat configuration.
    const Vec12 flat = foldedHinge(0.0);
    const Mat12 exact = evaluateAt(testHinge(), s, flat, HessianMode::Exact).hessian;
    const Mat12 definite = evaluateAt(testHinge(), s, flat, HessianMode::Definite).hessian;
    EXPECT_GT(exact.norm(), 0.0);
    EXPECT_LT((exact - definite).norm(), 1e-12 * exact.norm());
  }
}

TEST(Bending, RigidMotionChangesNeitherEnergyNorForceMagnitude) {
  const BendingSettings s = constantStiffness();
  const Mat3 rotation = Eigen::AngleAxisd(0.9, Vec3(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Vec3 shift(0.3, -1.2, 2.0);
  auto moved = [&](const Vec12& x) {
    Vec12 y;
    for (int i = 0; i < 4; ++i) y.segment<3>(3 * i) = rotation * vertexOf(x, i) + shift;
    return y;
  };

  // A flat hinge stays at zero energy and zero force wherever it is put.
  const HingeResult flat = evaluateAt(testHinge(), s, moved(foldedHinge(0.0)), HessianMode::None);
  EXPECT_NEAR(flat.energy, 0.0, 1e-18);
  EXPECT_LT(flat.force.norm(), 1e-15);

  // A folded hinge keeps its energy, and its forces turn with it.
  const Vec12 folded = foldedHinge(0.8);
  const HingeResult before = evaluateAt(testHinge(), s, folded, HessianMode::None);
  const HingeResult after = evaluateAt(testHinge(), s, moved(folded), HessianMode::None);
  EXPECT_GT(before.energy, 0.0);
  EXPECT_NEAR(after.energy, before.energy, 1e-12 * before.energy);
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT((after.force.segment<3>(3 * i) - rotation * before.force.segment<3>(3 * i)).norm(),
              1e-12 * before.force.norm());
  }
}

TEST(Bending, ForcesCarryNoNetForceOrTorque) {
  std::mt19937 rng(13);
  for (const BendingSettings& s : {constantStiffness(), measuredStiffness()}) {
    for (int trial = 0; trial < 10; ++trial) {
      const Vec12 x = randomHinge(rng);
      const Vec12 f = evaluateAt(testHinge(0.2), s, x, HessianMode::None).force;
      Vec3 total = Vec3::Zero(), torque = Vec3::Zero();
      for (int i = 0; i < 4; ++i) {
        total += f.segment<3>(3 * i);
        torque += vertexOf(x, i).cross(f.segment<3>(3 * i));
      }
      EXPECT_GT(f.norm(), 0.0);
      EXPECT_LT(total.norm(), 1e-12 * f.norm());
      EXPECT_LT(torque.norm(), 1e-12 * f.norm());
    }
  }
}

TEST(Bending, SmallAngleEnergyIsArcsimQuadraticHinge) {
  const ClothMesh mesh = twoTriangles(Vec2(0.0, 0.0), Vec2(0.02, 0.0), Vec2(0.008, 0.015), Vec2(0.011, -0.012));
  const BendingHinge hinge = buildBendingHinges(mesh, 0.0).at(0);
  const BendingSettings s = constantStiffness(3e-5);
  const double k = s.stiffness * s.stiffnessScale;
  for (double theta : {1e-3, -2e-3}) {
    // Turn the first wing about the edge (the x axis) by theta.
    Vec12 x;
    const Vec3 wing = mesh.x[hinge.v[2]];
    const Vec3 turned = Eigen::AngleAxisd(theta, Vec3::UnitX()) * wing;
    x << mesh.x[hinge.v[0]], mesh.x[hinge.v[1]], turned, mesh.x[hinge.v[3]];
    const double energy = evaluateAt(hinge, s, x, HessianMode::None).energy;
    const double expected = k * hinge.restLength * hinge.restLength * theta * theta / (8.0 * hinge.restAreaSum);
    EXPECT_NEAR(energy, expected, 1e-6 * expected);
  }
}

TEST(Bending, ConstantStiffnessEnergyIsClosedForm) {
  const BendingSettings s = constantStiffness();
  const BendingHinge hinge = testHinge(0.3);
  const double c = hinge.restLength * hinge.restLength / (2.0 * hinge.restAreaSum);
  const double k = s.stiffness * s.stiffnessScale;
  for (double fold : {-2.5, -0.4, 0.9, 2.8}) {
    // foldedHinge(fold) has dihedral angle -fold (see BuildsSignedRestAngle).
    const double phi = -fold - hinge.restAngle;
    const double expected = 2.0 * k * c * (1.0 - std::cos(phi / 2.0));
    EXPECT_NEAR(evaluateAt(hinge, s, foldedHinge(fold), HessianMode::None).energy, expected, 1e-12 * expected);
  }
  // Rest fold 2.8 rad, current -2.8 rad: the bend is the short way round through pi, 2 pi - 5.6.
  const double phi = 2.0 * kPi - 5.6;
  const double expected = 2.0 * k * c * (1.0 - std::cos(phi / 2.0));
  EXPECT_NEAR(evaluateAt(testHinge(2.8), s, foldedHinge(2.8), HessianMode::None).energy, expected, 1e-12 * expected);
  EXPECT_NEAR(evaluateAt(testHinge(-2.8), s, foldedHinge(-2.8), HessianMode::None).energy, expected, 1e-12 * expected);
}

TEST(Bending, BuildsOneHingePerInteriorEdgeInEdgeOrder) {
  // A 3 x 3 vertex grid, split into 8 counter-clockwise triangles.
  ClothMesh mesh;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) mesh.addVertex(Vec3(0.1 * i, 0.1 * j, 0.0));
  }
  test::triangulatePatch(mesh, 3);
  buildEdges(mesh);
  const std::vector<BendingHinge> hinges = buildBendingHinges(mesh, 0.0);
  int interior = 0;
  for (const Edge& e : mesh.edges) interior += e.isBoundary() ? 0 : 1;
  ASSERT_EQ(static_cast<int>(hinges.size()), interior);
  EXPECT_EQ(interior, 8);
  for (size_t h = 1; h < hinges.size(); ++h) EXPECT_LT(hinges[h - 1].edge, hinges[h].edge);
  const BendingSettings s = constantStiffness();
  for (const BendingHinge& hinge : hinges) {
    EXPECT_NEAR(hinge.restAngle, 0.0, 1e-15);
    EXPECT_NEAR(hinge.restAreaSum, 0.01, 1e-15);  // two triangles of half of 0.1 x 0.1
    const Edge& edge = mesh.edges[hinge.edge];
    EXPECT_NEAR(hinge.restLength, (mesh.x[edge.v[1]] - mesh.x[edge.v[0]]).norm(), 1e-15);
    // The flat mesh is at rest: no energy, no force.
    const HingeResult r = evaluateHinge(hinge, s, mesh.x[hinge.v[0]], mesh.x[hinge.v[1]], mesh.x[hinge.v[2]],
                                        mesh.x[hinge.v[3]], HessianMode::None);
    EXPECT_NEAR(r.energy, 0.0, 1e-20);
    EXPECT_LT(r.force.norm(), 1e-15);
  }
}

TEST(Bending, OrdersHingeVerticesAlongTheFirstTriangle) {
  const ClothMesh mesh = twoTriangles(Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(0.3, 0.5), Vec2(0.6, -0.4));
  const std::vector<BendingHinge> hinges = buildBendingHinges(mesh, 0.0);
  ASSERT_EQ(hinges.size(), 1u);
  const BendingHinge& h = hinges[0];
  const Edge& edge = mesh.edges[h.edge];
  const Triangle& first = mesh.tris[edge.tri[0]];
  // v[0] -> v[1] runs the way the first triangle runs, v[2] closes it, v[3] is the other wing.
  int k = 0;
  while (first.v[k] != h.v[0]) ++k;
  EXPECT_EQ(first.v[(k + 1) % 3], h.v[1]);
  EXPECT_EQ(first.v[(k + 2) % 3], h.v[2]);
  EXPECT_EQ(h.v[3], edge.tri[0] == 0 ? 3 : 2);
  EXPECT_NEAR(h.restLength, 1.0, 1e-15);
  EXPECT_NEAR(h.restAreaSum, 0.25 + 0.2, 1e-15);
}

TEST(Bending, BuildsSignedRestAngleFromCurrentShape) {
  const Vec2 a(0.0, 0.0), b(1.0, 0.0), c(0.5, 0.5), d(0.5, -0.5);
  EXPECT_NEAR(buildBendingHinges(twoTriangles(a, b, c, d), 0.0, true).at(0).restAngle, 0.0, 1e-15);
  // Raising the left wing by 0.5 folds by 45 degrees; lowering it folds the other way.
  const double up = buildBendingHinges(twoTriangles(a, b, c, d, 0.5), 0.0, true).at(0).restAngle;
  const double down = buildBendingHinges(twoTriangles(a, b, c, d, -0.5), 0.0, true).at(0).restAngle;
  EXPECT_NEAR(std::abs(up), kPi / 4.0, 1e-12);
  EXPECT_NEAR(down, -up, 1e-12);
  EXPECT_EQ(buildBendingHinges(twoTriangles(a, b, c, d, 0.5), 0.0, false).at(0).restAngle, 0.0);

  // Sign of Eq. 2.58: theta has the sign of (n1 x n2) . E. Recompute it from the ordered vertices.
  const ClothMesh mesh = twoTriangles(a, b, c, d, 0.5);
  const BendingHinge h = buildBendingHinges(mesh, 0.0, true).at(0);
  const Vec3 e = mesh.x[h.v[1]] - mesh.x[h.v[0]];
  const Vec3 n1 = (mesh.x[h.v[2]] - mesh.x[h.v[0]]).cross(mesh.x[h.v[2]] - mesh.x[h.v[1]]);  // Eq. 2.49
  const Vec3 n2 = (mesh.x[h.v[3]] - mesh.x[h.v[1]]).cross(mesh.x[h.v[3]] - mesh.x[h.v[0]]);  // Eq. 2.50
  EXPECT_GT(n1.dot(Vec3::UnitZ()) * n2.dot(Vec3::UnitZ()), 0.0);  // normals agree when nearly flat
  EXPECT_EQ(h.restAngle > 0.0, n1.cross(n2).dot(e) > 0.0);

  // At its own rest angle a folded hinge feels nothing.
  const HingeResult r = evaluateHinge(h, constantStiffness(), mesh.x[h.v[0]], mesh.x[h.v[1]], mesh.x[h.v[2]],
                                      mesh.x[h.v[3]], HessianMode::Exact);
  EXPECT_NEAR(r.energy, 0.0, 1e-18);
  EXPECT_LT(r.force.norm(), 1e-15);
  EXPECT_GT(r.hessian.norm(), 0.0);

  // foldedHinge(fold) has dihedral angle -fold in this convention.
  const double theta = 0.6;
  const Vec12 x = foldedHinge(theta);
  BendingHinge probe = testHinge(-theta);
  EXPECT_NEAR(evaluateAt(probe, constantStiffness(), x, HessianMode::None).energy, 0.0, 1e-18);
}

TEST(Bending, MeasuredRowFollowsEdgeDirection) {
  const BendingSettings s = measuredByRow(1e-5, 2e-5, 4e-5);
  const BendingHinge alongU = hingeAlong(Vec2(0.01, 0.0), 0.0);
  const BendingHinge alongV = hingeAlong(Vec2(0.0, 0.01), 0.0);
  const BendingHinge diagonal = hingeAlong(Vec2(0.01, 0.01), 0.0);
  const BendingHinge antiDiagonal = hingeAlong(Vec2(-0.01, 0.01), 0.0);
  const BendingHinge between = hingeAlong(Vec2(std::cos(kPi / 8), std::sin(kPi / 8)) * 0.01, 0.0);
  EXPECT_NEAR(alongU.edgeAngle, 0.0, 1e-15);
  EXPECT_NEAR(alongV.edgeAngle, kPi / 2.0, 1e-15);
  EXPECT_NEAR(diagonal.edgeAngle, kPi / 4.0, 1e-15);
  EXPECT_NEAR(antiDiagonal.edgeAngle, kPi / 4.0, 1e-15);
  EXPECT_NEAR(effectiveStiffness(alongU, s), 1e-5, 1e-12);
  EXPECT_NEAR(effectiveStiffness(alongV, s), 4e-5, 1e-12);
  EXPECT_NEAR(effectiveStiffness(diagonal, s), 2e-5, 1e-12);
  EXPECT_NEAR(effectiveStiffness(antiDiagonal, s), 2e-5, 1e-12);
  EXPECT_NEAR(effectiveStiffness(between, s), 1.5e-5, 1e-12);

  // The weft angle turns the frame: with the weft along material y, an x edge runs along V.
  const BendingHinge xEdgeWeftAlongY = hingeAlong(Vec2(0.01, 0.0), kPi / 2.0);
  const BendingHinge xEdgeWeftDiagonal = hingeAlong(Vec2(0.01, 0.0), kPi / 4.0);
  const BendingHinge diagonalEdgeWeftDiagonal = hingeAlong(Vec2(0.01, 0.01), kPi / 4.0);
  EXPECT_NEAR(xEdgeWeftAlongY.edgeAngle, kPi / 2.0, 1e-15);
  EXPECT_NEAR(xEdgeWeftDiagonal.edgeAngle, kPi / 4.0, 1e-15);
  EXPECT_NEAR(diagonalEdgeWeftDiagonal.edgeAngle, 0.0, 1e-15);
  EXPECT_NEAR(effectiveStiffness(xEdgeWeftAlongY, s), 4e-5, 1e-12);
  EXPECT_NEAR(effectiveStiffness(xEdgeWeftDiagonal, s), 2e-5, 1e-12);
  EXPECT_NEAR(effectiveStiffness(diagonalEdgeWeftDiagonal, s), 1e-5, 1e-12);
}

TEST(Bending, MeasuredStiffnessFollowsCurvatureColumns) {
  // Force of a measured hinge = force of a constant hinge with the interpolated k (Eq. 2.56).
  BendingSettings measured;
  measured.model = BendingSettings::Model::Measured;
  measured.measured = {{{1e-3, 2e-3, 6e-3, 3e-3, 5e-3}, {0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}}};
  BendingHinge hinge = testHinge(0.0, 0.0);  // row 0
  hinge.restAreaSum = 0.05;                  // alpha = theta l0 / (2 (A0+A1)) = 10 |theta|
  struct Case {
    double fold;
    double k;
  };
  for (const Case& c : {Case{0.75, 4e-3}, Case{-0.75, 4e-3}, Case{0.3, 1.6e-3}, Case{1.2, 4.8e-3},
                        Case{2.5, 5e-3}, Case{-3.0, 5e-3}}) {
    const Vec12 x = foldedHinge(c.fold);
    const HingeResult r = evaluateAt(hinge, measured, x, HessianMode::None);
    BendingSettings constant = constantStiffness(c.k);
    constant.stiffnessScale = 1.0;
    const HingeResult expected = evaluateAt(hinge, constant, x, HessianMode::None);
    EXPECT_LT((r.force - expected.force).norm(), 1e-10 * expected.force.norm()) << "fold " << c.fold;
  }
}

TEST(Bending, DegenerateHingeGivesFiniteZeroForce) {
  const BendingSettings s = measuredStiffness();
  Vec12 collapsedWing = foldedHinge(0.5);
  collapsedWing.segment<3>(6) = Vec3(0.5, 0.0, 0.0);  // x2 on the edge: triangle 1 has no normal
  Vec12 collapsedEdge = foldedHinge(0.5);
  collapsedEdge.segment<3>(3) = collapsedEdge.segment<3>(0);  // zero-length edge
  const Vec12 allSame = Vec12::Zero();
  for (const Vec12& x : {collapsedWing, collapsedEdge, allSame}) {
    for (HessianMode mode : {HessianMode::None, HessianMode::Exact, HessianMode::Definite}) {
      const HingeResult r = evaluateAt(testHinge(), s, x, mode);
      EXPECT_TRUE(std::isfinite(r.energy));
      EXPECT_TRUE(r.force.allFinite());
      EXPECT_TRUE(r.hessian.allFinite());
      EXPECT_EQ(r.force.norm(), 0.0);
    }
  }
}

TEST(Bending, SkipsHingesWithZeroRestArea) {
  // The second triangle's rest corners are collinear.
  const ClothMesh mesh = twoTriangles(Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(0.5, 0.5), Vec2(2.0, 0.0));
  EXPECT_TRUE(buildBendingHinges(mesh, 0.0).empty());
}

TEST(Bending, EnabledOnlyWithSomeStiffness) {
  BendingSettings s = constantStiffness();
  EXPECT_TRUE(bendingEnabled(s));
  s.stiffnessScale = 0.0;
  EXPECT_FALSE(bendingEnabled(s));
  s = constantStiffness(0.0);
  EXPECT_FALSE(bendingEnabled(s));
  s = constantStiffness();
  s.model = BendingSettings::Model::None;
  EXPECT_FALSE(bendingEnabled(s));
  EXPECT_EQ(evaluateAt(testHinge(), s, foldedHinge(0.5), HessianMode::Exact).force.norm(), 0.0);
  s = measuredByRow(0.0, 0.0, 0.0);
  EXPECT_FALSE(bendingEnabled(s));
  s.measured[2][4] = 1e-6;
  EXPECT_TRUE(bendingEnabled(s));
}

}  // namespace
}  // namespace weft
