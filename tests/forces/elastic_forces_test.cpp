// The elastic forces and Hessian summed by several threads (forces/elastic_forces.h: each thread
// evaluates the elements touching its range of vertices and adds what falls in it) are bit for bit
// those of one thread, on a bent sheet and on a torn one whose new vertices sit at the end.
#include "forces/elastic_forces.h"

#include <gtest/gtest.h>

#include <random>

#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "support/elastic_assembly.h"
#include "support/test_scenes.h"
#include "tearing/tear_mesh.h"

namespace weft {
namespace {

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
  const test::ElasticAssembly one = test::assembleElastic(cloth, 1);
  double largest = 0.0;
  for (const Vec3& f : one.forces) largest = std::max(largest, f.norm());
  ASSERT_GT(largest, 0.0);  // a loaded sheet: the comparison compares something
  ASSERT_GT(one.summary.bendingEnergy, 0.0);
  for (int threads : {2, 3, 5}) {
    SCOPED_TRACE(threads);
    test::expectSameBits(one, test::assembleElastic(cloth, threads));
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
  const test::ElasticAssembly one = test::assembleElastic(cloth, 1);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    test::expectSameBits(one, test::assembleElastic(cloth, threads));
  }
}

}  // namespace
}  // namespace weft
