#include "integrate/system_matrix.h"

#include <algorithm>
#include <cassert>
#include <iterator>

namespace weft {

namespace {

// (min, max) of each pair off the diagonal, sorted, without repeats.
std::vector<std::pair<int, int>> orderedUniquePairs(const std::vector<std::pair<int, int>>& pairs) {
  std::vector<std::pair<int, int>> ordered;
  ordered.reserve(pairs.size());
  for (const auto& [i, j] : pairs)
    if (i != j) ordered.emplace_back(std::min(i, j), std::max(i, j));
  std::sort(ordered.begin(), ordered.end());
  ordered.erase(std::unique(ordered.begin(), ordered.end()), ordered.end());
  return ordered;
}

}  // namespace

void SystemMatrix::setPattern(int vertexCount, const std::vector<std::pair<int, int>>& coupledPairs,
                              const std::vector<std::pair<int, int>>& weaklyCoupledPairs) {
  const std::vector<std::pair<int, int>> strong = orderedUniquePairs(coupledPairs);
  const std::vector<std::pair<int, int>> weak = orderedUniquePairs(weaklyCoupledPairs);
  weakPairs_.clear();
  std::set_difference(weak.begin(), weak.end(), strong.begin(), strong.end(), std::back_inserter(weakPairs_));

  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(9 * (vertexCount + 2 * (strong.size() + weakPairs_.size())));
  auto addBlockEntries = [&](int i, int j) {
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) entries.emplace_back(3 * i + r, 3 * j + c, 0.0);
  };
  for (int i = 0; i < vertexCount; ++i) addBlockEntries(i, i);
  for (const auto& [i, j] : strong) {
    addBlockEntries(i, j);
    addBlockEntries(j, i);
  }
  for (const auto& [i, j] : weakPairs_) {
    addBlockEntries(i, j);
    addBlockEntries(j, i);
  }
  matrix_.resize(3 * vertexCount, 3 * vertexCount);
  matrix_.setFromTriplets(entries.begin(), entries.end());
  matrix_.makeCompressed();
  vertexCount_ = vertexCount;
  ++patternVersion_;
}

bool SystemMatrix::hasBlock(int i, int j) const {
  if (i >= vertexCount_ || j >= vertexCount_) return false;
  const int col = 3 * j;
  const int* rows = matrix_.innerIndexPtr();
  const int* begin = rows + matrix_.outerIndexPtr()[col];
  const int* end = rows + matrix_.outerIndexPtr()[col + 1];
  const int* found = std::lower_bound(begin, end, 3 * i);
  return found != end && *found == 3 * i;
}

void SystemMatrix::growPattern(int vertexCount, const std::vector<std::pair<int, int>>& coupledPairs,
                               const std::vector<std::pair<int, int>>& weaklyCoupledPairs) {
  assert(vertexCount >= vertexCount_ && "vertices are never removed");
  // The new blocks, as (block column, block row).
  std::vector<std::pair<int, int>> blocks;
  for (int i = vertexCount_; i < vertexCount; ++i) blocks.emplace_back(i, i);
  const std::vector<std::pair<int, int>> strong = orderedUniquePairs(coupledPairs);
  for (const auto& pair : strong) {
    const auto weak = std::lower_bound(weakPairs_.begin(), weakPairs_.end(), pair);
    if (weak != weakPairs_.end() && *weak == pair) weakPairs_.erase(weak);  // now strong too
    if (hasBlock(pair.first, pair.second)) continue;
    blocks.emplace_back(pair.first, pair.second);
    blocks.emplace_back(pair.second, pair.first);
  }
  for (const auto& pair : orderedUniquePairs(weaklyCoupledPairs)) {
    if (hasBlock(pair.first, pair.second) || std::binary_search(strong.begin(), strong.end(), pair)) continue;
    weakPairs_.insert(std::lower_bound(weakPairs_.begin(), weakPairs_.end(), pair), pair);
    blocks.emplace_back(pair.first, pair.second);
    blocks.emplace_back(pair.second, pair.first);
  }
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());

  // Merge, column by column, the old rows with the new blocks' rows (both ascending).
  const int size = 3 * vertexCount;
  const int oldSize = 3 * vertexCount_;
  const int* oldOuter = matrix_.outerIndexPtr();
  const int* oldRows = matrix_.innerIndexPtr();
  const double* oldValues = matrix_.valuePtr();
  Sparse grown(size, size);
  grown.resizeNonZeros(static_cast<Eigen::Index>(matrix_.nonZeros() + 9 * blocks.size()));
  int* outer = grown.outerIndexPtr();
  int* rows = grown.innerIndexPtr();
  double* values = grown.valuePtr();
  int written = 0;
  auto next = blocks.begin();
  for (int blockColumn = 0; blockColumn < vertexCount; ++blockColumn) {
    const auto first = next;
    while (next != blocks.end() && next->first == blockColumn) ++next;
    for (int c = 0; c < 3; ++c) {
      const int col = 3 * blockColumn + c;
      outer[col] = written;
      int k = col < oldSize ? oldOuter[col] : 0;
      const int end = col < oldSize ? oldOuter[col + 1] : 0;
      for (auto block = first; block != next; ++block) {
        const int row = 3 * block->second;
        for (; k < end && oldRows[k] < row; ++k, ++written) {
          rows[written] = oldRows[k];
          values[written] = oldValues[k];
        }
        for (int r = 0; r < 3; ++r, ++written) {
          rows[written] = row + r;
          values[written] = 0.0;
        }
      }
      for (; k < end; ++k, ++written) {
        rows[written] = oldRows[k];
        values[written] = oldValues[k];
      }
    }
  }
  outer[size] = written;
  assert(written == grown.nonZeros());
  matrix_.swap(grown);
  vertexCount_ = vertexCount;
  ++patternVersion_;
}

