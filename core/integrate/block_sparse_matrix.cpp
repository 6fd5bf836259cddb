#include "integrate/block_sparse_matrix.h"

#include <algorithm>

namespace weft {

void BlockSparseMatrix::setPattern(int rows, int columns, const std::vector<std::vector<int>>& columnsOfRow) {
  blockRows = rows;
  blockColumns = columns;
  rowStart.assign(rows + 1, 0);
  column.clear();
  std::vector<int> sorted;
  for (int i = 0; i < rows; ++i) {
    sorted = columnsOfRow[i];
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    column.insert(column.end(), sorted.begin(), sorted.end());
    rowStart[i + 1] = static_cast<int>(column.size());
  }
  blocks.assign(column.size(), Mat3::Zero());
}

int BlockSparseMatrix::find(int row, int col) const {
  const auto begin = column.begin() + rowStart[row];
  const auto end = column.begin() + rowStart[row + 1];
  const auto found = std::lower_bound(begin, end, col);
  return found != end && *found == col ? static_cast<int>(found - column.begin()) : -1;
}

void BlockSparseMatrix::setZero() { std::fill(blocks.begin(), blocks.end(), Mat3::Zero()); }

void BlockSparseMatrix::multiply(const Eigen::VectorXd& inX, Eigen::VectorXd& outY, int threads) const {
  outY.resize(3 * static_cast<Eigen::Index>(blockRows));
#pragma omp parallel for num_threads(threadsFor(threads)) schedule(static)
  for (int i = 0; i < blockRows; ++i) {
    Vec3 sum = Vec3::Zero();
    for (int k = rowStart[i]; k < rowStart[i + 1]; ++k) sum.noalias() += blocks[k] * inX.segment<3>(3 * column[k]);
    outY.segment<3>(3 * i) = sum;
  }
}

void BlockSparseMatrix::addTransposeProduct(const Eigen::VectorXd& inX, Eigen::VectorXd& ioY) const {
  for (int i = 0; i < blockRows; ++i) {
    const Vec3 x = inX.segment<3>(3 * i);
    for (int k = rowStart[i]; k < rowStart[i + 1]; ++k) ioY.segment<3>(3 * column[k]).noalias() += blocks[k].transpose() * x;
  }
}

}  // namespace weft
