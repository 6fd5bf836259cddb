#include "tearing/tear_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "mesh/grid.h"
#include "mesh/mesh_check.h"
#include "support/mesh_helpers.h"
#include "support/tear_checks.h"
#include "tearing/restore_quality.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

constexpr double kDensity = 0.2;  // kg/m^2

// An n x n grid over the unit square with masses and random velocities.
ClothMesh grid(int n, unsigned seed = 1) {
  GridSpec spec;
  spec.resolutionX = n;
  spec.resolutionY = n;
  ClothMesh mesh = makeGrid(spec);
  assignLumpedMasses(mesh, kDensity);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> speed(-1.0, 1.0);
  for (Vec3& v : mesh.v) v = Vec3(speed(random), speed(random), speed(random));
  return mesh;
}

Vec2 atDegrees(double deg) { return Vec2(std::cos(degToRad(deg)), std::sin(degToRad(deg))); }

::testing::AssertionResult valid(const ClothMesh& mesh) {
  const std::vector<std::string> problems = checkMesh(mesh);
  if (problems.empty()) return ::testing::AssertionSuccess();
  auto failure = ::testing::AssertionFailure() << problems.size() << " problem(s):";
  for (size_t i = 0; i < std::min<size_t>(problems.size(), 5); ++i) failure << "\n  " << problems[i];
  return failure;
}

// What a tear through the centre of a 5 x 5 grid (vertex 12) changes in the counts.
struct Growth {
  int vertices, triangles, edges, boundaryEdges, tornEdges;
};

void expectTearGrows(const Vec2& direction, const Growth& expected) {
  ClothMesh mesh = grid(5);
  const ClothMesh before = mesh;
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(mesh, 12, direction, TearGuards{}, kDensity, change));
  EXPECT_TRUE(valid(mesh));
  EXPECT_EQ(mesh.vertexCount() - before.vertexCount(), expected.vertices);
  EXPECT_EQ(mesh.triangleCount() - before.triangleCount(), expected.triangles);
  EXPECT_EQ(mesh.edgeCount() - before.edgeCount(), expected.edges);
  EXPECT_EQ(test::boundaryEdgeCount(mesh) - test::boundaryEdgeCount(before), expected.boundaryEdges);
  EXPECT_EQ(test::tornEdgeCount(mesh), expected.tornEdges);
  EXPECT_EQ(static_cast<int>(change.tornEdges.size()), expected.tornEdges);
  for (int e : change.tornEdges) {
    EXPECT_TRUE(mesh.edges[e].torn);
    EXPECT_TRUE(mesh.edges[e].isBoundary());
  }
  ASSERT_EQ(change.vertexCopies.size(), 1u);
  EXPECT_EQ(change.vertexCopies[0].first, 12);
  EXPECT_EQ(test::connectedComponents(mesh), 1);  // an interior crack opens nothing yet
}

// Along a grid edge and along a cell diagonal the tear follows existing edges: the vertex is
// copied and the two cut edges are doubled, all four copies becoming border.
TEST(TearMesh, InteriorVertexAlongAnEdgeDirection) { expectTearGrows(Vec2(1, 0), {1, 0, 2, 4, 4}); }
TEST(TearMesh, InteriorVertexAlongADiagonal) { expectTearGrows(Vec2(1, 1), {1, 0, 2, 4, 4}); }

// At 17 degrees both rays cross a triangle: each splits an opposite side (one new vertex, two
// triangles become four, three new edges), then the vertex is copied and two edges doubled.
TEST(TearMesh, InteriorVertexAtAnArbitraryAngle) { expectTearGrows(atDegrees(17), {3, 4, 8, 4, 4}); }

TEST(TearMesh, TheSplitPointLiesOnTheTearLineInEveryTriangle) {
  ClothMesh mesh = grid(5);
  const Vec2 centre(0.5, 0.5);  // vertex 12 of the unit 5 x 5 grid
  const Vec2 direction = atDegrees(17);
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(mesh, 12, direction, TearGuards{}, kDensity, change));
  const std::vector<int> splitPoints(change.newVertices.begin(), change.newVertices.end() - 1);  // last is the copy
  ASSERT_EQ(splitPoints.size(), 2u);
  // Where each ray leaves its triangle: on the grid lines x = 0.75 and x = 0.25.
  const std::array<Vec2, 2> expected{centre + direction * (0.25 / direction.x()), centre - direction * (0.25 / direction.x())};
  for (int i = 0; i < 2; ++i) {
    int uses = 0;
    for (const Triangle& t : mesh.tris) {
      const int k = cornerOf(t, splitPoints[i]);
      if (k == kNone) continue;
      ++uses;
      EXPECT_NEAR(cross2(direction, t.rest[k] - centre), 0.0, 1e-15);
      EXPECT_NEAR((t.rest[k] - expected[i]).norm(), 0.0, 1e-15);
    }
    EXPECT_EQ(uses, 4);  // two pieces on each side of the split edge
    // The position interpolates the endpoints' like the rest coordinates (flat grid: the same).
    EXPECT_NEAR((mesh.x[splitPoints[i]].head<2>() - expected[i]).norm(), 0.0, 1e-15);
  }
}

