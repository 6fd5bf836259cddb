// The averaged stress a tear reads (tearing/nonlocal_stress.h): the load itself where it is
// uniform, never averaged across a crack, patched after a tear exactly as a fresh average, and
// converging where the local stress is singular.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mesh/grid.h"
#include "tearing/nonlocal_stress.h"
#include "tearing/stress_kernel.h"
#include "tearing/tear_mesh.h"

namespace weft {
namespace {

ClothMesh grid(int n) {
  GridSpec spec;
  spec.resolutionX = n;
  spec.resolutionY = n;
  ClothMesh mesh = makeGrid(spec);
  assignLumpedMasses(mesh, 0.3);
  return mesh;
}

Vec2 centroid(const ClothMesh& mesh, int t) {
  const Triangle& tri = mesh.tris[t];
  return (tri.rest[0] + tri.rest[1] + tri.rest[2]) / 3.0;
}

Mat2 tensor(double xx, double yy, double xy) {
  Mat2 s;
  s << xx, xy, xy, yy;
  return s;
}

TEST(NonlocalStress, AUniformStressIsItsOwnAverage) {
  const ClothMesh mesh = grid(17);
  const std::vector<Mat2> local(mesh.tris.size(), tensor(120.0, 40.0, 15.0));
  NonlocalStress averaged;
  std::vector<Mat2> out;
  averaged.average(mesh, local, 0.1, 0.0, out);
  for (const Mat2& s : out) EXPECT_LT((s - local[0]).norm(), 1e-9);
}

TEST(NonlocalStress, TheAverageDoesNotReachAcrossACrack) {
  // A crack along x = 0.5 from border to border: the left half loaded, the right half not.
  ClothMesh mesh = grid(17);
  TearGuards guards;
  int torn = 0;
  for (int iy = 0; iy < 17; ++iy) {
    TopologyChange change;
    if (tearThroughVertex(mesh, iy * 17 + 8, Vec2(0.0, 1.0), guards, 0.3, change)) ++torn;
  }
  ASSERT_GT(torn, 0);
  std::vector<Mat2> local(mesh.tris.size());
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    local[t] = centroid(mesh, t).x() < 0.5 ? tensor(100.0, 0.0, 0.0) : Mat2::Zero();
  }
  NonlocalStress averaged;
  std::vector<Mat2> out;
  averaged.average(mesh, local, 0.15, 0.0, out);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    EXPECT_LT((out[t] - local[t]).norm(), 1e-9) << "triangle " << t << " at x = " << centroid(mesh, t).x();
  }
}

// The triangles along a crack's lips read the lips' own stretch (tearing/nonlocal_stress.h): left
// out, a uniform load is read as itself right up to the lips and the tip, whatever the lips read.
TEST(NonlocalStress, ALipsOwnStretchIsLeftOutOfTheAverages) {
  // A slit from the top border down to the middle, along x = 0.5.
  ClothMesh mesh = grid(17);
  TearGuards guards;
  int torn = 0;
  for (int iy = 16; iy >= 8; --iy) {
    TopologyChange change;
    if (tearThroughVertex(mesh, iy * 17 + 8, Vec2(0.0, 1.0), guards, 0.3, change)) ++torn;
  }
  ASSERT_GT(torn, 0);
  const Mat2 load = tensor(100.0, 20.0, 5.0);
  std::vector<Mat2> local(mesh.tris.size(), load);
  int lips = 0;
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    for (int e : mesh.tris[t].edge) {
      if (mesh.edges[e].torn && mesh.edges[e].isBoundary()) {
        local[t] = tensor(100.0, 5000.0, 0.0);  // stretched along the lip, as an opening lip reads
        ++lips;
        break;
      }
    }
  }
  ASSERT_GT(lips, 4);
  NonlocalStress averaged;
  std::vector<Mat2> out;
  averaged.average(mesh, local, 0.15, 0.0, out);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    EXPECT_LT((out[t] - load).norm(), 1e-9) << "triangle " << t << " at " << centroid(mesh, t).transpose();
  }
}

