#include "integrate/amg_transfer_pattern.h"

#include <algorithm>

namespace weft {
namespace {

BlockPattern takePattern(BlockSparseMatrix& matrix) {
  BlockPattern pattern;
  pattern.rowStart = std::move(matrix.rowStart);
  pattern.column = std::move(matrix.column);
  matrix.rowStart.clear();
  matrix.column.clear();
  return pattern;
}

// A pattern of rows x columns filled row by row (appendRow / copyRow, in order).
void startPattern(BlockSparseMatrix& matrix, int rows, int columns, std::size_t expectedBlocks) {
  matrix.blockRows = rows;
  matrix.blockColumns = columns;
  matrix.rowStart.assign(1, 0);
  matrix.rowStart.reserve(rows + 1);
  matrix.column.clear();
  matrix.column.reserve(expectedBlocks);
}

// Appends a row from its distinct columns, in any order.
void appendRow(BlockSparseMatrix& matrix, std::vector<int>& columns) {
  std::sort(columns.begin(), columns.end());
  matrix.column.insert(matrix.column.end(), columns.begin(), columns.end());
  matrix.rowStart.push_back(static_cast<int>(matrix.column.size()));
}

void copyRow(BlockSparseMatrix& matrix, const BlockPattern& previous, int i) {
  matrix.column.insert(matrix.column.end(), previous.column.begin() + previous.rowStart[i],
                       previous.column.begin() + previous.rowStart[i + 1]);
  matrix.rowStart.push_back(static_cast<int>(matrix.column.size()));
}

void finishPattern(BlockSparseMatrix& matrix) { matrix.blocks.assign(matrix.column.size(), Mat3::Zero()); }

// An index list entry of a copied row, moved with its row's storage (-1 stays -1).
int shifted(int slot, int shift) { return slot >= 0 ? slot + shift : slot; }

int rowLength(const std::vector<int>& rowStart, int i) { return rowStart[i + 1] - rowStart[i]; }

}  // namespace

PreviousTransfer takeTransfer(AmgHierarchy::Level& fine, AmgHierarchy::Level& coarse, BlockPattern previousFineA) {
  PreviousTransfer previous;
  previous.A = std::move(previousFineA);
  previous.P = takePattern(fine.P);
  previous.AP = takePattern(fine.AP);
  previous.Ac = takePattern(coarse.A);
  previous.tentativeSlots = std::move(fine.tentativeSlots);
  previous.smoothingSlots = std::move(fine.smoothingSlots);
  previous.productSlots = std::move(fine.productSlots);
  previous.productStart = std::move(fine.productStart);
  previous.galerkinSlots = std::move(fine.galerkinSlots);
  return previous;
}

void setTransferPattern(AmgHierarchy::Level& fine, AmgHierarchy::Level& coarse, int coarseCount,
                        const TransferRows* rows, const PreviousTransfer* previous,
                        const BlockSparseMatrix* productOperator) {
  const BlockSparseMatrix& A = fine.A;
  const BlockSparseMatrix& B = productOperator != nullptr ? *productOperator : fine.A;  // A P's A
  const int n = A.blockRows;
  const std::vector<int>& aggregateOf = fine.aggregateOf;
  const auto derive = [&](const std::vector<char> TransferRows::*flags, int i) { return rows == nullptr || (rows->*flags)[i]; };
  std::vector<int> columns;
  std::vector<int> marker(coarseCount, -1);    // the row that last gathered a column
  std::vector<int> position(coarseCount, -1);  // a column's slot in the row being filled

  // P and the slots of its tentative and smoothed parts.
  BlockSparseMatrix& P = fine.P;
  startPattern(P, n, coarseCount, previous ? previous->P.column.size() + 64 : 4 * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    if (!derive(&TransferRows::p, i)) {
      copyRow(P, previous->P, i);
      continue;
    }
    columns.clear();
    const auto gather = [&](int J) {
      if (J >= 0 && marker[J] != i) {
        marker[J] = i;
        columns.push_back(J);
      }
    };
    gather(aggregateOf[i]);
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) gather(aggregateOf[A.column[k]]);
    appendRow(P, columns);
  }
  finishPattern(P);
  fine.tentativeSlots.assign(n, -1);
  fine.smoothingSlots.assign(A.blockCount(), -1);
  for (int i = 0; i < n; ++i) {
    if (!derive(&TransferRows::p, i)) {
      const int shift = P.rowStart[i] - previous->P.rowStart[i];
      fine.tentativeSlots[i] = shifted(previous->tentativeSlots[i], shift);
      const int* before = previous->smoothingSlots.data() + previous->A.rowStart[i];
      for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) fine.smoothingSlots[k] = shifted(*before++, shift);
      continue;
    }
    for (int p = P.rowStart[i]; p < P.rowStart[i + 1]; ++p) position[P.column[p]] = p;
    if (aggregateOf[i] >= 0) fine.tentativeSlots[i] = position[aggregateOf[i]];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
      if (aggregateOf[A.column[k]] >= 0) fine.smoothingSlots[k] = position[aggregateOf[A.column[k]]];
  }

  // A P and its product slots.
  BlockSparseMatrix& AP = fine.AP;
  std::fill(marker.begin(), marker.end(), -1);
  startPattern(AP, n, coarseCount, previous ? previous->AP.column.size() + 256 : 10 * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    if (!derive(&TransferRows::product, i)) {
      copyRow(AP, previous->AP, i);
      continue;
    }
    columns.clear();
    for (int k = B.rowStart[i]; k < B.rowStart[i + 1]; ++k) {
      const int j = B.column[k];
      for (int p = P.rowStart[j]; p < P.rowStart[j + 1]; ++p) {
        const int K = P.column[p];
        if (marker[K] == i) continue;
        marker[K] = i;
        columns.push_back(K);
      }
    }
    appendRow(AP, columns);
  }
  finishPattern(AP);
  fine.productStart.assign(n + 1, 0);
  fine.productSlots.clear();
  fine.productSlots.reserve(previous ? previous->productSlots.size() + 1024 : 30 * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    if (!derive(&TransferRows::product, i)) {
      const int shift = AP.rowStart[i] - previous->AP.rowStart[i];
      for (int s = previous->productStart[i]; s < previous->productStart[i + 1]; ++s)
        fine.productSlots.push_back(previous->productSlots[s] + shift);
    } else {
      for (int w = AP.rowStart[i]; w < AP.rowStart[i + 1]; ++w) position[AP.column[w]] = w;
      for (int k = B.rowStart[i]; k < B.rowStart[i + 1]; ++k) {
        const int j = B.column[k];
        for (int p = P.rowStart[j]; p < P.rowStart[j + 1]; ++p) fine.productSlots.push_back(position[P.column[p]]);
      }
    }
    fine.productStart[i + 1] = static_cast<int>(fine.productSlots.size());
  }

  // The fine vertices of each coarse column of P (P^T's rows), increasing, with their block of P.
  std::vector<int> supportStart(coarseCount + 1, 0);
  for (int p = 0; p < P.blockCount(); ++p) ++supportStart[P.column[p] + 1];
  for (int I = 0; I < coarseCount; ++I) supportStart[I + 1] += supportStart[I];
  std::vector<int> supportVertex(P.blockCount()), supportBlock(P.blockCount());
  {
    std::vector<int> fill(supportStart.begin(), supportStart.end() - 1);
    for (int i = 0; i < n; ++i)
      for (int p = P.rowStart[i]; p < P.rowStart[i + 1]; ++p) {
        const int s = fill[P.column[p]]++;
        supportVertex[s] = i;
        supportBlock[s] = p;
      }
  }

  // A_c = P^T (A P).
  BlockSparseMatrix& Ac = coarse.A;
  std::fill(marker.begin(), marker.end(), -1);
  startPattern(Ac, coarseCount, coarseCount, previous ? previous->Ac.column.size() + 256 : 20 * static_cast<std::size_t>(coarseCount));
  for (int I = 0; I < coarseCount; ++I) {
    if (!derive(&TransferRows::coarse, I)) {
      copyRow(Ac, previous->Ac, I);
      continue;
    }
    columns.clear();
    for (int s = supportStart[I]; s < supportStart[I + 1]; ++s) {
      const int i = supportVertex[s];
      for (int w = AP.rowStart[i]; w < AP.rowStart[i + 1]; ++w) {
        const int K = AP.column[w];
        if (marker[K] == I) continue;
        marker[K] = I;
        columns.push_back(K);
      }
    }
    appendRow(Ac, columns);
  }
  finishPattern(Ac);

  // The Galerkin slots: per fine row i, per block (i, I) of P, per block (i, K) of A P, the slot of
  // A_c(I, K). Filled coarse row by coarse row (the position table holds one row at a time); an
  // entry whose A P row and coarse row are both copied is the old one shifted with its coarse row.
  std::vector<std::size_t> galerkinStart(n + 1, 0), previousGalerkinStart;
  for (int i = 0; i < n; ++i)
    galerkinStart[i + 1] = galerkinStart[i] + static_cast<std::size_t>(rowLength(P.rowStart, i)) * rowLength(AP.rowStart, i);
  if (previous) {
    const int previousRows = previous->P.rows();
    previousGalerkinStart.assign(previousRows + 1, 0);
    for (int i = 0; i < previousRows; ++i)
      previousGalerkinStart[i + 1] = previousGalerkinStart[i] + static_cast<std::size_t>(rowLength(previous->P.rowStart, i)) *
                                                                     rowLength(previous->AP.rowStart, i);
  }
  fine.galerkinSlots.resize(galerkinStart[n]);
  for (int I = 0; I < coarseCount; ++I) {
    const bool coarseDerived = derive(&TransferRows::coarse, I);
    bool positionsSet = false;
    for (int s = supportStart[I]; s < supportStart[I + 1]; ++s) {
      const int i = supportVertex[s];
      const int length = rowLength(AP.rowStart, i);
      const std::size_t first = galerkinStart[i] + static_cast<std::size_t>(supportBlock[s] - P.rowStart[i]) * length;
      if (coarseDerived || derive(&TransferRows::product, i)) {
        if (!positionsSet) {
          for (int t = Ac.rowStart[I]; t < Ac.rowStart[I + 1]; ++t) position[Ac.column[t]] = t;
          positionsSet = true;
        }
        for (int w = 0; w < length; ++w) fine.galerkinSlots[first + w] = position[AP.column[AP.rowStart[i] + w]];
      } else {  // P's and A P's rows i are copied, so is coarse row I: the same entries, shifted
        const int shift = Ac.rowStart[I] - previous->Ac.rowStart[I];
        const int* before = previous->galerkinSlots.data() + previousGalerkinStart[i] +
                            static_cast<std::size_t>(supportBlock[s] - P.rowStart[i]) * length;
        for (int w = 0; w < length; ++w) fine.galerkinSlots[first + w] = before[w] + shift;
      }
    }
  }

  // The slot of each block's transpose (A_c's pattern is symmetric): rows in increasing order meet
  // the blocks of each row K in increasing column order.
  coarse.transposeSlots.resize(Ac.blockCount());
  std::vector<int> cursor(Ac.rowStart.begin(), Ac.rowStart.end() - 1);
  for (int I = 0; I < coarseCount; ++I)
    for (int s = Ac.rowStart[I]; s < Ac.rowStart[I + 1]; ++s) coarse.transposeSlots[s] = cursor[Ac.column[s]]++;
}

}  // namespace weft