// What a tear must keep: the totals of a mesh before it, compared with the mesh after it (mass,
// momentum and rest area to round-off; lumped masses as a from-scratch assignment gives them).
struct Totals {
  double mass, area;
  Vec3 momentum;
  explicit Totals(const ClothMesh& mesh)
      : mass(test::totalMass(mesh)), area(test::totalRestArea(mesh)), momentum(test::totalMomentum(mesh)) {}
};

void expectKept(const Totals& before, const ClothMesh& mesh) {
  EXPECT_NEAR(test::totalMass(mesh), before.mass, 1e-12 * before.mass);
  EXPECT_LE((test::totalMomentum(mesh) - before.momentum).norm(), 1e-12 * test::momentumScale(mesh));
  EXPECT_NEAR(test::totalRestArea(mesh), before.area, 1e-12 * before.area);
  ClothMesh reassigned = mesh;
  assignLumpedMasses(reassigned, kDensity);
  for (int i = 0; i < mesh.vertexCount(); ++i) EXPECT_NEAR(mesh.mass[i], reassigned.mass[i], 1e-15) << i;
}

TEST(TearMesh, KeepsMassMomentumAndRestArea) {
  for (double deg : {0.0, 17.0, 45.0, 62.0, 133.0}) {
    ClothMesh mesh = grid(6, 7);
    const Totals before(mesh);
    TopologyChange change;
    ASSERT_TRUE(tearThroughVertex(mesh, 14, atDegrees(deg), TearGuards{}, kDensity, change)) << deg;
    expectKept(before, mesh);
  }
}

// A separated vertex's copies keep the velocity; an inserted vertex's velocity is a positive-weight
// average of its neighbours' (inside their bounding box).
TEST(TearMesh, NewVerticesTakeConsistentVelocities) {
  ClothMesh mesh = grid(5, 3);
  const ClothMesh before = mesh;
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(mesh, 12, atDegrees(17), TearGuards{}, kDensity, change));
  for (const auto& [original, copy] : change.vertexCopies) EXPECT_EQ(mesh.v[copy], mesh.v[original]);
  Vec3 lo = before.v[0], hi = before.v[0];
  for (const Vec3& v : before.v) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  for (int q : change.newVertices) {
    EXPECT_TRUE((mesh.v[q].array() >= lo.array() - 1e-12).all() && (mesh.v[q].array() <= hi.array() + 1e-12).all());
  }
}

// Tears from the left border along y = 0.5, each from the crack's current end, until the cloth
// falls in two.
void tearAcross(ClothMesh& mesh, int startVertex, const Vec2& direction, int maxTears) {
  int tip = startVertex;
  for (int i = 0; i < maxTears && test::connectedComponents(mesh) == 1; ++i) {
    TopologyChange change;
    ASSERT_TRUE(tearThroughVertex(mesh, tip, direction, TearGuards{}, kDensity, change)) << "tear " << i;
    ASSERT_TRUE(valid(mesh)) << "tear " << i;
    ASSERT_EQ(change.crackEnds.size(), 1u);
    tip = change.crackEnds[0];
  }
}

TEST(TearMesh, AStraightTearAcrossTheGridOpensIt) {
  ClothMesh mesh = grid(9);
  const double mass = test::totalMass(mesh);
  tearAcross(mesh, 4 * 9, Vec2(1, 0), 8);
  EXPECT_EQ(test::connectedComponents(mesh), 2);
  EXPECT_EQ(test::tornEdgeCount(mesh), 16);  // 8 edges, two copies each
  EXPECT_EQ(mesh.vertexCount(), 81 + 9);     // every vertex on the line copied once
  EXPECT_NEAR(test::totalMass(mesh), mass, 1e-12 * mass);
}

