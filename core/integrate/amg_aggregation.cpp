#include "integrate/amg_aggregation.h"

#include <algorithm>
#include <cmath>

namespace weft {
namespace {

using amg::kIsolated;
using amg::kUnassigned;

// The strong neighbours of each free vertex, by its position in the free list (compressed rows).
struct StrongNeighbours {
  std::vector<int> start;  // freeVertices.size() + 1
  std::vector<int> vertex;

  int begin(std::size_t k) const { return start[k]; }
  int end(std::size_t k) const { return start[k + 1]; }
};

StrongNeighbours strongNeighbours(const BlockSparseMatrix& A, double theta, const std::vector<int>& freeVertices) {
  std::vector<double> diagonalNorm(A.blockRows, 0.0);
  for (int i = 0; i < A.blockRows; ++i) {
    const int d = A.find(i, i);
    if (d >= 0) diagonalNorm[i] = A.blocks[d].norm();
  }
  StrongNeighbours strong;
  strong.start.reserve(freeVertices.size() + 1);
  strong.start.push_back(0);
  for (const int i : freeVertices) {
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      const int j = A.column[k];
      if (j == i) continue;
      const double norm = A.blocks[k].norm();
      if (norm > 0.0 && norm >= theta * std::sqrt(diagonalNorm[i] * diagonalNorm[j])) strong.vertex.push_back(j);
    }
    strong.start.push_back(static_cast<int>(strong.vertex.size()));
  }
  return strong;
}

}  // namespace

void aggregateFreeVertices(const BlockSparseMatrix& A, double theta, const std::vector<int>& freeVertices,
                           std::vector<int>& ioAggregateOf, AggregateIds& ioIds) {
  const StrongNeighbours strong = strongNeighbours(A, theta, freeVertices);
  std::vector<int>& aggregateOf = ioAggregateOf;
  const std::size_t count = freeVertices.size();
  for (std::size_t k = 0; k < count; ++k)
    if (strong.begin(k) == strong.end(k)) aggregateOf[freeVertices[k]] = kIsolated;
  // 1. Roots: a free vertex whose strong neighbours are all free takes them.
  for (std::size_t k = 0; k < count; ++k) {
    const int i = freeVertices[k];
    if (aggregateOf[i] != kUnassigned) continue;
    const auto first = strong.vertex.begin() + strong.begin(k), last = strong.vertex.begin() + strong.end(k);
    if (!std::all_of(first, last, [&](int j) { return aggregateOf[j] == kUnassigned; })) continue;
    const int id = ioIds.take();
    aggregateOf[i] = id;
    for (auto j = first; j != last; ++j) aggregateOf[*j] = id;
  }
  // 2. The rest join the aggregate their first strong neighbour had after pass 1.
  const std::vector<int> afterRoots = aggregateOf;
  for (std::size_t k = 0; k < count; ++k) {
    const int i = freeVertices[k];
    if (aggregateOf[i] != kUnassigned) continue;
    for (int s = strong.begin(k); s < strong.end(k); ++s) {
      if (afterRoots[strong.vertex[s]] >= 0) {
        aggregateOf[i] = afterRoots[strong.vertex[s]];
        break;
      }
    }
  }
  // 3. Whatever is left forms aggregates with its free strong neighbours.
  for (std::size_t k = 0; k < count; ++k) {
    const int i = freeVertices[k];
    if (aggregateOf[i] != kUnassigned) continue;
    const int id = ioIds.take();
    aggregateOf[i] = id;
    for (int s = strong.begin(k); s < strong.end(k); ++s)
      if (aggregateOf[strong.vertex[s]] == kUnassigned) aggregateOf[strong.vertex[s]] = id;
  }
}

}  // namespace weft
