#include "mesh/grid.h"

#include <gtest/gtest.h>

#include "support/mesh_helpers.h"

#include <cmath>
#include <limits>

#include "mesh/mesh_check.h"
#include "util/input_error.h"

namespace weft {
namespace {

GridSpec spec(int nx, int ny, double width = 1.0, double height = 1.0) {
  GridSpec s;
  s.resolutionX = nx;
  s.resolutionY = ny;
  s.width = width;
  s.height = height;
  return s;
}

class GridSizes : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(GridSizes, CountsFollowTheResolution) {
  const auto [n, m] = GetParam();
  const ClothMesh mesh = makeGrid(spec(n, m, 2.0, 0.5));
  EXPECT_EQ(mesh.vertexCount(), n * m);
  EXPECT_EQ(mesh.triangleCount(), 2 * (n - 1) * (m - 1));
  EXPECT_EQ(mesh.edgeCount(), (n - 1) * m + n * (m - 1) + (n - 1) * (m - 1));

  int boundary = 0;
  for (const Edge& e : mesh.edges) boundary += e.isBoundary() ? 1 : 0;
  EXPECT_EQ(boundary, 2 * (n - 1) + 2 * (m - 1));
}

TEST_P(GridSizes, PassesTheMeshCheck) {
  const auto [n, m] = GetParam();
  const std::vector<std::string> problems = checkMesh(makeGrid(spec(n, m, 0.7, 1.3)));
  EXPECT_TRUE(problems.empty()) << problems.front();
}

TEST_P(GridSizes, HasNoPreferredDiagonal) {
  const auto [n, m] = GetParam();
  const ClothMesh mesh = makeGrid(spec(n, m));
  // A diagonal edge joins vertices differing in both ix and iy; classify it by its slope.
  int rising = 0;   // (ix, iy) - (ix+1, iy+1)
  int falling = 0;  // (ix+1, iy) - (ix, iy+1)
  for (const Edge& e : mesh.edges) {
    const int dx = e.v[1] % n - e.v[0] % n;
    const int dy = e.v[1] / n - e.v[0] / n;
    if (dx == 0 || dy == 0) continue;
    ASSERT_EQ(std::abs(dx), 1);
    ASSERT_EQ(dy, 1);
    (dx == 1 ? rising : falling)++;
  }
  EXPECT_EQ(rising + falling, (n - 1) * (m - 1));
  EXPECT_LE(std::abs(rising - falling), 1);
}

INSTANTIATE_TEST_SUITE_P(Grid, GridSizes,
                         ::testing::Values(std::pair{2, 2}, std::pair{3, 2}, std::pair{2, 5}, std::pair{4, 4},
                                           std::pair{7, 4}, std::pair{9, 9}));

TEST(Grid, DiagonalsAlternateLikeACheckerboard) {
  const int n = 5;
  const ClothMesh mesh = makeGrid(spec(n, 4));
  // The triangles of cell (ix, iy) are 2*(iy*(n-1)+ix) and the next; the one that contains both
  // (ix, iy) and (ix+1, iy+1) exists only when the cell is cut along the rising diagonal.
  for (int iy = 0; iy < 3; ++iy) {
    for (int ix = 0; ix < n - 1; ++ix) {
      const int cell = iy * (n - 1) + ix;
      const int a = iy * n + ix;
      const int c = (iy + 1) * n + ix + 1;
      bool risingDiagonal = false;
      for (int t = 2 * cell; t < 2 * cell + 2; ++t) {
        const auto& v = mesh.tris[t].v;
        const bool hasA = v[0] == a || v[1] == a || v[2] == a;
        const bool hasC = v[0] == c || v[1] == c || v[2] == c;
        risingDiagonal = risingDiagonal || (hasA && hasC);
      }
      EXPECT_EQ(risingDiagonal, (ix + iy) % 2 == 0) << "cell " << ix << ", " << iy;
    }
  }
}

TEST(Grid, VerticesAreLaidOutRowByRowInTheRestPlane) {
  const int nx = 5, ny = 3;
  const ClothMesh mesh = makeGrid(spec(nx, ny, 2.0, 0.6));
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      const Vec3& x = mesh.x[iy * nx + ix];
      EXPECT_NEAR(x.x(), 2.0 * ix / (nx - 1), 1e-15);
      EXPECT_NEAR(x.y(), 0.6 * iy / (ny - 1), 1e-15);
      EXPECT_EQ(x.z(), 0.0);
    }
  }
  // The far corner lands exactly on the requested size.
  EXPECT_EQ(mesh.x.back(), Vec3(2.0, 0.6, 0.0));
}