TEST(TearMesh, ASlantedTearAcrossTheGridOpensIt) {
  ClothMesh mesh = grid(9);
  tearAcross(mesh, 3 * 9, atDegrees(17), 40);
  EXPECT_EQ(test::connectedComponents(mesh), 2);
}

TEST(TearMesh, ADirectionWithinTheSnapAngleFollowsTheEdge) {
  TearGuards guards;
  guards.minAngleDeg = 1.0;
  guards.snapAngleDeg = 10.0;
  ClothMesh mesh = grid(5);
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(mesh, 12, atDegrees(7), guards, kDensity, change));
  EXPECT_EQ(change.newVertices.size(), 1u);  // only the copy: no split point
  EXPECT_EQ(mesh.triangleCount(), 32);

  guards.snapAngleDeg = 5.0;  // now 7 degrees crosses
  mesh = grid(5);
  ASSERT_TRUE(tearThroughVertex(mesh, 12, atDegrees(7), guards, kDensity, change));
  EXPECT_EQ(change.newVertices.size(), 3u);
  EXPECT_TRUE(valid(mesh));
}

// Every torn edge of the mesh lies on the line through `centre` along `direction` (material space).
void expectTornEdgesOnTheLine(const ClothMesh& mesh, const Vec2& centre, const Vec2& direction) {
  int torn = 0;
  for (const Edge& e : mesh.edges) {
    if (!e.torn) continue;
    ++torn;
    const Triangle& t = mesh.tris[e.tri[0]];
    for (int v : e.v) EXPECT_NEAR(cross2(direction.normalized(), t.rest[cornerOf(t, v)] - centre), 0.0, 1e-12);
  }
  EXPECT_GT(torn, 0);
}

// A crossing that would make a sliver moves the end of the entered triangle's opposite side onto
// the line and follows its edge: the crack stays on the line, with no split point and no sliver.
TEST(TearMesh, ACrossingThatWouldMakeASliverMovesTheNearerVertexOntoTheLine) {
  TearGuards guards;
  guards.snapAngleDeg = 0.0;
  guards.minAngleDeg = 20.0;  // 17 degrees at the vertex is too thin to cross
  ClothMesh mesh = grid(5);
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(mesh, 12, atDegrees(17), guards, kDensity, change));
  EXPECT_EQ(change.newVertices.size(), 1u);  // only the copy
  EXPECT_EQ(change.movedVertices.size(), 2u);  // one end for each ray
  expectTornEdgesOnTheLine(mesh, Vec2(0.5, 0.5), atDegrees(17));
  for (const Triangle& t : mesh.tris) EXPECT_GE(smallestRestAngle(t), degToRad(20.0) * (1 - 1e-12));
  EXPECT_TRUE(valid(mesh));

  guards.minAngleDeg = 1.0;
  guards.minEdgeLength = 0.1;  // the split point would be 0.08 m from a grid vertex: too close
  mesh = grid(5);
  ASSERT_TRUE(tearThroughVertex(mesh, 12, atDegrees(17), guards, kDensity, change));
  EXPECT_EQ(change.newVertices.size(), 1u);
  expectTornEdgesOnTheLine(mesh, Vec2(0.5, 0.5), atDegrees(17));
  EXPECT_TRUE(valid(mesh));
}

// A move keeps what a split keeps: mass, momentum and the rest area exactly, lumped masses as a
// fresh assignment gives them, and the deformation: on a cloth deformed by an affine map the moved
// vertex lands where the map takes its new material point (so no strain appears).
TEST(TearMesh, AMoveKeepsMassMomentumRestAreaAndTheDeformation) {
  Mat3 map;
  map << 1.3, 0.2, 0.0, -0.1, 0.9, 0.0, 0.4, 0.3, 1.0;
  const Vec3 shift(0.2, -0.5, 1.0);
  for (const double deg : {3.0, 8.0, 12.0, 38.0, 85.0}) {
    ClothMesh mesh = grid(6, 11);
    for (const Triangle& t : mesh.tris) {
      for (int k = 0; k < 3; ++k) mesh.x[t.v[k]] = map * Vec3(t.rest[k].x(), t.rest[k].y(), 0.0) + shift;
    }
    const Totals before(mesh);
    TopologyChange change;
    ASSERT_TRUE(tearThroughVertex(mesh, 14, atDegrees(deg), TearGuards{}, kDensity, change)) << deg;
    EXPECT_FALSE(change.movedVertices.empty()) << deg << " degrees: a move was expected";
    expectKept(before, mesh);
    for (int v : change.movedVertices) {
      const Triangle& t = mesh.tris[findTriangleAt(mesh, v)];
      const Vec2 rest = t.rest[cornerOf(t, v)];
      EXPECT_LE((mesh.x[v] - (map * Vec3(rest.x(), rest.y(), 0.0) + shift)).norm(), 1e-6) << deg;  // 1e-6: the nudge
    }
    EXPECT_TRUE(valid(mesh));
  }
}

