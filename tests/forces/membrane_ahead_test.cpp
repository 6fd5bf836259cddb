// The membrane evaluated at the end of a step and reused by the tear stage and the next step's
// assembly (forces/membrane_ahead.h): what is taken from it is bit for bit what an evaluation
// gives, and it is never taken where the positions, the triangle or the law changed.
#include "forces/membrane_ahead.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "forces/elastic_forces.h"
#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "support/elastic_assembly.h"
#include "support/test_scenes.h"
#include "tearing/tensile_stress.h"

namespace weft {
namespace {

// A sheet stretched and crumpled at random so every triangle carries its own stress.
Cloth stretchedSheet() {
  const Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-3), 9, 1.0 / 100);
  Cloth cloth = buildCloth(scene.cloths[0], "test", 0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  for (Vec3& p : cloth.mesh.x) p = 1.1 * p + Vec3(jitter(rng), jitter(rng), jitter(rng));
  return cloth;
}

TEST(MembraneAhead, WhatTheAssemblyTakesFromItIsWhatItWouldEvaluate) {
  Cloth cloth = stretchedSheet();
  MembraneAhead ahead;
  StageProfile profile;
  ahead.evaluate(cloth, HessianMode::Definite, 1, profile);
  ASSERT_TRUE(ahead.serves(cloth.material.elasticity));
  for (int t = 0; t < cloth.mesh.triangleCount(); ++t) {
    const MembraneElement& e = cloth.membranes[t];
    ASSERT_NE(nullptr, ahead.find(t, e, cloth.mesh.x[e.v[0]], cloth.mesh.x[e.v[1]], cloth.mesh.x[e.v[2]])) << t;
  }
  for (int threads : {1, 2}) test::expectSameBits(test::assembleElastic(cloth, threads), test::assembleElastic(cloth, threads, &ahead));
}

TEST(MembraneAhead, IsNotTakenWhereAVertexMovedOrTheLawChanged) {
  Cloth cloth = stretchedSheet();
  MembraneAhead ahead;
  StageProfile profile;
  ahead.evaluate(cloth, HessianMode::Definite, 1, profile);
  // A vertex moved (a pin script, the editor): its triangles are evaluated, the others taken.
  const int moved = cloth.mesh.vertexCount() / 2;
  cloth.mesh.x[moved] += Vec3(0.003, -0.002, 0.004);
  int missed = 0, touching = 0;
  for (int t = 0; t < cloth.mesh.triangleCount(); ++t) {
    const MembraneElement& e = cloth.membranes[t];
    const bool touches = e.v[0] == moved || e.v[1] == moved || e.v[2] == moved;
    touching += touches;
    const bool found = ahead.find(t, e, cloth.mesh.x[e.v[0]], cloth.mesh.x[e.v[1]], cloth.mesh.x[e.v[2]]) != nullptr;
    EXPECT_EQ(!touches, found) << t;
    missed += !found;
  }
  EXPECT_EQ(touching, missed);
  EXPECT_GT(touching, 0);
  for (int threads : {1, 2}) test::expectSameBits(test::assembleElastic(cloth, threads), test::assembleElastic(cloth, threads, &ahead));
  // A live edit of the material: nothing is taken.
  cloth.material.elasticity.stiffnessScale *= 2.0;
  EXPECT_FALSE(ahead.serves(cloth.material.elasticity));
  for (int threads : {1, 2}) test::expectSameBits(test::assembleElastic(cloth, threads), test::assembleElastic(cloth, threads, &ahead));
  // Another Hessian mode than the one it holds: evaluated too.
  cloth.material.elasticity.stiffnessScale /= 2.0;
  ahead.evaluate(cloth, HessianMode::Exact, 1, profile);
  test::expectSameBits(test::assembleElastic(cloth, 1), test::assembleElastic(cloth, 1, &ahead));
  // After clear, nothing.
  ahead.clear();
  EXPECT_FALSE(ahead.serves(cloth.material.elasticity));
}

TEST(MembraneAhead, TheTearStagesStressReadFromItIsTheStressItWouldEvaluate) {
  Cloth cloth = stretchedSheet();
  MembraneAhead ahead;
  StageProfile profile;
  ahead.evaluate(cloth, HessianMode::Definite, 1, profile);
  std::vector<Mat2> evaluated, read;
  tensileStresses(cloth, evaluated);
  tensileStresses(cloth, &ahead, read);
  ASSERT_EQ(evaluated.size(), read.size());
  bool anyTension = false;
  for (std::size_t t = 0; t < read.size(); ++t) {
    EXPECT_EQ(0, std::memcmp(evaluated[t].data(), read[t].data(), sizeof(Mat2))) << t;
    anyTension = anyTension || evaluated[t].norm() > 0.0;
  }
  EXPECT_TRUE(anyTension);
}

}  // namespace
}  // namespace weft
