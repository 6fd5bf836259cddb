// Wind: the flat-plate drag and lift of wind.h, checked on single triangles and a small sheet.
#include "forces/wind.h"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "support/mesh_helpers.h"

namespace weft {
namespace {

// One triangle with the given corners (world = rest for simplicity), at rest.
ClothMesh triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  ClothMesh mesh;
  mesh.addVertex(a);
  mesh.addVertex(b);
  mesh.addVertex(c);
  Triangle t;
  t.v = {0, 1, 2};
  t.rest = {a.head<2>(), b.head<2>(), c.head<2>()};
  mesh.tris.push_back(t);
  return mesh;
}

// A right triangle of legs `size` in the plane through the origin with unit normal `normal`.
ClothMesh triangleFacing(const Vec3& normal, double size = 1.0) {
  const Vec3 n = normal.normalized();
  const Vec3 u = n.unitOrthogonal();
  const Vec3 w = n.cross(u);  // (u, w, n) right-handed, so the winding below has normal +n
  return triangle(Vec3::Zero(), size * u, size * w);
}

WindSpec windAlong(const Vec3& velocity) {
  WindSpec wind;
  wind.velocity = velocity;
  wind.airDensity = 1.2;
  wind.drag = 1.0;
  wind.lift = 0.3;
  wind.gustAmplitude = 0.0;
  return wind;
}

Vec3 totalForce(const ClothMesh& mesh, const WindSpec& wind, double time = 0.0) {
  std::vector<Vec3> forces(mesh.vertexCount(), Vec3::Zero());
  addWindForces(mesh, wind, time, forces);
  Vec3 sum = Vec3::Zero();
  for (const Vec3& f : forces) sum += f;
  return sum;
}

TEST(Wind, EdgeOnSheetFeelsNoForce) {
  const WindSpec wind = windAlong(Vec3(5.0, 0.0, 0.0));
  const ClothMesh mesh = triangleFacing(Vec3::UnitZ());  // lies in the xy plane, wind along x
  EXPECT_LT(totalForce(mesh, wind).norm(), 1e-15);
}

TEST(Wind, FacingSheetIsPushedAlongTheWind) {
  const WindSpec wind = windAlong(Vec3(0.0, 0.0, 4.0));
  const ClothMesh mesh = triangleFacing(Vec3::UnitZ(), 2.0);  // area 2 m^2
  const Vec3 f = totalForce(mesh, wind);
  // Face-on there is no lift: all drag, 1/2 rho C_d A v^2 along the wind.
  const double expected = 0.5 * wind.airDensity * wind.drag * 2.0 * 16.0;
  EXPECT_NEAR(f.z(), expected, 1e-12 * expected);
  EXPECT_LT(f.head<2>().norm(), 1e-12 * expected);
}

TEST(Wind, EachCornerTakesAThird) {
  const WindSpec wind = windAlong(Vec3(1.0, -2.0, 3.0));
  const ClothMesh mesh = triangle(Vec3(0.1, 0.0, 0.2), Vec3(1.0, 0.3, 0.0), Vec3(0.2, 0.9, 0.4));
  std::vector<Vec3> forces(3, Vec3(1.0, 1.0, 1.0));  // forces are added, not overwritten
  addWindForces(mesh, wind, 0.0, forces);
  const Vec3 total = totalForce(mesh, wind);
  EXPECT_GT(total.norm(), 0.0);
  for (const Vec3& f : forces) EXPECT_LT((f - Vec3(1.0, 1.0, 1.0) - total / 3.0).norm(), 1e-14);
}

TEST(Wind, ForceScalesWithSpeedSquaredAndArea) {
  const Vec3 direction = Vec3(1.0, 0.5, 2.0).normalized();  // oblique: drag and lift both act
  const ClothMesh small = triangleFacing(Vec3(0.2, 0.3, 1.0), 1.0);
  const ClothMesh large = triangleFacing(Vec3(0.2, 0.3, 1.0), 3.0);  // nine times the area
  const Vec3 base = totalForce(small, windAlong(2.0 * direction));
  EXPECT_GT(base.norm(), 0.0);
  EXPECT_LT((totalForce(small, windAlong(6.0 * direction)) - 9.0 * base).norm(), 1e-12 * base.norm());
  EXPECT_LT((totalForce(large, windAlong(2.0 * direction)) - 9.0 * base).norm(), 1e-12 * base.norm());
}

TEST(Wind, FlippedWindingGivesTheSameForce) {
  const WindSpec wind = windAlong(Vec3(3.0, -1.0, 2.0));
  const Vec3 a(0.0, 0.1, 0.0), b(1.0, 0.0, 0.3), c(0.2, 0.8, 0.5);
  const Vec3 forward = totalForce(triangle(a, b, c), wind);
  const Vec3 backward = totalForce(triangle(a, c, b), wind);
  EXPECT_GT(forward.norm(), 0.0);
  EXPECT_LT((forward - backward).norm(), 1e-14 * forward.norm());
}

TEST(Wind, LiftIsPerpendicularToTheWindAndFollowsTheAngleOfAttack) {
  // A plate at angle of attack a to a wind along x, leading edge up: the lift goes up (+y).
  const double attack = 0.3;
  const Vec3 normal(std::sin(attack), std::cos(attack), 0.0);
  WindSpec wind = windAlong(Vec3(2.0, 0.0, 0.0));
  wind.drag = 0.0;
  const Vec3 lift = totalForce(triangleFacing(normal), wind);
  const double expected = 0.5 * wind.airDensity * wind.lift * 0.5 * 4.0 * std::sin(attack) * std::cos(attack);
  EXPECT_NEAR(lift.y(), expected, 1e-12 * expected);
  EXPECT_LT(std::abs(lift.dot(wind.velocity)), 1e-14);
  EXPECT_LT(std::abs(lift.z()), 1e-14);
  // Drag alone lies along the normal, with size 1/2 rho C_d A (v.n)^2.
  wind.drag = 1.0;
  wind.lift = 0.0;
  const Vec3 drag = totalForce(triangleFacing(normal), wind);
  const double vn = wind.velocity.dot(normal);
  EXPECT_LT((drag - 0.5 * wind.airDensity * 0.5 * vn * vn * normal).norm(), 1e-14);
}

TEST(Wind, ClothMovingWithTheWindFeelsNoForce) {
  const WindSpec wind = windAlong(Vec3(1.0, 2.0, -3.0));
  ClothMesh mesh = triangleFacing(Vec3(1.0, 1.0, 1.0));
  for (Vec3& v : mesh.v) v = wind.velocity;
  EXPECT_LT(totalForce(mesh, wind).norm(), 1e-15);
  // Only the mean velocity counts: a spin about the centroid changes nothing.
  const Vec3 centroid = (mesh.x[0] + mesh.x[1] + mesh.x[2]) / 3.0;
  for (int i = 0; i < 3; ++i) mesh.v[i] += Vec3(0.0, 0.0, 1.0).cross(mesh.x[i] - centroid);
  EXPECT_LT(totalForce(mesh, wind).norm(), 1e-14);
}

TEST(Wind, GustModulatesWithTime) {
  WindSpec wind = windAlong(Vec3(0.0, 0.0, 2.0));
  wind.gustAmplitude = 0.5;
  wind.gustFrequency = 0.25;  // period 4 s
  const ClothMesh mesh = triangleFacing(Vec3::UnitZ());
  const double calm = totalForce(mesh, windAlong(wind.velocity)).z();
  // sin(2 pi f t) = 0, 1, -1 at t = 0, 1, 3 s: speed factor 1, 1.5, 0.5, force factor its square.
  EXPECT_NEAR(totalForce(mesh, wind, 0.0).z(), calm, 1e-12 * calm);
  EXPECT_NEAR(totalForce(mesh, wind, 1.0).z(), 2.25 * calm, 1e-12 * calm);
  EXPECT_NEAR(totalForce(mesh, wind, 3.0).z(), 0.25 * calm, 1e-12 * calm);
  EXPECT_NEAR(totalForce(mesh, wind, 5.0).z(), 2.25 * calm, 1e-12 * calm);  // periodic
  EXPECT_LT((windVelocityAt(wind, 1.0) - 1.5 * wind.velocity).norm(), 1e-15);
}

TEST(Wind, TotalIsTheSumOverTriangles) {
  // A crumpled 3 x 3 vertex sheet, moving, in an oblique wind.
  ClothMesh sheet;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      const int id = sheet.addVertex(Vec3(0.5 * i, 0.5 * j, 0.1 * std::sin(3.0 * i + j)));
      sheet.v[id] = Vec3(0.1 * j, -0.2 * i, 0.05 * (i + j));
    }
  }
  test::triangulatePatch(sheet, 3);
  const WindSpec wind = windAlong(Vec3(2.0, 1.0, 3.0));
  Vec3 sum = Vec3::Zero();
  for (const Triangle& t : sheet.tris) {
    ClothMesh single = triangle(sheet.x[t.v[0]], sheet.x[t.v[1]], sheet.x[t.v[2]]);
    for (int k = 0; k < 3; ++k) single.v[k] = sheet.v[t.v[k]];
    sum += totalForce(single, wind);
  }
  const Vec3 total = totalForce(sheet, wind);
  EXPECT_GT(total.norm(), 0.0);
  EXPECT_LT((total - sum).norm(), 1e-12 * sum.norm());
}

TEST(Wind, CollapsedTriangleFeelsNoForce) {
  const WindSpec wind = windAlong(Vec3(1.0, 1.0, 1.0));
  const ClothMesh mesh = triangle(Vec3::Zero(), Vec3(1.0, 0.0, 0.0), Vec3(2.0, 0.0, 0.0));
  const Vec3 f = totalForce(mesh, wind);
  EXPECT_TRUE(f.allFinite());
  EXPECT_EQ(f.norm(), 0.0);
}

TEST(Wind, EnabledOnlyWithWind) {
  EXPECT_FALSE(windEnabled(WindSpec{}));
  EXPECT_TRUE(windEnabled(windAlong(Vec3(0.0, 0.0, 0.1))));
}

}  // namespace
}  // namespace weft
