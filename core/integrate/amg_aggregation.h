#pragma once
// Aggregation of one multigrid level's vertices: which fine vertices each coarse vertex stands for
// (Vanek, Mandel & Brezina 1996, section 4.1), for a whole level (AmgHierarchy::build) or for the
// vertices around a pattern change only (amg_patch.h: the rest keep their aggregates).
//
//   - strength of connection: block (i, j) is strong when |A_ij|_F >= theta sqrt(|A_ii|_F |A_jj|_F)
//     (eq. 3.2 with Frobenius norms of 3x3 blocks);
//   - a free vertex without strong neighbours (a pinned vertex: its row is the identity) is
//     isolated: it stays out of the coarse space, and the smoother solves it exactly;
//   - pass 1, roots: a free vertex whose strong neighbours are all free takes them into a new
//     aggregate;
//   - pass 2: the free vertices left join the aggregate of their first strong neighbour that had
//     one after pass 1 (in a patch that includes the kept aggregates around the change);
//   - pass 3: whatever is left forms new aggregates with its free strong neighbours.
// Every pass runs in vertex order: deterministic, and with every vertex free it is the whole-level
// aggregation.
#include <cstddef>
#include <utility>
#include <vector>

#include "integrate/block_sparse_matrix.h"

namespace weft {

namespace amg {
constexpr int kUnassigned = -2;  // aggregateOf: free, to be aggregated
constexpr int kIsolated = -1;    // aggregateOf: no strong neighbour, in no aggregate
}  // namespace amg

// Hands out the ids (coarse vertices) of new aggregates: first `reusable` in increasing order (the
// ids of aggregates a patch dissolved), then next, next + 1, ...
class AggregateIds {
 public:
  AggregateIds(std::vector<int> reusable, int next) : reusable_(std::move(reusable)), next_(next) {}
  int take() { return used_ < reusable_.size() ? reusable_[used_++] : next_++; }
  // The reusable ids no new aggregate took (holes in the coarse numbering), increasing.
  std::vector<int> untaken() const { return {reusable_.begin() + static_cast<long>(used_), reusable_.end()}; }
  // One past the largest id handed out or reusable.
  int end() const { return next_; }

 private:
  std::vector<int> reusable_;
  std::size_t used_ = 0;
  int next_;
};

// Aggregates the vertices listed in `freeVertices` (increasing; each marked amg::kUnassigned in
// ioAggregateOf) by the three passes above, on the values of A; every other vertex keeps its entry.
// New aggregates take their ids from ioIds.
void aggregateFreeVertices(const BlockSparseMatrix& A, double theta, const std::vector<int>& freeVertices,
                           std::vector<int>& ioAggregateOf, AggregateIds& ioIds);

}  // namespace weft