// A random tensile-like stress per triangle.
std::vector<Mat2> randomStresses(const ClothMesh& mesh, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Mat2> local(mesh.tris.size());
  for (Mat2& s : local) s = tensor(100.0 * unit(random), 50.0 * unit(random), 10.0 * unit(random));
  return local;
}

// Up to 25 random tears through the mesh, each changed triangle given a new stress and the
// averages patched as the tear stage does; returns how many tears were made.
int tearAndPatch(ClothMesh& mesh, std::mt19937& random, std::vector<Mat2>& local, NonlocalStress& patched,
                 std::vector<Mat2>& out) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  TearGuards guards;
  int tears = 0;
  for (int attempt = 0; attempt < 200 && tears < 25; ++attempt) {
    const int vertex = static_cast<int>(unit(random) * mesh.vertexCount()) % mesh.vertexCount();
    const double angle = unit(random) * 3.14159;
    TopologyChange change;
    if (!tearThroughVertex(mesh, vertex, Vec2(std::cos(angle), std::sin(angle)), guards, 0.3, change)) continue;
    ++tears;
    local.resize(mesh.tris.size());
    for (int t : change.changedTriangles) local[t] = tensor(100.0 * unit(random), 50.0 * unit(random), 0.0);
    std::vector<int> seeds = change.changedTriangles;
    for (int e : change.changedEdges) {
      for (int t : mesh.edges[e].tri) {
        if (t != kNone) seeds.push_back(t);
      }
    }
    patched.patch(mesh, local, seeds, out);
  }
  return tears;
}

TEST(NonlocalStress, APatchAfterTearsEqualsAFreshAverage) {
  ClothMesh mesh = grid(21);
  std::mt19937 random(7);
  std::vector<Mat2> local = randomStresses(mesh, random);
  NonlocalStress patched;
  std::vector<Mat2> out;
  patched.average(mesh, local, 0.12, 0.0, out);
  ASSERT_GT(tearAndPatch(mesh, random, local, patched, out), 10);
  NonlocalStress fresh;
  std::vector<Mat2> expected;
  fresh.average(mesh, local, 0.12, 0.0, expected);
  // The next average rebuilds what the patches left: every neighbourhood as a fresh object's.
  patched.average(mesh, local, 0.12, 0.0, out);
  ASSERT_EQ(out.size(), expected.size());
  for (std::size_t t = 0; t < out.size(); ++t) EXPECT_LT((out[t] - expected[t]).norm(), 1e-9) << "triangle " << t;
}

// Right after a tear, the triangles it changed or added read their own neighbourhoods on the torn
// mesh (as a fresh object's); the others keep the step's averages until the next average call.
TEST(NonlocalStress, RightAfterATearTheChangedTrianglesReadTheTornMesh) {
  ClothMesh mesh = grid(21);
  std::mt19937 random(9);
  std::vector<Mat2> local = randomStresses(mesh, random);
  NonlocalStress patched;
  std::vector<Mat2> out;
  patched.average(mesh, local, 0.12, 0.0, out);
  const std::vector<Mat2> before = out;
  TearGuards guards;
  TopologyChange change;
  ASSERT_TRUE(tearThroughVertex(mesh, 10 * 21 + 10, Vec2(0.0, 1.0), guards, 0.3, change));
  local.resize(mesh.tris.size());
  for (int t : change.changedTriangles) local[t] = tensor(300.0, 0.0, 0.0);
  std::vector<int> seeds = change.changedTriangles;
  for (int e : change.changedEdges) {
    for (int t : mesh.edges[e].tri) {
      if (t != kNone) seeds.push_back(t);
    }
  }
  const std::vector<int> recomputed = patched.patch(mesh, local, seeds, out);
  NonlocalStress fresh;
  std::vector<Mat2> expected;
  fresh.average(mesh, local, 0.12, 0.0, expected);
  ASSERT_FALSE(recomputed.empty());
  for (int t : recomputed) EXPECT_LT((out[t] - expected[t]).norm(), 1e-9) << "changed triangle " << t;
  int kept = 0;
  for (std::size_t t = 0; t < before.size(); ++t) {
    if (std::binary_search(recomputed.begin(), recomputed.end(), static_cast<int>(t))) continue;
    EXPECT_EQ(out[t], before[t]) << "triangle " << t;
    kept += (out[t] - expected[t]).norm() > 1e-6;  // stale until the next average
  }
  EXPECT_GT(kept, 0) << "some neighbour's average should wait for the next step";
}