TEST(Grid, RestCoordinatesMatchTheVerticesMaterialPositions) {
  const ClothMesh mesh = makeGrid(spec(6, 4, 1.5, 0.9));
  for (const Triangle& t : mesh.tris) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(t.rest[k].x(), mesh.x[t.v[k]].x());
      EXPECT_EQ(t.rest[k].y(), mesh.x[t.v[k]].y());
    }
  }
}

TEST(Grid, EveryTriangleIsCounterClockwiseWithPositiveRestArea) {
  const ClothMesh mesh = makeGrid(spec(8, 6, 1.2, 0.8));
  const double cellArea = (1.2 / 7) * (0.8 / 5);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    EXPECT_NEAR(restArea(mesh.tris[t]), cellArea / 2, 1e-12) << "triangle " << t;
  }
}

TEST(Grid, TotalRestAreaIsWidthTimesHeight) {
  const ClothMesh mesh = makeGrid(spec(13, 7, 1.7, 0.45));
  double total = 0.0;
  for (const Triangle& t : mesh.tris) total += restArea(t);
  EXPECT_NEAR(total, 1.7 * 0.45, 1e-12);
}

TEST(Grid, LumpedMassTotalsDensityTimesArea) {
  ClothMesh mesh = makeGrid(spec(10, 12, 1.3, 0.9));
  assignLumpedMasses(mesh, 0.25);
  double total = 0.0;
  for (double m : mesh.mass) total += m;
  EXPECT_NEAR(total, 0.25 * 1.3 * 0.9, 1e-12);
}

TEST(Grid, StartsAtRestWithZeroMassAndNothingPinned) {
  const ClothMesh mesh = makeGrid(spec(4, 3));
  ASSERT_EQ(mesh.v.size(), 12u);
  ASSERT_EQ(mesh.mass.size(), 12u);
  ASSERT_EQ(mesh.pinned.size(), 12u);
  for (int i = 0; i < 12; ++i) {
    EXPECT_EQ(mesh.v[i], Vec3::Zero());
    EXPECT_EQ(mesh.mass[i], 0.0);
    EXPECT_EQ(mesh.pinned[i], 0);
  }
  for (const Edge& e : mesh.edges) EXPECT_FALSE(e.torn || e.cut);
}

TEST(Grid, BuildingTheSameGridTwiceGivesIdenticalArrays) {
  const ClothMesh a = makeGrid(spec(11, 9, 1.1, 0.7));
  const ClothMesh b = makeGrid(spec(11, 9, 1.1, 0.7));
  test::expectSameMesh(a, b);
}

TEST(Grid, EdgesAreSortedByTheirEndpoints) {
  const ClothMesh mesh = makeGrid(spec(6, 5));
  for (int e = 0; e < mesh.edgeCount(); ++e) {
    const Edge& edge = mesh.edges[e];
    EXPECT_LT(edge.v[0], edge.v[1]);
    if (e > 0) {
      EXPECT_LT(mesh.edges[e - 1].v, edge.v);
    }
    if (edge.tri[1] != kNone) {
      EXPECT_LT(edge.tri[0], edge.tri[1]);
    }
  }
}

TEST(Grid, BuildsA256By256Sheet) {
  const ClothMesh mesh = makeGrid(spec(256, 256));
  EXPECT_EQ(mesh.vertexCount(), 256 * 256);
  EXPECT_EQ(mesh.triangleCount(), 2 * 255 * 255);
  EXPECT_EQ(mesh.edgeCount(), 255 * 256 * 2 + 255 * 255);
  EXPECT_TRUE(checkMesh(mesh).empty());
}

void expectRejected(const GridSpec& s, const std::string& field) {
  try {
    makeGrid(s);
    ADD_FAILURE() << "expected an InputError for " << field;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
  }
}

TEST(Grid, RejectsTooFewVertices) {
  expectRejected(spec(1, 4), "grid.resolution");
  expectRejected(spec(4, 1), "grid.resolution");
  expectRejected(spec(0, -3), "grid.resolution");
}

TEST(Grid, RejectsNonPositiveOrNonFiniteSizes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  expectRejected(spec(4, 4, 0.0, 1.0), "grid.width");
  expectRejected(spec(4, 4, -1.0, 1.0), "grid.width");
  expectRejected(spec(4, 4, nan, 1.0), "grid.width");
  expectRejected(spec(4, 4, inf, 1.0), "grid.width");
  expectRejected(spec(4, 4, 1.0, 0.0), "grid.height");
  expectRejected(spec(4, 4, 1.0, nan), "grid.height");
}

TEST(Grid, RejectsMoreVerticesThanIdsCanCount) { expectRejected(spec(50000, 50000), "grid.resolution"); }

}  // namespace
}  // namespace weft
