#include "integrate/amg_float_cycle.h"

#include <algorithm>

namespace weft {
namespace {

using Float4 = AmgFloatCycle::Float4;

// The three columns of a double 3x3 block as padded float columns.
inline void storeColumns(const Mat3& m, Float4* out) {
  for (int c = 0; c < 3; ++c)
    out[c] = Float4{static_cast<float>(m(0, c)), static_cast<float>(m(1, c)), static_cast<float>(m(2, c)), 0.0f};
}

inline void storeTransposedColumns(const Mat3& m, Float4* out) {
  for (int c = 0; c < 3; ++c)
    out[c] = Float4{static_cast<float>(m(c, 0)), static_cast<float>(m(c, 1)), static_cast<float>(m(c, 2)), 0.0f};
}

// B x for a block B stored as three columns: x's lanes broadcast, multiplied, summed in a fixed order.
inline Float4 times(const Float4* B, Float4 x) {
  const Float4 x0 = Float4{x[0], x[0], x[0], x[0]};
  const Float4 x1 = Float4{x[1], x[1], x[1], x[1]};
  const Float4 x2 = Float4{x[2], x[2], x[2], x[2]};
  return B[0] * x0 + B[1] * x1 + B[2] * x2;
}

int threadsFor(int rows, int threads) { return rows >= BlockSparseMatrix::kRowsPerThread ? threads : 1; }

}  // namespace

void AmgFloatCycle::build(const AmgHierarchy& hierarchy) {
  levels_.assign(hierarchy.levelCount(), Level{});
  for (int l = 0; l < hierarchy.levelCount(); ++l) {
    const AmgHierarchy::Level& source = hierarchy.level(l);
    const BlockSparseMatrix& A = source.A;
    Level& level = levels_[l];
    level.rows = A.blockRows;
    level.offStart.assign(A.blockRows + 1, 0);
    level.upperStart.assign(A.blockRows, 0);
    level.diagonalSource.assign(A.blockRows, -1);
    level.offColumn.clear();
    level.offSource.clear();
    for (int i = 0; i < A.blockRows; ++i) {
      level.upperStart[i] = -1;
      for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
        const int j = A.column[k];
        if (j == i) {
          level.diagonalSource[i] = k;
          continue;
        }
        if (j > i && level.upperStart[i] < 0) level.upperStart[i] = static_cast<int>(level.offColumn.size());
        level.offColumn.push_back(j);
        level.offSource.push_back(k);
      }
      level.offStart[i + 1] = static_cast<int>(level.offColumn.size());
      if (level.upperStart[i] < 0) level.upperStart[i] = level.offStart[i + 1];
    }
    level.off.resize(3 * level.offColumn.size());
    level.inverseDiagonal.resize(3 * static_cast<size_t>(A.blockRows));
    level.diagonal.resize(3 * static_cast<size_t>(A.blockRows));
    level.b.assign(A.blockRows, Float4{});
    level.x.assign(A.blockRows, Float4{});
    level.r.assign(A.blockRows, Float4{});
    level.p.clear();
    level.transposeStart.clear();
    level.transposeColumn.clear();
    level.transposeSource.clear();
    level.pt.clear();
    if (l + 1 < hierarchy.levelCount()) {
      const BlockSparseMatrix& P = source.P;
      level.p.resize(3 * static_cast<size_t>(P.blockCount()));
      // P^T's rows: for each coarse vertex, the fine rows i with a block (i, J), in increasing i.
      level.transposeStart.assign(P.blockColumns + 1, 0);
      for (int k = 0; k < P.blockCount(); ++k) ++level.transposeStart[P.column[k] + 1];
      for (int J = 0; J < P.blockColumns; ++J) level.transposeStart[J + 1] += level.transposeStart[J];
      level.transposeColumn.resize(P.blockCount());
      level.transposeSource.resize(P.blockCount());
      std::vector<int> fill(level.transposeStart.begin(), level.transposeStart.end() - 1);
      for (int i = 0; i < P.blockRows; ++i)
        for (int k = P.rowStart[i]; k < P.rowStart[i + 1]; ++k) {
          const int slot = fill[P.column[k]]++;
          level.transposeColumn[slot] = i;
          level.transposeSource[slot] = k;
        }
      level.pt.resize(3 * static_cast<size_t>(P.blockCount()));
    }
  }
}

void AmgFloatCycle::refresh(const AmgHierarchy& hierarchy, int threads) {
  for (int l = 0; l < hierarchy.levelCount(); ++l) {
    const AmgHierarchy::Level& source = hierarchy.level(l);
    Level& level = levels_[l];
    const int rowThreads = threadsFor(level.rows, threads);
#pragma omp parallel for num_threads(rowThreads) schedule(static)
    for (int i = 0; i < level.rows; ++i) {
      for (int k = level.offStart[i]; k < level.offStart[i + 1]; ++k)
        storeColumns(source.A.blocks[level.offSource[k]], &level.off[3 * static_cast<size_t>(k)]);
      storeColumns(source.inverseDiagonal[i], &level.inverseDiagonal[3 * static_cast<size_t>(i)]);
      storeColumns(level.diagonalSource[i] >= 0 ? source.A.blocks[level.diagonalSource[i]] : Mat3::Zero().eval(),
                   &level.diagonal[3 * static_cast<size_t>(i)]);
    }
    if (l + 1 == hierarchy.levelCount()) continue;
    const BlockSparseMatrix& P = source.P;
#pragma omp parallel for num_threads(rowThreads) schedule(static)
    for (int i = 0; i < P.blockRows; ++i)
      for (int k = P.rowStart[i]; k < P.rowStart[i + 1]; ++k) storeColumns(P.blocks[k], &level.p[3 * static_cast<size_t>(k)]);
    const int coarseRows = static_cast<int>(level.transposeStart.size()) - 1;
#pragma omp parallel for num_threads(threadsFor(coarseRows, threads)) schedule(static)
    for (int J = 0; J < coarseRows; ++J)
      for (int s = level.transposeStart[J]; s < level.transposeStart[J + 1]; ++s)
        storeTransposedColumns(P.blocks[level.transposeSource[s]], &level.pt[3 * static_cast<size_t>(s)]);
  }
}

