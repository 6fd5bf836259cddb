#pragma once
// A sparse matrix of 3x3 blocks stored by block rows (BSR): the storage the multigrid hierarchy
// (amg_hierarchy.h) works in. One block per coupled vertex pair instead of nine scalars with their
// own indices: a product streams each block once, and a Gauss-Seidel sweep reads a vertex's whole
// row in one pass.
#include <vector>

#include <Eigen/Core>

#include "util/types.h"

namespace weft {

struct BlockSparseMatrix {
  int blockRows = 0;
  int blockColumns = 0;
  std::vector<int> rowStart;   // blockRows + 1 entries: the blocks of row i are rowStart[i] .. rowStart[i+1]-1
  std::vector<int> column;     // block column of each stored block, increasing within a row
  std::vector<Mat3> blocks;

  // The pattern from each row's (unsorted, possibly repeated) block columns; values zero.
  void setPattern(int rows, int columns, const std::vector<std::vector<int>>& columnsOfRow);
  // Slot of block (row, col) in `blocks`, or -1 when it is not in the pattern.
  int find(int row, int col) const;
  void setZero();
  int blockCount() const { return static_cast<int>(column.size()); }
  // The threads worth using for a loop over this matrix's rows: 1 below a few thousand rows or
  // blocks (the fork would cost more than it saves). The blocks count too: a coarse level has few
  // rows of many blocks (64^2's second level: 703 rows, 11,247 blocks, a third of the finest
  // level's Galerkin product).
  int threadsFor(int threads) const {
    return blockRows >= kRowsPerThread || blockCount() >= kBlocksPerThread ? threads : 1;
  }
  static constexpr int kRowsPerThread = 1500;
  static constexpr int kBlocksPerThread = 8000;

  // outY = M inX; rows split over `threads` in fixed ranges (each row summed in the same order by
  // any thread: the same bits for any count). Small matrices stay on one thread.
  void multiply(const Eigen::VectorXd& inX, Eigen::VectorXd& outY, int threads = 1) const;
  // ioY += M^T inX.
  void addTransposeProduct(const Eigen::VectorXd& inX, Eigen::VectorXd& ioY) const;
};

}  // namespace weft
