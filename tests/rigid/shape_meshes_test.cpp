// Procedural shapes: closed and outward, vertices on the true surface, and how far their volume and
// inertia are from the smooth shape's (the tessellation error, printed for the record).
#include "rigid/shape_meshes.h"

#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "rigid/closed_surface_check.h"
#include "rigid/mass_properties.h"

namespace weft {
namespace {

// Closed, outward, and for these convex shapes centred at the origin: every triangle faces away
// from the origin.
void expectClosedConvexOutward(const TriangleMesh& mesh) {
  const std::vector<std::string> problems = closedSurfaceProblems(mesh);
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_GT(signedVolume(mesh), 0.0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3& a = mesh.vertices[mesh.triangles[t][0]];
    const Vec3& b = mesh.vertices[mesh.triangles[t][1]];
    const Vec3& c = mesh.vertices[mesh.triangles[t][2]];
    EXPECT_GT((b - a).cross(c - a).dot(a + b + c), 0.0) << "triangle " << t << " faces inward";
  }
}

double relativeError(double approximate, double exact) { return (approximate - exact) / exact; }

TEST(ShapeMeshes, IcosphereCountsAndRadius) {
  for (int level = 0; level <= 4; ++level) {
    const TriangleMesh mesh = makeSphereMesh({0.25, level});
    const int power = 1 << (2 * level);
    EXPECT_EQ(mesh.triangles.size(), static_cast<size_t>(20 * power));
    EXPECT_EQ(mesh.vertices.size(), static_cast<size_t>(10 * power + 2));
    for (const Vec3& v : mesh.vertices) EXPECT_NEAR(v.norm(), 0.25, 1e-15);
    expectClosedConvexOutward(mesh);
  }
}

TEST(ShapeMeshes, IcosphereTrianglesAreNearlyUniform) {
  const TriangleMesh mesh = makeSphereMesh({1.0, 3});
  double shortest = INFINITY, longest = 0.0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const double length = (mesh.vertices[t[k]] - mesh.vertices[t[(k + 1) % 3]]).norm();
      shortest = std::min(shortest, length);
      longest = std::max(longest, length);
    }
  EXPECT_LT(longest / shortest, 1.3);  // a UV sphere of similar size has a ratio of ~10 near its poles
}

// The icosphere is inscribed in the sphere: its volume and inertia fall short by a tessellation
// error that shrinks about 4x per subdivision (the gap is quadratic in the edge length).
TEST(ShapeMeshes, IcosphereTessellationErrorAgainstAnalyticSphere) {
  const double radius = 0.1, density = 1000.0;
  const double volume = 4.0 / 3.0 * kPi * radius * radius * radius;
  const double inertia = 0.4 * density * volume * radius * radius;
  // Measured relative errors (volume, inertia), rounded up: level 1..4.
  const double bounds[5][2] = {{0, 0}, {0.130, 0.205}, {0.035, 0.057}, {0.0090, 0.0146}, {0.0023, 0.0037}};
  double previous = 1.0;
  for (int level = 1; level <= 4; ++level) {
    const MassProperties p = computeMassProperties(makeSphereMesh({radius, level}), density, "icosphere");
    const double volumeError = relativeError(p.volume, volume);
    std::printf("[   info   ] icosphere level %d (%d triangles): volume error %+.3f%%, inertia error %+.3f%%\n", level,
                20 << (2 * level), 100.0 * volumeError, 100.0 * relativeError(p.inertia(0, 0), inertia));
    EXPECT_LT(volumeError, 0.0);  // inscribed
    EXPECT_GT(volumeError, -bounds[level][0]);
    EXPECT_LT(std::abs(volumeError), previous / 3.5);
    previous = std::abs(volumeError);
    EXPECT_NEAR(p.centreOfMass.norm(), 0.0, 1e-15);
    for (int a = 0; a < 3; ++a) {
      EXPECT_LT(relativeError(p.inertia(a, a), inertia), 0.0);
      EXPECT_GT(relativeError(p.inertia(a, a), inertia), -bounds[level][1]);
    }
  }
}

TEST(ShapeMeshes, BoxIsExactAndSplitsLargeFaces) {
  const Vec3 half(0.5, 0.2, 0.05);
  const TriangleMesh single = makeBoxMesh({half, 0.0});
  EXPECT_EQ(single.vertices.size(), 8u);
  EXPECT_EQ(single.triangles.size(), 12u);
  expectClosedConvexOutward(single);

  const TriangleMesh split = makeBoxMesh({half, 0.1});  // cells: 10 x 4 x 1
  const int nx = 10, ny = 4, nz = 1;
  EXPECT_EQ(split.triangles.size(), static_cast<size_t>(4 * (nx * ny + ny * nz + nz * nx)));
  EXPECT_EQ(split.vertices.size(),
            static_cast<size_t>((nx + 1) * (ny + 1) * (nz + 1) - (nx - 1) * (ny - 1) * (nz - 1)));
  expectClosedConvexOutward(split);
  for (const auto& t : split.triangles)
    for (int k = 0; k < 3; ++k)
      EXPECT_LE((split.vertices[t[k]] - split.vertices[t[(k + 1) % 3]]).norm(), 0.1 * std::sqrt(2.0) + 1e-12);

  for (const TriangleMesh* mesh : {&single, &split}) {
    for (const Vec3& v : mesh->vertices) EXPECT_TRUE(((v.cwiseAbs() - half).array().abs() < 1e-15).any());  // on a face
    const MassProperties p = computeMassProperties(*mesh, 1.0, "box");
    EXPECT_NEAR(p.volume, 8.0 * half.prod(), 1e-15);
  }
}

// The mesh of a cylinder is a prism over a regular polygon: its volume is known exactly.
TEST(ShapeMeshes, CylinderIsAPrismOverARegularPolygon) {
  const CylinderShape shape{0.1, 1.0, 32, 20};
  const TriangleMesh mesh = makeCylinderMesh(shape);
  EXPECT_EQ(mesh.vertices.size(), static_cast<size_t>(2 + 32 * 21));
  EXPECT_EQ(mesh.triangles.size(), static_cast<size_t>(2 * 32 + 2 * 32 * 20));
  expectClosedConvexOutward(mesh);
  const double polygonArea = 0.5 * 32 * 0.01 * std::sin(2.0 * kPi / 32);
  const MassProperties p = computeMassProperties(mesh, 1.0, "cylinder");
  EXPECT_NEAR(p.volume, polygonArea * 2.0, 1e-13 * p.volume);  // rounding over 1344 terms
  const double smooth = kPi * 0.01 * 2.0;
  std::printf("[   info   ] cylinder, 32 segments: volume error %+.3f%%, axial inertia error %+.3f%%\n",
              100.0 * relativeError(p.volume, smooth), 100.0 * relativeError(p.inertia(1, 1), 0.5 * smooth * 0.01));
  for (const Vec3& v : mesh.vertices) {
    const double r = std::hypot(v.x(), v.z());
    EXPECT_TRUE(std::abs(r - 0.1) < 1e-15 || (r == 0.0 && std::abs(std::abs(v.y()) - 1.0) < 1e-15));
  }
}

TEST(ShapeMeshes, CapsuleIsClosedOutwardAndNearTheSmoothShape) {
  for (const double halfLength : {0.0, 0.1}) {
    const CapsuleShape shape{0.05, halfLength, 24};
    const TriangleMesh mesh = makeCapsuleMesh(shape);
    expectClosedConvexOutward(mesh);
    // Each vertex lies on the capsule: at distance `radius` from the segment y in [-h, h].
    for (const Vec3& v : mesh.vertices) {
      const Vec3 axisPoint(0.0, std::clamp(v.y(), -halfLength, halfLength), 0.0);
      EXPECT_NEAR((v - axisPoint).norm(), 0.05, 1e-15);
    }
    const double smooth = kPi * 0.0025 * 2.0 * halfLength + 4.0 / 3.0 * kPi * 0.05 * 0.05 * 0.05;
    const MassProperties p = computeMassProperties(mesh, 1.0, "capsule");
    const double error = relativeError(p.volume, smooth);
    std::printf("[   info   ] capsule, 24 segments, half length %.2f: volume error %+.3f%%\n", halfLength,
                100.0 * error);
    EXPECT_LT(error, 0.0);
    EXPECT_GT(error, -0.03);
    EXPECT_NEAR(p.centreOfMass.norm(), 0.0, 1e-15);
  }
}

TEST(ShapeMeshes, GenerationIsDeterministic) {
  const TriangleMesh a = makeSphereMesh({0.1, 3}), b = makeSphereMesh({0.1, 3});
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.triangles, b.triangles);
}

}  // namespace
}  // namespace weft