void AmgFloatCycle::apply(const AmgHierarchy& hierarchy, const Eigen::VectorXd& inR, Eigen::VectorXd& outZ, int sweeps,
                          int threads) {
  Level& finest = levels_[0];
  for (int i = 0; i < finest.rows; ++i)
    finest.b[i] = Float4{static_cast<float>(inR[3 * i]), static_cast<float>(inR[3 * i + 1]),
                         static_cast<float>(inR[3 * i + 2]), 0.0f};
  cycle(hierarchy, 0, std::max(sweeps, 1), threads);
  outZ.resize(inR.size());
  for (int i = 0; i < finest.rows; ++i)
    for (int c = 0; c < 3; ++c) outZ[3 * i + c] = finest.x[i][c];
}

void AmgFloatCycle::cycle(const AmgHierarchy& hierarchy, int l, int sweeps, int threads) {
  Level& level = levels_[l];
  const int n = level.rows;
  const bool coarsest = l + 1 == hierarchy.levelCount();
  if (coarsest && hierarchy.coarsestFactored()) {
    // The coarsest level's dense Cholesky solve, in double (a few dozen unknowns).
    coarsestRhs_.resize(3 * static_cast<Eigen::Index>(n));
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) coarsestRhs_[3 * i + c] = level.b[i][c];
    coarsestSolution_ = hierarchy.coarsestFactor().solve(coarsestRhs_);
    for (int i = 0; i < n; ++i)
      level.x[i] = Float4{static_cast<float>(coarsestSolution_[3 * i]), static_cast<float>(coarsestSolution_[3 * i + 1]),
                          static_cast<float>(coarsestSolution_[3 * i + 2]), 0.0f};
    return;
  }
  const Float4* off = level.off.data();
  const Float4* inverseDiagonal = level.inverseDiagonal.data();
  Float4* x = level.x.data();
  const Float4* b = level.b.data();
  // First forward sweep from x = 0: the blocks right of the diagonal multiply zeros, skip them.
  for (int i = 0; i < n; ++i) {
    Float4 sum = b[i];
    for (int k = level.offStart[i]; k < level.upperStart[i]; ++k) sum -= times(off + 3 * k, x[level.offColumn[k]]);
    x[i] = times(inverseDiagonal + 3 * i, sum);
  }
  for (int sweep = 1; sweep < sweeps; ++sweep)
    for (int i = 0; i < n; ++i) {
      Float4 sum = b[i];
      for (int k = level.offStart[i]; k < level.offStart[i + 1]; ++k) sum -= times(off + 3 * k, x[level.offColumn[k]]);
      x[i] = times(inverseDiagonal + 3 * i, sum);
    }
  if (!coarsest) {
    Level& coarse = levels_[l + 1];
    Float4* r = level.r.data();
    const int rowThreads = threadsFor(n, threads);
    // The residual b - A x. After one sweep from zero each row's equation was met with the lower
    // part and the diagonal when it was solved: what is left is -(strictly upper part) x.
    if (sweeps == 1) {
#pragma omp parallel for num_threads(rowThreads) schedule(static)
      for (int i = 0; i < n; ++i) {
        Float4 sum = Float4{};
        for (int k = level.upperStart[i]; k < level.offStart[i + 1]; ++k) sum -= times(off + 3 * k, x[level.offColumn[k]]);
        r[i] = sum;
      }
    } else {
#pragma omp parallel for num_threads(rowThreads) schedule(static)
      for (int i = 0; i < n; ++i) {
        Float4 sum = b[i] - times(level.diagonal.data() + 3 * i, x[i]);
        for (int k = level.offStart[i]; k < level.offStart[i + 1]; ++k) sum -= times(off + 3 * k, x[level.offColumn[k]]);
        r[i] = sum;
      }
    }
    // Restriction: the coarse right-hand side P^T r, gathered by coarse rows.
    const int coarseThreads = threadsFor(coarse.rows, threads);
#pragma omp parallel for num_threads(coarseThreads) schedule(static)
    for (int J = 0; J < coarse.rows; ++J) {
      Float4 sum = Float4{};
      for (int k = level.transposeStart[J]; k < level.transposeStart[J + 1]; ++k)
        sum += times(level.pt.data() + 3 * k, r[level.transposeColumn[k]]);
      coarse.b[J] = sum;
    }
    cycle(hierarchy, l + 1, sweeps, threads);
    // Prolongation: x += P e.
    const BlockSparseMatrix& P = hierarchy.level(l).P;
    const Float4* e = coarse.x.data();
#pragma omp parallel for num_threads(rowThreads) schedule(static)
    for (int i = 0; i < n; ++i) {
      Float4 sum = Float4{};
      for (int k = P.rowStart[i]; k < P.rowStart[i + 1]; ++k) sum += times(level.p.data() + 3 * k, e[P.column[k]]);
      x[i] += sum;
    }
  }
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (int i = n - 1; i >= 0; --i) {
      Float4 sum = b[i];
      for (int k = level.offStart[i]; k < level.offStart[i + 1]; ++k) sum -= times(off + 3 * k, x[level.offColumn[k]]);
      x[i] = times(inverseDiagonal + 3 * i, sum);
    }
}

}  // namespace weft
