#include "integrate/amg_patch.h"

#include <algorithm>

#include "integrate/amg_aggregation.h"
#include "integrate/amg_transfer_pattern.h"

namespace weft {
namespace {

using amg::kUnassigned;

bool sameRow(const BlockPattern& previous, const BlockSparseMatrix& A, int i) {
  const int length = A.rowStart[i + 1] - A.rowStart[i];
  if (previous.rowStart[i + 1] - previous.rowStart[i] != length) return false;
  return std::equal(A.column.begin() + A.rowStart[i], A.column.begin() + A.rowStart[i + 1],
                    previous.column.begin() + previous.rowStart[i]);
}

}  // namespace

bool patchTransfer(AmgHierarchy::Level& fine, AmgHierarchy::Level& coarse, const BlockPattern& previousFine,
                   const std::vector<int>& seeds, const AmgSettings& settings, TransferPatch& out,
                   const BlockSparseMatrix* product, const BlockPattern* previousProduct) {
  const BlockSparseMatrix& A = fine.A;
  const BlockSparseMatrix& B = product != nullptr ? *product : fine.A;  // A P's operator
  const BlockPattern& previousB = product != nullptr ? *previousProduct : previousFine;
  const int n = A.blockRows;
  const int previousRows = previousFine.rows();
  const std::vector<int>& previousAggregateOf = fine.aggregateOf;
  const int previousCoarseCount = coarse.A.blockRows;
  if (static_cast<int>(previousAggregateOf.size()) != previousRows) return false;  // not the level it was built for

  // 1. Rows whose pattern changed; with the seeds, the vertices to aggregate again.
  std::vector<char> rowChanged(n, 0), reconsider(n, 0);
  std::vector<char> dissolved(previousCoarseCount, 0);
  const auto dissolveAggregateOf = [&](int i) {
    if (i < previousRows && previousAggregateOf[i] >= 0) dissolved[previousAggregateOf[i]] = 1;
  };
  for (int i = 0; i < n; ++i) {
    rowChanged[i] = i >= previousRows || !sameRow(previousFine, A, i);
    if (rowChanged[i]) {
      reconsider[i] = 1;
      dissolveAggregateOf(i);
    }
  }
  for (const int s : seeds) {
    if (s >= n) continue;
    reconsider[s] = 1;
    dissolveAggregateOf(s);
  }
  for (int i = n; i < previousRows; ++i) dissolveAggregateOf(i);  // a removed vertex (coarse levels only)

  // 2. Free the dissolved aggregates' vertices and aggregate them again.
  std::vector<int> aggregateOf(n);
  std::vector<int> freeVertices;
  for (int i = 0; i < n; ++i) {
    const int previous = i < previousRows ? previousAggregateOf[i] : kUnassigned;
    const bool free = reconsider[i] || (previous >= 0 && dissolved[previous]);
    aggregateOf[i] = free ? kUnassigned : previous;
    if (free) freeVertices.push_back(i);
  }
  if (static_cast<double>(freeVertices.size()) > settings.patchLimit * n) return false;
  std::vector<int> reusable;
  for (int J = 0; J < previousCoarseCount; ++J)
    if (dissolved[J]) reusable.push_back(J);
  AggregateIds ids(std::move(reusable), previousCoarseCount);
  aggregateFreeVertices(A, settings.strengthThreshold, freeVertices, aggregateOf, ids);
  // Fewer aggregates than were dissolved: move the highest ids into the holes.
  int coarseCount = ids.end();
  const std::vector<int> holes = ids.untaken();
  if (!holes.empty()) {
    coarseCount = previousCoarseCount - static_cast<int>(holes.size());
    std::vector<int> renumbered(previousCoarseCount);
    for (int J = 0; J < previousCoarseCount; ++J) renumbered[J] = J;
    std::vector<char> isHole(previousCoarseCount, 0);
    for (const int h : holes) isHole[h] = 1;
    auto hole = holes.begin();
    for (int J = coarseCount; J < previousCoarseCount; ++J)
      if (!isHole[J]) renumbered[J] = *hole++;  // the holes below coarseCount, in order
    for (int& J : aggregateOf)
      if (J >= coarseCount) J = renumbered[J];
  }
  if (coarseCount == 0 || coarseCount > settings.stallRatio * n) return false;

  // The coarse vertices whose set of fine vertices changed (the next level's seeds), and the fine
  // vertices whose aggregate id changed.
  std::vector<char> membershipChanged(coarseCount, 0);
  std::vector<char> idChanged(n, 0);
  for (int i = 0; i < std::max(n, previousRows); ++i) {
    const int before = i < previousRows ? previousAggregateOf[i] : kUnassigned;
    const int now = i < n ? aggregateOf[i] : kUnassigned;
    if (before == now) continue;
    if (i < n) idChanged[i] = 1;
    if (before >= 0 && before < coarseCount) membershipChanged[before] = 1;
    if (now >= 0) membershipChanged[now] = 1;
  }

  // 3. The rows to derive again (amg_transfer_pattern.h): P's rows that see a changed row or
  //    aggregate id, A P's rows that see such a P row, and the coarse rows fed by any of them
  //    before or after the change (or by a removed fine vertex).
  TransferRows rows;
  rows.p.assign(n, 0);
  rows.product.assign(n, 0);
  rows.coarse.assign(coarseCount, 0);
  for (int i = 0; i < n; ++i) {
    bool derive = rowChanged[i] || idChanged[i];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1] && !derive; ++k) derive = idChanged[A.column[k]];
    rows.p[i] = derive;
  }
  for (int i = 0; i < n; ++i) {  // A P's row i reads B's row i and the P rows of its columns
    bool derive = rows.p[i] || i >= previousB.rows() || !sameRow(previousB, B, i);
    for (int k = B.rowStart[i]; k < B.rowStart[i + 1] && !derive; ++k) derive = rows.p[B.column[k]];
    rows.product[i] = derive;
  }
  for (int i = 0; i < n; ++i) {  // a derived A P row's P row, as it will be: its aggregate and its neighbours'
    if (!rows.product[i]) continue;
    if (aggregateOf[i] >= 0) rows.coarse[aggregateOf[i]] = 1;
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
      if (aggregateOf[A.column[k]] >= 0) rows.coarse[aggregateOf[A.column[k]]] = 1;
  }
  fine.aggregateOf = std::move(aggregateOf);
  PreviousTransfer previous = takeTransfer(fine, coarse, previousFine);
  for (int i = 0; i < previousRows; ++i) {  // ... and as it was (a removed vertex's too)
    if (i < n && !rows.product[i]) continue;
    for (int p = previous.P.rowStart[i]; p < previous.P.rowStart[i + 1]; ++p)
      if (previous.P.column[p] < coarseCount) rows.coarse[previous.P.column[p]] = 1;
  }
  setTransferPattern(fine, coarse, coarseCount, &rows, &previous, product);

  out.previousCoarse = std::move(previous.Ac);
  out.freedVertices = static_cast<int>(freeVertices.size());
  out.coarseSeeds.clear();
  for (int I = 0; I < coarseCount; ++I)
    if (membershipChanged[I]) out.coarseSeeds.push_back(I);
  return true;
}

}  // namespace weft