// A ray whose crossing leaves a thin triangle beyond the crossed side that flips there cannot
// mend, where no neighbour may move onto the line (all eight pinned: a crack between clamps), used
// to be refused, and a crack tip there stalled for good (measured on the ball scene at 32^2: its
// flap's right tip, refused in every later step). It now crosses on its line and the guards are
// restored by flips and splits over the vertex's and the crossing's fans (restore_quality.h):
// every triangle keeps 15 degrees and 1 mm, mass and momentum are kept, nothing pinned moves.
TEST(TearMesh, AThinCrossingWhereNoVertexMayMoveIsReTriangulatedNotRefused) {
  for (const double deg : {31.0, 35.0, 39.0, 52.0}) {
    ClothMesh mesh = grid(5);
    const std::vector<int> ring{6, 7, 8, 11, 13, 16, 17, 18};
    for (int v : ring) mesh.pinned[v] = 1;
    const ClothMesh start = mesh;
    const Totals before(mesh);
    TopologyChange change;
    ASSERT_TRUE(tearThroughVertex(mesh, 12, atDegrees(deg), TearGuards{}, kDensity, change)) << deg;
    EXPECT_TRUE(change.movedVertices.empty()) << deg;
    EXPECT_GT(mesh.vertexCount(), start.vertexCount() + 2) << deg << " degrees: a split beyond the crossing";
    expectTornEdgesOnTheLine(mesh, Vec2(0.5, 0.5), atDegrees(deg));
    for (const Triangle& t : mesh.tris) {
      EXPECT_TRUE(keepsGuards(t, TearGuards{})) << deg << " degrees: smallest angle "
                                                << smallestRestAngle(t) * 180.0 / kPi;
    }
    expectKept(before, mesh);
    for (int v : ring) EXPECT_EQ(mesh.x[v], start.x[v]) << deg;
    EXPECT_TRUE(valid(mesh)) << deg;
  }
}

// Pinned vertices never move: a ray whose only ways are a sliver or a move of a pinned vertex
// follows the nearer edge within the snap angle, and is refused beyond it.
TEST(TearMesh, PinnedVerticesAreNotMovedAndTheRayFollowsWithinTheSnapAngleOrIsRefused) {
  ClothMesh mesh = grid(5);
  for (int v = 0; v < mesh.vertexCount(); ++v) mesh.pinned[v] = v != 12;
  const ClothMesh before = mesh;
  TopologyChange change;
  EXPECT_FALSE(tearThroughVertex(mesh, 12, atDegrees(9), TearGuards{}, kDensity, change));
  test::expectSameMesh(mesh, before);
  ASSERT_TRUE(tearThroughVertex(mesh, 12, atDegrees(4), TearGuards{}, kDensity, change));
  EXPECT_TRUE(change.movedVertices.empty());
  EXPECT_TRUE(valid(mesh));
}

TEST(TearMesh, ARayOutOfABorderVertexsFanIsRefusedAndChangesNothing) {
  ClothMesh mesh = grid(5);
  const ClothMesh before = mesh;
  TopologyChange change;
  EXPECT_FALSE(tearThroughVertex(mesh, 2, Vec2(0.3, -1), TearGuards{}, kDensity, change));  // bottom border, pointing down
  EXPECT_FALSE(tearThroughVertex(mesh, 2, Vec2(1, 0), TearGuards{}, kDensity, change));     // along the border
  EXPECT_FALSE(tearThroughVertex(mesh, 12, Vec2(0, 0), TearGuards{}, kDensity, change));    // no direction
  EXPECT_TRUE(change.newVertices.empty());
  test::expectSameMesh(mesh, before);
}

