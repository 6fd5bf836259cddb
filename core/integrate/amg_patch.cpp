#include "integrate/amg_patch.h"

#include <algorithm>

#include "integrate/amg_aggregation.h"

namespace weft {
namespace {

using amg::kUnassigned;

// Moves a matrix's pattern out (its values go with it: the numeric setup refills them).
BlockPattern takePattern(BlockSparseMatrix& matrix) {
  BlockPattern pattern;
  pattern.rowStart = std::move(matrix.rowStart);
  pattern.column = std::move(matrix.column);
  matrix.rowStart.clear();
  matrix.column.clear();
  return pattern;
}

bool sameRow(const BlockPattern& previous, const BlockSparseMatrix& A, int i) {
  const int length = A.rowStart[i + 1] - A.rowStart[i];
  if (previous.rowStart[i + 1] - previous.rowStart[i] != length) return false;
  return std::equal(A.column.begin() + A.rowStart[i], A.column.begin() + A.rowStart[i + 1],
                    previous.column.begin() + previous.rowStart[i]);
}

// Starts a pattern of `rows` x `columns` to be filled row by row (appendRow / copyRow, in order).
void startPattern(BlockSparseMatrix& matrix, int rows, int columns, std::size_t expectedBlocks) {
  matrix.blockRows = rows;
  matrix.blockColumns = columns;
  matrix.rowStart.assign(1, 0);
  matrix.rowStart.reserve(rows + 1);
  matrix.column.clear();
  matrix.column.reserve(expectedBlocks);
}

// Appends a row from unsorted, possibly repeated columns (sorted in place).
void appendRow(BlockSparseMatrix& matrix, std::vector<int>& columns) {
  std::sort(columns.begin(), columns.end());
  columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
  matrix.column.insert(matrix.column.end(), columns.begin(), columns.end());
  matrix.rowStart.push_back(static_cast<int>(matrix.column.size()));
}

void copyRow(BlockSparseMatrix& matrix, const BlockPattern& previous, int i) {
  matrix.column.insert(matrix.column.end(), previous.column.begin() + previous.rowStart[i],
                       previous.column.begin() + previous.rowStart[i + 1]);
  matrix.rowStart.push_back(static_cast<int>(matrix.column.size()));
}

void finishPattern(BlockSparseMatrix& matrix) { matrix.blocks.assign(matrix.column.size(), Mat3::Zero()); }

// An index list entry of an unchanged row, moved with its row's storage (-1 stays -1).
int shifted(int slot, int shift) { return slot >= 0 ? slot + shift : slot; }

}  // namespace

bool patchTransfer(AmgHierarchy::Level& fine, AmgHierarchy::Level& coarse, const BlockPattern& previousFine,
                   const std::vector<int>& seeds, const AmgSettings& settings, TransferPatch& out) {
  const BlockSparseMatrix& A = fine.A;
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

  // 3. The rows to redo: P's row i = the aggregates of i and of its neighbours in A; A P's row i =
  //    the union of P's rows over i's neighbours.
  std::vector<char> redoP(n, 0), redoAP(n, 0);
  for (int i = 0; i < n; ++i) {
    bool redo = rowChanged[i] || idChanged[i];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1] && !redo; ++k) redo = idChanged[A.column[k]];
    redoP[i] = redo;
  }
  for (int i = 0; i < n; ++i) {
    bool redo = redoP[i];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1] && !redo; ++k) redo = redoP[A.column[k]];
    redoAP[i] = redo;
  }

  // P and the slots that fill it.
  BlockSparseMatrix& P = fine.P;
  const BlockPattern previousP = takePattern(P);
  const std::vector<int> previousTentative = std::move(fine.tentativeSlots);
  const std::vector<int> previousSmoothing = std::move(fine.smoothingSlots);
  std::vector<int> columns;
  startPattern(P, n, coarseCount, previousP.column.size() + 8 * freeVertices.size());
  for (int i = 0; i < n; ++i) {
    if (!redoP[i]) {
      copyRow(P, previousP, i);
      continue;
    }
    columns.clear();
    if (aggregateOf[i] >= 0) columns.push_back(aggregateOf[i]);
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
      if (aggregateOf[A.column[k]] >= 0) columns.push_back(aggregateOf[A.column[k]]);
    appendRow(P, columns);
  }
  finishPattern(P);
  fine.tentativeSlots.assign(n, -1);
  fine.smoothingSlots.assign(A.blockCount(), -1);
  for (int i = 0; i < n; ++i) {
    if (redoP[i]) {
      if (aggregateOf[i] >= 0) fine.tentativeSlots[i] = P.find(i, aggregateOf[i]);
      for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
        if (aggregateOf[A.column[k]] >= 0) fine.smoothingSlots[k] = P.find(i, aggregateOf[A.column[k]]);
      continue;
    }
    const int shift = P.rowStart[i] - previousP.rowStart[i];
    fine.tentativeSlots[i] = shifted(previousTentative[i], shift);
    const int* previous = previousSmoothing.data() + previousFine.rowStart[i];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) fine.smoothingSlots[k] = shifted(*previous++, shift);
  }

  // A P and the slots that fill it.
  BlockSparseMatrix& AP = fine.AP;
  const BlockPattern previousAP = takePattern(AP);
  const std::vector<int> previousProductSlots = std::move(fine.productSlots);
  const std::vector<int> previousProductStart = std::move(fine.productStart);
  startPattern(AP, n, coarseCount, previousAP.column.size() + 16 * freeVertices.size());
  for (int i = 0; i < n; ++i) {
    if (!redoAP[i]) {
      copyRow(AP, previousAP, i);
      continue;
    }
    columns.clear();
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      const int j = A.column[k];
      columns.insert(columns.end(), P.column.begin() + P.rowStart[j], P.column.begin() + P.rowStart[j + 1]);
    }
    appendRow(AP, columns);
  }
  finishPattern(AP);
  fine.productSlots.clear();
  fine.productSlots.reserve(previousProductSlots.size() + 64 * freeVertices.size());
  fine.productStart.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    if (redoAP[i]) {
      for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
        const int j = A.column[k];
        for (int p = P.rowStart[j]; p < P.rowStart[j + 1]; ++p) fine.productSlots.push_back(AP.find(i, P.column[p]));
      }
    } else {
      const int shift = AP.rowStart[i] - previousAP.rowStart[i];
      for (int s = previousProductStart[i]; s < previousProductStart[i + 1]; ++s)
        fine.productSlots.push_back(previousProductSlots[s] + shift);
    }
    fine.productStart[i + 1] = static_cast<int>(fine.productSlots.size());
  }

  // 4. The coarse rows to redo: A_c's row I is the union of A P's rows over the fine vertices with
  //    a block (i, I) in P, so it changes only through the P or A P rows redone above (their
  //    columns before and after) or a removed fine vertex's P row.
  std::vector<char> redoCoarse(coarseCount, 0);
  const auto markColumnsOf = [&](const std::vector<int>& rowStart, const std::vector<int>& column, int i) {
    for (int p = rowStart[i]; p < rowStart[i + 1]; ++p)
      if (column[p] < coarseCount) redoCoarse[column[p]] = 1;
  };
  for (int i = 0; i < n; ++i) {
    if (!redoAP[i]) continue;
    markColumnsOf(P.rowStart, P.column, i);
    if (i < previousRows) markColumnsOf(previousP.rowStart, previousP.column, i);
  }
  for (int i = n; i < previousRows; ++i) markColumnsOf(previousP.rowStart, previousP.column, i);
  // The fine vertices of each redone coarse row (P's columns, gathered), increasing.
  std::vector<int> supportStart(coarseCount + 1, 0);
  for (int p = 0; p < P.blockCount(); ++p)
    if (redoCoarse[P.column[p]]) ++supportStart[P.column[p] + 1];
  for (int I = 0; I < coarseCount; ++I) supportStart[I + 1] += supportStart[I];
  std::vector<int> support(supportStart[coarseCount]);
  {
    std::vector<int> fill(supportStart.begin(), supportStart.end() - 1);
    for (int i = 0; i < n; ++i)
      for (int p = P.rowStart[i]; p < P.rowStart[i + 1]; ++p)
        if (redoCoarse[P.column[p]]) support[fill[P.column[p]]++] = i;
  }
  BlockSparseMatrix& Ac = coarse.A;
  out.previousCoarse = takePattern(Ac);
  const BlockPattern& previousAc = out.previousCoarse;
  const std::vector<int> previousTranspose = std::move(coarse.transposeSlots);
  startPattern(Ac, coarseCount, coarseCount, previousAc.column.size() + 32 * freeVertices.size());
  for (int I = 0; I < coarseCount; ++I) {
    if (!redoCoarse[I]) {  // then I is no new id: new ids only appear in redone P rows
      copyRow(Ac, previousAc, I);
      continue;
    }
    columns.clear();
    for (int s = supportStart[I]; s < supportStart[I + 1]; ++s) {
      const int i = support[s];
      columns.insert(columns.end(), AP.column.begin() + AP.rowStart[i], AP.column.begin() + AP.rowStart[i + 1]);
    }
    appendRow(Ac, columns);
  }
  finishPattern(Ac);

  // The Galerkin slots: per fine row i, per block (i, I) of P, per block (i, K) of A P, the slot of
  // A_c(I, K). A row of neither P nor A P redone keeps its list, each entry shifted with its
  // coarse row unless that row was redone.
  const std::vector<int> previousGalerkin = std::move(fine.galerkinSlots);
  fine.galerkinSlots.clear();
  fine.galerkinSlots.reserve(previousGalerkin.size() + 256 * freeVertices.size());
  std::size_t previousOffset = 0;
  for (int i = 0; i < n; ++i) {
    const int productLength = AP.rowStart[i + 1] - AP.rowStart[i];
    for (int p = P.rowStart[i]; p < P.rowStart[i + 1]; ++p) {
      const int I = P.column[p];
      if (redoAP[i] || redoCoarse[I]) {
        for (int w = AP.rowStart[i]; w < AP.rowStart[i + 1]; ++w) fine.galerkinSlots.push_back(Ac.find(I, AP.column[w]));
      } else {
        const int shift = Ac.rowStart[I] - previousAc.rowStart[I];
        const int* previous = previousGalerkin.data() + previousOffset + static_cast<std::size_t>(p - P.rowStart[i]) * productLength;
        for (int w = 0; w < productLength; ++w) fine.galerkinSlots.push_back(previous[w] + shift);
      }
    }
    if (i < previousRows)
      previousOffset += static_cast<std::size_t>(previousP.rowStart[i + 1] - previousP.rowStart[i]) *
                        (previousAP.rowStart[i + 1] - previousAP.rowStart[i]);
  }

  // The coarse operator's transpose slots (for its symmetrization).
  coarse.transposeSlots.resize(Ac.blockCount());
  for (int I = 0; I < coarseCount; ++I)
    for (int s = Ac.rowStart[I]; s < Ac.rowStart[I + 1]; ++s) {
      const int K = Ac.column[s];
      if (redoCoarse[I] || redoCoarse[K]) {
        coarse.transposeSlots[s] = Ac.find(K, I);
      } else {
        const int before = previousTranspose[previousAc.rowStart[I] + (s - Ac.rowStart[I])];
        coarse.transposeSlots[s] = before - previousAc.rowStart[K] + Ac.rowStart[K];
      }
    }

  fine.aggregateOf = std::move(aggregateOf);
  out.freedVertices = static_cast<int>(freeVertices.size());
  out.coarseSeeds.clear();
  for (int I = 0; I < coarseCount; ++I)
    if (membershipChanged[I]) out.coarseSeeds.push_back(I);
  return true;
}

}  // namespace weft
