#pragma once
// A cloth's elastic forces and Hessian assembled into a fresh system matrix (the definite Hessian),
// and a check that two assemblies are the same bits: for the tests that compare ways of assembling
// (threads, the membrane evaluated ahead).
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "forces/elastic_forces.h"
#include "sim/cloth.h"
#include "sim/cloth_topology.h"

namespace weft::test {

struct ElasticAssembly {
  std::vector<Vec3> forces;
  std::vector<double> hessianValues;
  ElasticSummary summary;
};

inline ElasticAssembly assembleElastic(const Cloth& cloth, int threads, const MembraneAhead* ahead = nullptr) {
  SystemMatrix matrix;
  const CoupledVertexPairs pairs = coupledVertexPairs(cloth);
  matrix.setPattern(cloth.mesh.vertexCount(), pairs.edges, pairs.hingeWings);
  matrix.setZero();
  ElasticOptions options;
  options.hessian = HessianMode::Definite;
  options.threads = threads;
  options.ahead = ahead;
  ElasticWorkspace workspace;
  StageProfile profile;
  ElasticAssembly out;
  out.summary = evaluateElasticForces(cloth, cloth.mesh.x, options, workspace, out.forces, &matrix, profile);
  out.hessianValues.assign(matrix.matrix().valuePtr(), matrix.matrix().valuePtr() + matrix.matrix().nonZeros());
  return out;
}

inline void expectSameBits(const ElasticAssembly& a, const ElasticAssembly& b) {
  ASSERT_EQ(a.forces.size(), b.forces.size());
  EXPECT_EQ(0, std::memcmp(a.forces.data(), b.forces.data(), a.forces.size() * sizeof(Vec3)));
  ASSERT_EQ(a.hessianValues.size(), b.hessianValues.size());
  EXPECT_EQ(0, std::memcmp(a.hessianValues.data(), b.hessianValues.data(), a.hessianValues.size() * sizeof(double)));
  EXPECT_EQ(a.summary.membraneEnergy, b.summary.membraneEnergy);
  EXPECT_EQ(a.summary.bendingEnergy, b.summary.bendingEnergy);
  EXPECT_EQ(a.summary.maxPrincipalStrain, b.summary.maxPrincipalStrain);
}

}  // namespace weft::test