TEST(TearMesh, ABorderVertexTearsAlongOneRay) {
  ClothMesh mesh = grid(5);
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(mesh, 2, Vec2(0, 1), TearGuards{}, kDensity, change));
  EXPECT_TRUE(valid(mesh));
  EXPECT_EQ(change.tornEdges.size(), 2u);
  EXPECT_EQ(mesh.vertexCount(), 26);
  EXPECT_EQ(change.crackEnds, std::vector<int>{7});
}

TEST(TearMesh, PinnedVerticesPassTheFlagToTheirCopies) {
  ClothMesh mesh = grid(5);
  mesh.pinned[12] = 1;
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(mesh, 12, Vec2(1, 0), TearGuards{}, kDensity, change));
  ASSERT_EQ(change.vertexCopies.size(), 1u);
  EXPECT_EQ(mesh.pinned[change.vertexCopies[0].second], 1);
}

// A line whose two ends are pinned never tears: cloth held in a clamp's jaws cannot open. The top
// two rows of the 5 x 5 grid are the clamp (0.25 m cells). Refused: a line from a pinned vertex to
// a pinned vertex, and one across a clamped triangle to a point it would insert between two; the
// mesh is left as it was. A crack from the free cloth still reaches the clamp's edge, and stops
// there: no ray from its tip into the clamp tears.
TEST(TearMesh, ALineWhoseTwoEndsArePinnedIsRefused) {
  ClothMesh mesh = grid(5);
  for (int v = 15; v < 25; ++v) mesh.pinned[v] = 1;
  const ClothMesh before = mesh;
  TopologyChange change;
  EXPECT_FALSE(tearThroughVertex(mesh, 17, Vec2(1, 0), TearGuards{}, kDensity, change));  // along the clamp's edge
  EXPECT_FALSE(tearThroughVertex(mesh, 17, Vec2(0, 1), TearGuards{}, kDensity, change));  // up into it (and down)
  EXPECT_FALSE(tearThroughVertex(mesh, 17, atDegrees(135), TearGuards{}, kDensity, change));  // to the middle of 16-22
  EXPECT_FALSE(tearThroughVertex(mesh, 22, Vec2(0, -1), TearGuards{}, kDensity, change));  // from the border in
  EXPECT_TRUE(change.newVertices.empty());
  test::expectSameMesh(mesh, before);

  ASSERT_TRUE(tearThroughVertex(mesh, 12, Vec2(0, 1), TearGuards{}, kDensity, change));
  EXPECT_TRUE(valid(mesh));
  EXPECT_NE(std::find(change.crackEnds.begin(), change.crackEnds.end(), 17), change.crackEnds.end());
  for (double deg = 0.0; deg <= 180.0; deg += 15.0) {
    EXPECT_FALSE(tearThroughVertex(mesh, 17, atDegrees(deg), TearGuards{}, kDensity, change)) << deg;
  }
}

// A crack from the free cloth that meets the clamp's edge between two pinned vertices inserts a
// point there. The jaws hold it as they hold its neighbours: it is pinned, and no ray from it into
// the clamp tears (else the crack would go on into the jaws from a vertex that is not pinned).
TEST(TearMesh, APointInsertedBetweenTwoPinnedVerticesIsPinnedAndHeld) {
  ClothMesh mesh = grid(5);
  for (int v = 15; v < 25; ++v) mesh.pinned[v] = 1;
  TopologyChange change;
  // From (0.5, 0.5) at 65 degrees: across triangle (12, 18, 17) to edge 17-18, on the clamp's edge.
  ASSERT_TRUE(tearThroughVertex(mesh, 12, atDegrees(65), TearGuards{}, kDensity, change));
  EXPECT_TRUE(valid(mesh));
  ASSERT_EQ(change.pinnedSplits.size(), 1u);
  const PinnedSplit split = change.pinnedSplits[0];
  EXPECT_EQ(std::minmax(split.from, split.to), std::minmax(17, 18));
  int pinnedNew = 0;
  for (int v : change.newVertices) pinnedNew += mesh.pinned[v];
  EXPECT_EQ(pinnedNew, 1);  // the other ray's split point, in the free cloth, is free
  EXPECT_EQ(mesh.pinned[split.vertex], 1);
  EXPECT_NE(std::find(change.crackEnds.begin(), change.crackEnds.end(), split.vertex), change.crackEnds.end());
  for (double deg = 0.0; deg <= 180.0; deg += 15.0) {
    EXPECT_FALSE(tearThroughVertex(mesh, split.vertex, atDegrees(deg), TearGuards{}, kDensity, change)) << deg;
  }
}

}  // namespace
}  // namespace weft
