// The elastic forces and Hessian summed by several threads (forces/elastic_forces.h: each thread
// evaluates the elements touching its range of vertices and adds what falls in it) are bit for bit
// those of one thread, on a bent sheet and on a torn one whose new vertices sit at the end.
#include "forces/elastic_forces.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "support/test_scenes.h"
#include "tearing/tear_mesh.h"

namespace weft {
namespace {

struct Assembled {
  std::vector<Vec3> forces;
  std::vector<double> values;
  ElasticSummary summary;
};

Assembled assemble(const Cloth& cloth, int threads) {
  SystemMatrix matrix;
  const CoupledVertexPairs pairs = coupledVertexPairs(cloth);
  matrix.setPattern(cloth.mesh.vertexCount(), pairs.edges, pairs.hingeWings);
  matrix.setZero();
  ElasticOptions options;
  options.hessian = HessianMode::Definite;
  options.threads = threads;
  ElasticWorkspace workspace;
  StageProfile profile;
  Assembled out;
  out.summary = evaluateElasticForces(cloth, cloth.mesh.x, options, workspace, out.forces, &matrix, profile);
  out.values.assign(matrix.matrix().valuePtr(), matrix.matrix().valuePtr() + matrix.matrix().nonZeros());
  return out;
}

void expectSameBits(const Assembled& a, const Assembled& b) {
  ASSERT_EQ(a.forces.size(), b.forces.size());
  EXPECT_EQ(0, std::memcmp(a.forces.data(), b.forces.data(), a.forces.size() * sizeof(Vec3)));
  ASSERT_EQ(a.values.size(), b.values.size());
  EXPECT_EQ(0, std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(double)));
  EXPECT_EQ(a.summary.membraneEnergy, b.summary.membraneEnergy);
  EXPECT_EQ(a.summary.bendingEnergy, b.summary.bendingEnergy);
  EXPECT_EQ(a.summary.maxPrincipalStrain, b.summary.maxPrincipalStrain);
}

Cloth crumpledSheet(int resolution) {
  const Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-3), resolution, 1.0 / 100);
  Cloth cloth = buildCloth(scene.cloths[0], "test", 0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (Vec3& p : cloth.mesh.x) p = 1.1 * p + Vec3(jitter(rng), jitter(rng), jitter(rng));
  return cloth;
}

TEST(ElasticForces, AnyThreadCountSumsTheSameBitsAsOne) {
  const Cloth cloth = crumpledSheet(17);
  const Assembled one = assemble(cloth, 1);
  double largest = 0.0;
  for (const Vec3& f : one.forces) largest = std::max(largest, f.norm());
  ASSERT_GT(largest, 0.0);  // a loaded sheet: the comparison compares something
  ASSERT_GT(one.summary.bendingEnergy, 0.0);
  for (int threads : {2, 3, 5}) {
    SCOPED_TRACE(threads);
    expectSameBits(one, assemble(cloth, threads));
  }
}

TEST(ElasticForces, AfterTearsTheThreadsStillSumTheSameBits) {
  Cloth cloth = crumpledSheet(13);
  // Tears through a few interior vertices: the copies they make are numbered last, so elements
  // join vertices of the first range with vertices of the last.
  TearGuards guards;
  int torn = 0;
  for (int vertex : {40, 60, 85, 100}) {
    TopologyChange change;
    torn += tearThroughVertex(cloth.mesh, vertex, Vec2(1.0, 0.3).normalized(), guards, 0.2, change) ? 1 : 0;
  }
  ASSERT_GT(torn, 0);
  rebuildElements(cloth);
  const Assembled one = assemble(cloth, 1);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    expectSameBits(one, assemble(cloth, threads));
  }
}

}  // namespace
}  // namespace weft
