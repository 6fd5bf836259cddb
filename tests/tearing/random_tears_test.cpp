// Thousands of random tears on grids of several sizes, with every invariant checked after each.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "forces/bending.h"
#include "mesh/grid.h"
#include "mesh/mesh_check.h"
#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "support/tear_checks.h"
#include "tearing/tear_mesh.h"

namespace weft {
namespace {

Cloth randomCloth(int nx, int ny, std::mt19937& random) {
  Cloth cloth;
  GridSpec spec;
  spec.resolutionX = nx;
  spec.resolutionY = ny;
  spec.width = 1.0;
  spec.height = 0.8;
  cloth.mesh = makeGrid(spec);
  cloth.weftAngleRad = 0.3;
  assignLumpedMasses(cloth.mesh, cloth.material.areaDensity);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < cloth.mesh.vertexCount(); ++i) {
    cloth.mesh.v[i] = Vec3(unit(random), unit(random), unit(random));
    cloth.mesh.x[i].z() = 0.05 * unit(random);  // not flat, so that hinges have distinct wings
  }
  rebuildElements(cloth);
  // Pin the top row.
  PinTrack track;
  for (int ix = 0; ix < nx; ++ix) {
    const int id = (ny - 1) * nx + ix;
    track.vertices.push_back(id);
    track.start.push_back(cloth.mesh.x[id]);
    cloth.mesh.pinned[id] = 1;
  }
  cloth.pins.push_back(track);
  return cloth;
}

bool sameMembrane(const MembraneElement& a, const MembraneElement& b) {
  return a.v == b.v && a.ru == b.ru && a.rv == b.rv && a.restArea == b.restArea;
}

auto hingeKey(const BendingHinge& h) {
  return std::tuple(h.edge, h.v, h.restAngle, h.restLength, h.restAreaSum, h.edgeAngle);
}

std::vector<BendingHinge> sortedByEdge(std::vector<BendingHinge> hinges) {
  std::sort(hinges.begin(), hinges.end(), [](const auto& a, const auto& b) { return hingeKey(a) < hingeKey(b); });
  return hinges;
}

// The caches match a rebuild from scratch, and every pinned vertex is tracked from its start.
::testing::AssertionResult cachesMatchARebuild(const Cloth& cloth) {
  Cloth rebuilt = cloth;
  rebuildElements(rebuilt);
  if (cloth.membranes.size() != rebuilt.membranes.size()) return ::testing::AssertionFailure() << "membrane count";
  for (size_t t = 0; t < cloth.membranes.size(); ++t) {
    if (!sameMembrane(cloth.membranes[t], rebuilt.membranes[t])) return ::testing::AssertionFailure() << "membrane " << t;
  }
  const auto patched = sortedByEdge(cloth.hinges);
  const auto fresh = sortedByEdge(rebuilt.hinges);
  if (patched.size() != fresh.size()) {
    return ::testing::AssertionFailure() << patched.size() << " hinges, a rebuild has " << fresh.size();
  }
  for (size_t i = 0; i < fresh.size(); ++i) {
    if (hingeKey(patched[i]) != hingeKey(fresh[i])) return ::testing::AssertionFailure() << "hinge of edge " << fresh[i].edge;
  }
  const PinTrack& track = cloth.pins[0];
  if (!std::is_sorted(track.vertices.begin(), track.vertices.end()) || track.start.size() != track.vertices.size()) {
    return ::testing::AssertionFailure() << "pin track not sorted or start misaligned";
  }
  for (int i = 0; i < cloth.mesh.vertexCount(); ++i) {
    const bool tracked = std::binary_search(track.vertices.begin(), track.vertices.end(), i);
    if (tracked != (cloth.mesh.pinned[i] == 1)) return ::testing::AssertionFailure() << "vertex " << i << " pin state";
  }
  for (size_t k = 0; k < track.vertices.size(); ++k) {
    // Every pinned vertex (copies included) sits at its start: nothing has moved.
    if (track.start[k] != cloth.mesh.x[track.vertices[k]]) return ::testing::AssertionFailure() << "pin start " << k;
  }
  return ::testing::AssertionSuccess();
}

TEST(RandomTears, EveryChangeKeepsTheMeshValidConservedAndTheCachesExact) {
  struct Run {
    int nx, ny, tears;
  };
  TearGuards guards;
  guards.minEdgeLength = 0.004;
  std::mt19937 random(20240611);
  int succeeded = 0;
  // Every grid here starts with angles above the guard (the flattest, 25 x 9, at 22.6 degrees),
  // so any triangle below it would have been made by a tear.
  for (const Run& run : {Run{6, 5, 1500}, Run{12, 12, 2500}, Run{20, 14, 3000}, Run{25, 9, 2000}}) {
    Cloth cloth = randomCloth(run.nx, run.ny, random);
    const double density = cloth.material.areaDensity;
    const double mass = test::totalMass(cloth.mesh);
    const Vec3 momentum = test::totalMomentum(cloth.mesh);
    const double scale = test::momentumScale(cloth.mesh);
    const double area = test::totalRestArea(cloth.mesh);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
    for (int i = 0; i < run.tears; ++i) {
      const int vertex = std::uniform_int_distribution<int>(0, cloth.mesh.vertexCount() - 1)(random);
      const double a = angle(random);
      const ClothMesh before = cloth.mesh;
      TopologyChange change;
      if (!tearThroughVertex(cloth.mesh, vertex, Vec2(std::cos(a), std::sin(a)), guards, density, change)) {
        ASSERT_EQ(cloth.mesh.vertexCount(), before.vertexCount());
        ASSERT_EQ(cloth.mesh.edgeCount(), before.edgeCount());
        continue;
      }
      ++succeeded;
      applyTopologyChange(cloth, change);
      const std::vector<std::string> problems = checkMesh(cloth.mesh);
      ASSERT_TRUE(problems.empty()) << "tear " << i << " of grid " << run.nx << "x" << run.ny << ": " << problems.front();
      for (int t : change.changedTriangles) {
        ASSERT_GE(smallestRestAngle(cloth.mesh.tris[t]), degToRad(guards.minAngleDeg) * (1 - 1e-12))
            << "triangle " << t << " after tear " << i;
      }
      ASSERT_NEAR(test::totalMass(cloth.mesh), mass, 1e-12 * mass);
      ASSERT_LE((test::totalMomentum(cloth.mesh) - momentum).norm(), 1e-12 * scale);
      ASSERT_NEAR(test::totalRestArea(cloth.mesh), area, 1e-12 * area);
      ASSERT_TRUE(cachesMatchARebuild(cloth)) << "tear " << i;
    }
    double smallest = kPi;
    for (const Triangle& t : cloth.mesh.tris) smallest = std::min(smallest, smallestRestAngle(t));
    EXPECT_GE(smallest, degToRad(guards.minAngleDeg) * (1 - 1e-12));
    EXPECT_GT(test::connectedComponents(cloth.mesh), 1);  // the tears met each other and the border
  }
  EXPECT_GT(succeeded, 2000) << "too few tears were possible to test much";
}

}  // namespace
}  // namespace weft