void SystemMatrix::setZero() { std::fill_n(matrix_.valuePtr(), matrix_.nonZeros(), 0.0); }

int SystemMatrix::blockOffset(int i, int j, int column) const {
  const int col = 3 * j + column;
  const int* rows = matrix_.innerIndexPtr();
  const int begin = matrix_.outerIndexPtr()[col];
  const int end = matrix_.outerIndexPtr()[col + 1];
  const int* found = std::lower_bound(rows + begin, rows + end, 3 * i);
  assert(found != rows + end && *found == 3 * i && "block not in the pattern");
  return static_cast<int>(found - rows);
}

void SystemMatrix::addBlock(int i, int j, const Mat3& m) {
  double* values = matrix_.valuePtr();
  for (int c = 0; c < 3; ++c) {
    const int offset = blockOffset(i, j, c);
    for (int r = 0; r < 3; ++r) values[offset + r] += m(r, c);
  }
}

void SystemMatrix::addDiagonal(int i, double value) {
  double* values = matrix_.valuePtr();
  for (int c = 0; c < 3; ++c) values[blockOffset(i, i, c) + c] += value;
}

double SystemMatrix::largestDiagonal(int i) const {
  const double* values = matrix_.valuePtr();
  return std::max({values[blockOffset(i, i, 0)], values[blockOffset(i, i, 1) + 1], values[blockOffset(i, i, 2) + 2]});
}

void SystemMatrix::constrainVertices(const std::vector<int>& vertices, const Eigen::VectorXd& knownValues,
                                     Eigen::VectorXd& rhs) {
  if (vertices.empty()) return;
  std::vector<char> constrained(vertexCount_, 0);
  for (int p : vertices) constrained[p] = 1;
  double* values = matrix_.valuePtr();
  const int* rows = matrix_.innerIndexPtr();
  const int* outer = matrix_.outerIndexPtr();
  // Column pass: move known columns to the right-hand side, then clear them.
  for (int p : vertices) {
    for (int c = 0; c < 3; ++c) {
      const int col = 3 * p + c;
      for (int k = outer[col]; k < outer[col + 1]; ++k) {
        const int row = rows[k];
        if (!constrained[row / 3]) rhs[row] -= values[k] * knownValues[col];
        values[k] = row == col ? 1.0 : 0.0;
      }
    }
  }
  // Row pass: clear the constrained rows in the other columns (the pattern is symmetric, so the
  // entries of row p are found in the columns coupled with p).
  for (int p : vertices) {
    for (int c = 0; c < 3; ++c) {
      const int col = 3 * p + c;
      for (int k = outer[col]; k < outer[col + 1]; ++k) {
        const int otherColumn = rows[k];
        if (constrained[otherColumn / 3]) continue;
        const int* begin = rows + outer[otherColumn];
        const int* end = rows + outer[otherColumn + 1];
        const int* found = std::lower_bound(begin, end, col);
        if (found != end && *found == col) values[found - rows] = 0.0;
      }
    }
    for (int c = 0; c < 3; ++c) rhs[3 * p + c] = knownValues[3 * p + c];
  }
}

}  // namespace weft