// Two averages agree to rounding, relative to the larger stress of the two.
void expectSameAverages(const std::vector<Mat2>& got, const std::vector<Mat2>& expected) {
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t t = 0; t < got.size(); ++t) {
    const double scale = std::max({got[t].norm(), expected[t].norm(), 1e-300});
    EXPECT_LE((got[t] - expected[t]).norm(), 1e-12 * scale) << "triangle " << t;
  }
}

// The neighbourhoods are kept from one call to the next (they depend on the mesh, not on the
// stress): a second call with another stress reads as a fresh object's first, near a crack too.
TEST(NonlocalStress, AKeptNeighbourhoodAveragesAnotherStressAsAFreshOne) {
  ClothMesh mesh = grid(21);
  TearGuards guards;
  int torn = 0;
  for (int iy = 20; iy >= 10; --iy) {
    TopologyChange change;
    if (tearThroughVertex(mesh, iy * 21 + 10, Vec2(0.0, 1.0), guards, 0.3, change)) ++torn;
  }
  ASSERT_GT(torn, 0);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Mat2> first(mesh.tris.size()), second(mesh.tris.size());
  for (Mat2& s : first) s = tensor(100.0 * unit(random), 50.0 * unit(random), 10.0 * unit(random));
  for (Mat2& s : second) s = tensor(100.0 * unit(random), 50.0 * unit(random), 10.0 * unit(random));
  for (double threshold : {0.0, 90.0}) {  // everywhere, and only around the hot triangles
    NonlocalStress kept;
    std::vector<Mat2> out;
    kept.average(mesh, first, 0.12, threshold, out);
    kept.average(mesh, second, 0.12, threshold, out);
    NonlocalStress fresh;
    std::vector<Mat2> expected;
    fresh.average(mesh, second, 0.12, threshold, expected);
    expectSameAverages(out, expected);
  }
}

// After tears and their patches, the next step's average on the patched object reads the torn
// mesh as a fresh object does: no neighbourhood kept from before a tear reaches across it.
TEST(NonlocalStress, AnAverageAfterPatchesEqualsAFreshOne) {
  ClothMesh mesh = grid(21);
  std::mt19937 random(5);
  std::vector<Mat2> local = randomStresses(mesh, random);
  NonlocalStress patched;
  std::vector<Mat2> out;
  patched.average(mesh, local, 0.12, 0.0, out);
  ASSERT_GT(tearAndPatch(mesh, random, local, patched, out), 10);
  // The next step: a new stress everywhere, the lists kept.
  local = randomStresses(mesh, random);
  patched.average(mesh, local, 0.12, 0.0, out);
  NonlocalStress fresh;
  std::vector<Mat2> expected;
  fresh.average(mesh, local, 0.12, 0.0, expected);
  expectSameAverages(out, expected);
}

TEST(NonlocalStress, OnlyTrianglesNearAStressThatCouldTearAreAveraged) {
  const ClothMesh mesh = grid(33);
  std::vector<Mat2> local(mesh.tris.size(), tensor(1.0, 1.0, 0.0));
  int hot = 0;
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    if ((centroid(mesh, t) - Vec2(0.2, 0.2)).norm() < 0.03) {
      local[t] = tensor(500.0, 0.0, 0.0);
      ++hot;
    }
  }
  ASSERT_GT(hot, 0);
  NonlocalStress averaged;
  std::vector<Mat2> out;
  averaged.average(mesh, local, 0.08, 100.0, out);
  NonlocalStress everywhere;
  std::vector<Mat2> all;
  everywhere.average(mesh, local, 0.08, 0.0, all);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    const double d = (centroid(mesh, t) - Vec2(0.2, 0.2)).norm();
    if (d < 0.1) EXPECT_LT((out[t] - all[t]).norm(), 1e-9) << "near the hot spot, at " << d;
    if (d > 0.3) EXPECT_LT((out[t] - local[t]).norm(), 1e-12) << "far from it, at " << d;
  }
}

