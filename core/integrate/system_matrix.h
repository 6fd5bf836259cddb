#pragma once
// The 3n x 3n system matrix of a cloth, stored as an Eigen column-major sparse matrix whose
// pattern (3x3 blocks between vertices that share a triangle or a bending hinge) is built once
// per topology and then only refilled: no allocation per step.
#include <utility>
#include <vector>

#include <Eigen/SparseCore>

#include "util/types.h"

namespace weft {

class SystemMatrix {
 public:
  using Sparse = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  // Builds the pattern: diagonal blocks for every vertex plus both (i,j) and (j,i) blocks for each
  // coupled pair. Full symmetric storage (CG reads both triangles, CHOLMOD the lower one).
  // weaklyCoupledPairs are in the pattern too, but known to couple their vertices only weakly
  // (bending hinge wings, next to the membrane's edges): a preconditioner may drop them.
  void setPattern(int vertexCount, const std::vector<std::pair<int, int>>& coupledPairs,
                  const std::vector<std::pair<int, int>>& weaklyCoupledPairs = {});
  // Grows the pattern after a local topology change (a tear) without rebuilding it: rows and
  // columns for the new vertices (vertexCount may grow) and the blocks of the given pairs that
  // are not in it yet, merged column by column into the compressed storage (one pass over it, no
  // sort of the whole pattern; values kept). Pairs the change uncoupled stay in the pattern as
  // explicit zeros, so the grown pattern contains, and may exceed, what setPattern would build;
  // a pair stays strong once strong (weakPairs() may miss a pair demoted to a hinge wing). The
  // version increases: a solver must redo its symbolic analysis of the new pattern.
  void growPattern(int vertexCount, const std::vector<std::pair<int, int>>& coupledPairs,
                   const std::vector<std::pair<int, int>>& weaklyCoupledPairs = {});
  bool hasPattern() const { return vertexCount_ > 0; }
  // Block (i, j) is in the pattern.
  bool hasBlock(int i, int j) const;
  int vertexCount() const { return vertexCount_; }
  // Increases every time the pattern changes (solvers redo their symbolic analysis then).
  int patternVersion() const { return patternVersion_; }
  // The weakly coupled pairs (i < j) that are not also strongly coupled, sorted, without repeats.
  const std::vector<std::pair<int, int>>& weakPairs() const { return weakPairs_; }

  void setZero();
  // Adds m to block (i, j). The block must be in the pattern.
  void addBlock(int i, int j, const Mat3& m);
  void addDiagonal(int i, double value);  // adds value * I to block (i, i)
  double largestDiagonal(int i) const;     // the largest of block (i, i)'s three diagonal entries
  // Offset into valuePtr() of entry (3i + r, 3j + c) is blockOffset(i, j, c) + r.
  int blockOffset(int i, int j, int column) const;

  // Replaces the rows and columns of the given vertices by identity rows, moving the known
  // values y of those unknowns to the right-hand side: b -= A[:, p] y_p, then b_p = y_p.
  void constrainVertices(const std::vector<int>& vertices, const Eigen::VectorXd& knownValues, Eigen::VectorXd& rhs);

  const Sparse& matrix() const { return matrix_; }
  Sparse& matrix() { return matrix_; }

 private:
  Sparse matrix_;
  std::vector<std::pair<int, int>> weakPairs_;
  int vertexCount_ = 0;
  int patternVersion_ = 0;
};

}  // namespace weft
