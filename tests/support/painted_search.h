#pragma once
// The reference search (findTearCandidates) on a painted cloth (a strength map, a tear region),
// run the two ways the painted tests compare: with the bound that skips vertices and without.
#include <vector>

#include <gtest/gtest.h>

#include "mesh/cloth_mesh.h"
#include "tearing/tear_candidates.h"

namespace weft::test {

struct PaintedSearch {
  std::vector<TearCandidate> withBound, withoutBound;  // dense lines, painted
  bool unpaintedFindsNone = true;                     // the same search without the painting, both ways
};

inline PaintedSearch paintedSearch(const ClothMesh& mesh, const std::vector<Mat2>& stress, const TearTable& table,
                                   const TearStrengthMap* map, const TearRegion* region) {
  PaintedSearch result;
  for (const bool skip : {true, false}) {
    TearSearchSettings settings;
    settings.lines = CandidateLines::Dense;
    settings.skipByBound = skip;
    std::vector<TearCandidate> painted, unpainted;
    TearSearchCounts counts;
    findTearCandidates(mesh, triangleCorners(mesh), stress, table, 0.0, settings, painted, counts, map, region);
    findTearCandidates(mesh, triangleCorners(mesh), stress, table, 0.0, settings, unpainted, counts);
    (skip ? result.withBound : result.withoutBound) = painted;
    result.unpaintedFindsNone = result.unpaintedFindsNone && unpainted.empty();
  }
  return result;
}

// The bound skipped nothing: the same vertices with the same lines, in the same order.
inline void expectTheBoundSkipsNothing(const PaintedSearch& search) {
  ASSERT_EQ(search.withBound.size(), search.withoutBound.size());
  for (std::size_t k = 0; k < search.withBound.size(); ++k) {
    EXPECT_EQ(search.withBound[k].vertex, search.withoutBound[k].vertex) << k;
    EXPECT_EQ(search.withBound[k].angle, search.withoutBound[k].angle) << k;
  }
}

}  // namespace weft::test