// A sheet with a crack from border to border along x = 0.5 (the left and right halves joined by
// nothing).
ClothMesh splitDown(int n) {
  ClothMesh mesh = grid(n);
  TearGuards guards;
  for (int iy = 0; iy < n; ++iy) {
    TopologyChange change;
    tearThroughVertex(mesh, iy * n + n / 2, Vec2(0.0, 1.0), guards, 0.3, change);
  }
  return mesh;
}

// A stress rising steeply across x, and a bump.
std::vector<Mat2> steepStress(const ClothMesh& mesh) {
  std::vector<Mat2> local(mesh.tris.size());
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    const Vec2 c = centroid(mesh, t);
    const double bump = std::exp(-((c - Vec2(0.45, 0.5)).squaredNorm()) / (0.04 * 0.04));
    local[t] = tensor(100.0 + 2000.0 * c.x() + 300.0 * bump, 50.0 + 500.0 * c.y(), 20.0 * bump);
  }
  return local;
}

bool isLip(const ClothMesh& mesh, int t) {
  for (int e : mesh.tris[t].edge) {
    if (mesh.edges[e].torn && mesh.edges[e].isBoundary()) return true;
  }
  return false;
}

// Away from cracks and borders the average is the kernel's over every triangle (the lattice),
// to rounding; beside a crack, the bell's over the triangles on the same side (a list).
TEST(NonlocalStress, TheLatticeAndTheListsReadWhatTheKernelAndTheBellWeigh) {
  const double radius = 0.065;
  const ClothMesh mesh = splitDown(65);
  const std::vector<Mat2> local = steepStress(mesh);
  NonlocalStress averaged;
  std::vector<Mat2> out;
  averaged.average(mesh, local, radius, 0.0, out);
  const StressKernel kernel(radius);
  int interior = 0, beside = 0;
  for (int t = 0; t < mesh.triangleCount(); t += 7) {
    const Vec2 c = centroid(mesh, t);
    const bool farFromAll = std::min({c.x(), 1.0 - c.x(), c.y(), 1.0 - c.y(), std::abs(c.x() - 0.5)}) > 0.15;
    const bool besideTheCrack = std::abs(c.x() - 0.5) < 0.03 && !isLip(mesh, t);
    if (!farFromAll && !besideTheCrack) continue;
    Mat2 sum = Mat2::Zero();
    double weights = 0.0;
    for (int u = 0; u < mesh.triangleCount(); ++u) {
      if (isLip(mesh, u)) continue;
      const Vec2 d = centroid(mesh, u);
      double w = 0.0;
      if (farFromAll) {
        w = kernel.weight(c, d);
      } else if ((d.x() < 0.5) == (c.x() < 0.5)) {
        const double d2 = (d - c).squaredNorm() / (radius * radius);
        w = d2 < 1.0 ? (1.0 - d2) * (1.0 - d2) : 0.0;
      }
      w *= std::abs(restArea(mesh.tris[u]));
      sum += w * local[u];
      weights += w;
    }
    const Mat2 expected = sum / weights;
    EXPECT_LT((out[t] - expected).norm(), 1e-9 * expected.norm()) << "triangle " << t << " at " << c.transpose();
    (farFromAll ? interior : beside) += 1;
  }
  EXPECT_GT(interior, 50);
  EXPECT_GT(beside, 20);
}

