#include "sim/cloth_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/grid.h"
#include "tearing/tear_mesh.h"

namespace weft {
namespace {

Cloth gridCloth(int resolution = 5) {
  Cloth cloth;
  GridSpec spec;
  spec.resolutionX = resolution;
  spec.resolutionY = resolution;
  cloth.mesh = makeGrid(spec);
  assignLumpedMasses(cloth.mesh, cloth.material.areaDensity);
  rebuildElements(cloth);
  return cloth;
}

bool hasHingeOn(const Cloth& cloth, int edge) {
  return std::any_of(cloth.hinges.begin(), cloth.hinges.end(), [edge](const BendingHinge& h) { return h.edge == edge; });
}

TEST(ClothTopology, TornEdgesLoseTheirHingesAndNewTrianglesGetMembranes) {
  Cloth cloth = gridCloth();
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(cloth.mesh, 12, Vec2(1, 0.3), TearGuards{}, cloth.material.areaDensity, change));
  applyTopologyChange(cloth, change);
  ASSERT_EQ(cloth.membranes.size(), cloth.mesh.tris.size());
  for (int t : change.newTriangles) EXPECT_EQ(cloth.membranes[t].v, cloth.mesh.tris[t].v);
  for (int e : change.tornEdges) EXPECT_FALSE(hasHingeOn(cloth, e));
  // The spokes from the split points into the neighbours are interior and new: they bend.
  int newInteriorEdges = 0;
  for (int e : change.newEdges) {
    if (!cloth.mesh.edges[e].isBoundary()) {
      ++newInteriorEdges;
      EXPECT_TRUE(hasHingeOn(cloth, e)) << e;
    }
  }
  EXPECT_GT(newInteriorEdges, 0);
  EXPECT_EQ(cloth.hinges.size(), buildBendingHinges(cloth.mesh, cloth.weftAngleRad).size());
}

// A step's tears refresh the hinges once (refreshHingesAfter): the same hinges, in the same order,
// as refreshing them after every tear, on a crack whose later tears change the earlier ones' edges.
TEST(ClothTopology, HingesRefreshedOnceForManyTearsEqualThoseRefreshedAfterEach) {
  Cloth eachTime = gridCloth(9);
  Cloth once = gridCloth(9);
  std::vector<std::vector<int>> changedEdges;
  // A crack along the middle row (vertex 40 is the centre of the 9 x 9 grid), then one across it
  // at its end, and tears beside them that change the edges the first ones made.
  const std::vector<std::pair<int, Vec2>> tears = {{40, Vec2(1, 0.3)}, {42, Vec2(1, 0.1)}, {38, Vec2(1, -0.2)},
                                                   {24, Vec2(0.2, 1)}, {58, Vec2(-0.3, 1)}, {41, Vec2(0.1, 1)},
                                                   {50, Vec2(1, 1)}};
  int torn = 0;
  for (const auto& [vertex, direction] : tears) {
    TopologyChange first, second;
    const bool a = tearThroughVertex(eachTime.mesh, vertex, direction, TearGuards{}, eachTime.material.areaDensity, first);
    const bool b = tearThroughVertex(once.mesh, vertex, direction, TearGuards{}, once.material.areaDensity, second);
    ASSERT_EQ(a, b);
    if (!a) continue;
    ++torn;
    applyTopologyChange(eachTime, first);
    applyTopologyChangeButHinges(once, second);
    changedEdges.push_back(second.changedEdges);
    EXPECT_EQ(once.membranes.size(), eachTime.membranes.size());
  }
  ASSERT_GE(torn, 3);
  refreshHingesAfter(once, changedEdges);
  ASSERT_EQ(once.hinges.size(), eachTime.hinges.size());
  for (std::size_t h = 0; h < once.hinges.size(); ++h) {
    EXPECT_EQ(once.hinges[h].edge, eachTime.hinges[h].edge) << h;
    EXPECT_EQ(once.hinges[h].v, eachTime.hinges[h].v) << h;
    EXPECT_EQ(once.hinges[h].restLength, eachTime.hinges[h].restLength) << h;
    EXPECT_EQ(once.hinges[h].restAreaSum, eachTime.hinges[h].restAreaSum) << h;
    EXPECT_EQ(once.hinges[h].edgeAngle, eachTime.hinges[h].edgeAngle) << h;
  }
  EXPECT_EQ(once.hinges.size(), buildBendingHinges(once.mesh, once.weftAngleRad).size());
}

TEST(ClothTopology, ACopyOfAPinnedVertexJoinsItsTrackAtTheSameStart) {
  Cloth cloth = gridCloth();
  PinTrack track;
  track.vertices = {2, 12, 20};
  for (int v : track.vertices) {
    track.start.push_back(cloth.mesh.x[v] + Vec3(0, 0, v));  // distinct starts, to see which one is copied
    cloth.mesh.pinned[v] = 1;
  }
  cloth.pins.push_back(track);
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(cloth.mesh, 12, Vec2(0, 1), TearGuards{}, cloth.material.areaDensity, change));
  applyTopologyChange(cloth, change);
  ASSERT_EQ(change.vertexCopies.size(), 1u);
  const int copy = change.vertexCopies[0].second;
  const PinTrack& after = cloth.pins[0];
  EXPECT_EQ(after.vertices, (std::vector<int>{2, 12, 20, copy}));
  ASSERT_EQ(after.start.size(), 4u);
  EXPECT_EQ(after.start[3], after.start[1]);
  EXPECT_EQ(cloth.mesh.pinned[copy], 1);
}

// A point a tear inserts between two pinned vertices is held by the same clamp: it joins their
// track, from the start interpolated between theirs.
TEST(ClothTopology, APointInsertedBetweenTwoPinnedVerticesJoinsTheirTrackBetweenTheirStarts) {
  Cloth cloth = gridCloth();
  PinTrack track;
  for (int v = 15; v < 25; ++v) {
    track.vertices.push_back(v);
    track.start.push_back(cloth.mesh.x[v] + Vec3(0, 0, v));  // distinct starts, to see the interpolation
    cloth.mesh.pinned[v] = 1;
  }
  cloth.pins.push_back(track);
  TopologyChange change;
  const Vec2 along(std::cos(65.0 * std::numbers::pi / 180.0), std::sin(65.0 * std::numbers::pi / 180.0));
  ASSERT_TRUE(tearThroughVertex(cloth.mesh, 12, along, TearGuards{}, cloth.material.areaDensity, change));
  applyTopologyChange(cloth, change);
  ASSERT_EQ(change.pinnedSplits.size(), 1u);
  const PinnedSplit& split = change.pinnedSplits[0];
  const PinTrack& after = cloth.pins[0];
  EXPECT_TRUE(std::is_sorted(after.vertices.begin(), after.vertices.end()));
  ASSERT_EQ(after.vertices.size(), track.vertices.size() + 1);
  ASSERT_EQ(after.start.size(), after.vertices.size());
  const auto at = std::find(after.vertices.begin(), after.vertices.end(), split.vertex);
  ASSERT_NE(at, after.vertices.end());
  const Vec3 expected = (1.0 - split.fraction) * track.start[split.from - 15] + split.fraction * track.start[split.to - 15];
  EXPECT_LT((after.start[at - after.vertices.begin()] - expected).norm(), 1e-12);
  EXPECT_EQ(cloth.mesh.pinned[split.vertex], 1);
}

}  // namespace
}  // namespace weft
