#include "integrate/strong_coupling_approximation.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "util/types.h"

namespace weft {
namespace {

// Offset in M's storage of entry (row, col), which must be in M's pattern.
int entryOffset(const SystemMatrix::Sparse& m, int row, int col) {
  const int* rows = m.innerIndexPtr();
  const int begin = m.outerIndexPtr()[col];
  const int end = m.outerIndexPtr()[col + 1];
  const int* found = std::lower_bound(rows + begin, rows + end, row);
  assert(found != rows + end && *found == row);
  return static_cast<int>(found - rows);
}

}  // namespace

bool strongCouplingCompensation(const Mat3& B, Mat3& outForI, Mat3& outForJ) {
  const double squaredNorm = B.squaredNorm();
  if (squaredNorm == 0.0) return false;
  // Lower bound of s1^2 = the largest eigenvalue of B^T B: Rayleigh quotient after a few power
  // iterations (any unit vector gives a lower bound; these make it nearly tight).
  const Mat3 BtB = B.transpose() * B;
  Vec3 v = BtB.rowwise().sum();
  if (v.squaredNorm() == 0.0) v = Vec3::UnitX();
  for (int iteration = 0; iteration < 4; ++iteration) v = (BtB * v).normalized();
  double largestSquared = v.dot(BtB * v);
  if (!std::isfinite(largestSquared)) largestSquared = 0.0;  // then shift = norm: the plain bound, still safe
  const double norm = std::sqrt(squaredNorm);
  const double shift = std::sqrt(std::max(0.0, squaredNorm - largestSquared));
  outForI = B * B.transpose() / norm + shift * Mat3::Identity();
  outForJ = BtB / norm + shift * Mat3::Identity();
  return true;
}

bool strongCouplingCompensationFast(const Mat3& B, Mat3& outForI, Mat3& outForJ) {
  const double squaredNorm = B.squaredNorm();
  if (squaredNorm == 0.0) return false;
  const Mat3 BtB = B.transpose() * B;
  const Mat3 scaled = BtB * (1.0 / squaredNorm);  // trace 1: eigenvalues in [0, 1], the largest >= 1/3
  Vec3 v = scaled.rowwise().sum();
  if (v.squaredNorm() == 0.0) v = Vec3::UnitX();
  for (int iteration = 0; iteration < 4; ++iteration) v = scaled * v;  // shrinks by at most 3^-4
  double largestSquared = squaredNorm * v.dot(scaled * v) / v.squaredNorm();
  if (!std::isfinite(largestSquared)) largestSquared = 0.0;  // then shift = norm: the plain bound, still safe
  const double norm = std::sqrt(squaredNorm);
  const double inverseNorm = 1.0 / norm;
  const double shift = std::sqrt(std::max(0.0, squaredNorm - largestSquared));
  outForI = (B * B.transpose()) * inverseNorm + shift * Mat3::Identity();
  outForJ = BtB * inverseNorm + shift * Mat3::Identity();
  return true;
}

void StrongCouplingApproximation::setPattern(const SystemMatrix& A) {
  const SystemMatrix::Sparse& a = A.matrix();
  const std::vector<std::pair<int, int>>& weak = A.weakPairs();
  // A column of A, as vertex blocks, is sorted; mark the dropped blocks of each block column.
  std::vector<std::vector<int>> droppedRowsOfColumn(A.vertexCount());
  for (const auto& [i, j] : weak) {
    droppedRowsOfColumn[j].push_back(i);
    droppedRowsOfColumn[i].push_back(j);
  }
  for (std::vector<int>& rows : droppedRowsOfColumn) std::sort(rows.begin(), rows.end());

  approximation_.resize(a.rows(), a.cols());
  std::vector<int> columnCounts(a.cols(), 0);
  sourceOffsets_.clear();
  sourceOffsets_.reserve(a.nonZeros());
  for (int col = 0; col < a.cols(); ++col) {
    const std::vector<int>& dropped = droppedRowsOfColumn[col / 3];
    for (int k = a.outerIndexPtr()[col]; k < a.outerIndexPtr()[col + 1]; ++k) {
      if (std::binary_search(dropped.begin(), dropped.end(), a.innerIndexPtr()[k] / 3)) continue;
      sourceOffsets_.push_back(k);
      ++columnCounts[col];
    }
  }
  approximation_.reserve(columnCounts);
  for (int col = 0; col < a.cols(); ++col) {
    const std::vector<int>& dropped = droppedRowsOfColumn[col / 3];
    for (int k = a.outerIndexPtr()[col]; k < a.outerIndexPtr()[col + 1]; ++k) {
      const int row = a.innerIndexPtr()[k];
      if (!std::binary_search(dropped.begin(), dropped.end(), row / 3)) approximation_.insert(row, col) = 0.0;
    }
  }
  approximation_.makeCompressed();

  droppedColumnOffsets_.clear();
  compensatedColumns_.clear();
  droppedColumnOffsets_.reserve(3 * weak.size());
  compensatedColumns_.reserve(6 * weak.size());
  for (const auto& [i, j] : weak) {
    for (int c = 0; c < 3; ++c) droppedColumnOffsets_.push_back(A.blockOffset(i, j, c));
    for (int vertex : {i, j})
      for (int c = 0; c < 3; ++c) compensatedColumns_.push_back(entryOffset(approximation_, 3 * vertex, 3 * vertex + c));
  }
}

void StrongCouplingApproximation::refill(const SystemMatrix& A) {
  const double* source = A.matrix().valuePtr();
  double* values = approximation_.valuePtr();
  for (size_t k = 0; k < sourceOffsets_.size(); ++k) values[k] = source[sourceOffsets_[k]];
  auto addToBlock = [values](const int* columnOffsets, const Mat3& m) {
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) values[columnOffsets[c] + r] += m(r, c);
  };
  const size_t pairs = droppedColumnOffsets_.size() / 3;
  for (size_t p = 0; p < pairs; ++p) {
    Mat3 B;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) B(r, c) = source[droppedColumnOffsets_[3 * p + c] + r];
    Mat3 forI, forJ;
    if (!strongCouplingCompensation(B, forI, forJ)) continue;  // e.g. a pinned vertex: nothing was dropped
    addToBlock(&compensatedColumns_[6 * p], forI);
    addToBlock(&compensatedColumns_[6 * p + 3], forJ);
  }
}

}  // namespace weft