// On a mesh much finer than the averaging length a list holds over a thousand triangles; the
// lists are thinned to at most 256 (memory and time per triangle bounded at any resolution), and
// still read the whole disc: a stress varying across it averages as the full disc's bell-weighted
// mean does.
TEST(NonlocalStress, OnAMeshFinerThanTheRadiusTheListsAreBoundedAndStillReadTheWholeDisc) {
  const double radius = 0.065;
  const ClothMesh coarse = splitDown(65), fine = splitDown(161);
  const auto bytesPerTriangle = [&](const ClothMesh& mesh) {
    NonlocalStress averaged;
    std::vector<Mat2> out;
    averaged.average(mesh, std::vector<Mat2>(mesh.tris.size(), tensor(1.0, 0.0, 0.0)), radius, 0.0, out);
    return static_cast<double>(averaged.heapBytes()) / mesh.triangleCount();
  };
  // Lists beside the crack (a band as wide in metres, so the same share of the triangles at both
  // resolutions): about 100 triangles per disc at 65^2, 680 at 161^2, without the cap 7 times
  // the bytes.
  EXPECT_LT(bytesPerTriangle(fine), 3.0 * bytesPerTriangle(coarse));

  // The full disc's weighted mean on the crack's side, computed here triangle by triangle, against
  // the thinned lists' average, at triangles beside the crack.
  const std::vector<Mat2> local = steepStress(fine);
  NonlocalStress averaged;
  std::vector<Mat2> out;
  averaged.average(fine, local, radius, 0.0, out);
  double worst = 0.0;
  int checked = 0;
  for (int t = 0; t < fine.triangleCount(); t += 13) {
    const Vec2 c = centroid(fine, t);
    if (std::abs(c.y() - 0.5) > 0.1 || std::abs(c.x() - 0.5) > 0.03 || isLip(fine, t)) continue;
    Mat2 sum = Mat2::Zero();
    double weights = 0.0;
    for (int u = 0; u < fine.triangleCount(); ++u) {
      if (isLip(fine, u) || (centroid(fine, u).x() < 0.5) != (c.x() < 0.5)) continue;
      const double d2 = (centroid(fine, u) - c).squaredNorm() / (radius * radius);
      if (d2 > 1.0) continue;
      const double w = std::abs(restArea(fine.tris[u])) * (1.0 - d2) * (1.0 - d2);
      sum += w * local[u];
      weights += w;
    }
    worst = std::max(worst, (out[t] - sum / weights).norm());
    ++checked;
  }
  ASSERT_GT(checked, 20);
  // The stress varies by 260 N/m across a disc and the bump by 300 N/m: read within 3 N/m (runs
  // of the walk read at their first triangle were 27 N/m off at 241^2).
  EXPECT_LT(worst, 3.0);
}

// A crack tip's stress grows as 1/sqrt(r) towards it: the triangle at the tip reads more of it the
// finer the mesh; averaged over a fixed radius it converges.
TEST(NonlocalStress, ASingularStressAveragedConvergesAsTheMeshIsRefined) {
  const Vec2 tip(0.5, 0.5);
  std::vector<double> atTip, averagedAtTip;
  for (int n : {33, 65, 129}) {
    const ClothMesh mesh = grid(n);
    std::vector<Mat2> local(mesh.tris.size());
    int nearest = 0;
    for (int t = 0; t < mesh.triangleCount(); ++t) {
      const double r = (centroid(mesh, t) - tip).norm();
      local[t] = tensor(10.0 / std::sqrt(r), 0.0, 0.0);
      if (r < (centroid(mesh, nearest) - tip).norm()) nearest = t;
    }
    NonlocalStress averaged;
    std::vector<Mat2> out;
    averaged.average(mesh, local, 0.1, 0.0, out);
    atTip.push_back(local[nearest](0, 0));
    averagedAtTip.push_back(out[nearest](0, 0));
  }
  // Each refinement raises the local reading by about sqrt(2); the average moves by a few percent
  // (the tip triangle's own centroid still approaches the singularity).
  EXPECT_GT(atTip.back() / atTip.front(), 1.8);
  for (std::size_t k = 1; k < averagedAtTip.size(); ++k) {
    EXPECT_LT(std::abs(averagedAtTip[k] / averagedAtTip[k - 1] - 1.0), 0.06)
        << "refinement " << k << ": " << averagedAtTip[k - 1] << " then " << averagedAtTip[k] << "; local " << atTip[k - 1] << " then " << atTip[k];
  }
}

}  // namespace
}  // namespace weft
