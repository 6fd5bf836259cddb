#include "integrate/amg_float_cycle.h"

#include <algorithm>

#include <omp.h>

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

// The cycle's row-wise passes (residual, restriction, prolongation, the conversions) go on several
// threads from this many rows: a pass over 256 rows takes ~20 µs at 64², against a few µs to start
// the threads. Each row is summed alone, so the bits do not depend on the thread count.
constexpr int kCycleRowsPerThread = 256;

int threadsFor(int rows, int threads) { return rows >= kCycleRowsPerThread ? threads : 1; }

}  // namespace

void AmgFloatCycle::build(const AmgHierarchy& hierarchy, int splitRows) {
  levels_.assign(hierarchy.levelCount(), Level{});
  for (int l = 0; l < hierarchy.levelCount(); ++l) {
    const AmgHierarchy::Level& source = hierarchy.level(l);
    const BlockSparseMatrix& A = source.A;
    Level& level = levels_[l];
    level.rows = A.blockRows;
    // The sweep order's groups (Level says why): 0 below the split, 1 after it, 2 the interface.
    std::vector<char> group(A.blockRows, 0);
    level.split = splitRows > 0 && A.blockRows >= splitRows ? A.blockRows / 2 : 0;
    level.secondGroup.clear();
    level.interfaceRows.clear();
    if (level.split > 0) {
      for (int i = level.split; i < A.blockRows; ++i) {
        bool touchesFirst = false;
        for (int k = A.rowStart[i]; k < A.rowStart[i + 1] && !touchesFirst; ++k) touchesFirst = A.column[k] < level.split;
        group[i] = touchesFirst ? 2 : 1;
        (touchesFirst ? level.interfaceRows : level.secondGroup).push_back(i);
      }
    }
    auto before = [&](int a, int b) { return group[a] != group[b] ? group[a] < group[b] : a < b; };
    level.offStart.assign(A.blockRows + 1, 0);
    level.laterStart.assign(A.blockRows, 0);
    level.diagonalSource.assign(A.blockRows, -1);
    level.offColumn.clear();
    level.offSource.clear();
    std::vector<std::pair<int, int>> row;  // (column, slot) of one row's off-diagonal blocks
    for (int i = 0; i < A.blockRows; ++i) {
      row.clear();
      for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
        if (A.column[k] == i) {
          level.diagonalSource[i] = k;
        } else {
          row.emplace_back(A.column[k], k);
        }
      }
      // In sweep order (the columns' own order when there is no split: A's rows are sorted).
      if (level.split > 0)
        std::stable_sort(row.begin(), row.end(), [&](const auto& a, const auto& b) { return before(a.first, b.first); });
      const int first = static_cast<int>(level.offColumn.size());
      int later = first + static_cast<int>(row.size());
      for (std::size_t n = 0; n < row.size(); ++n) {
        if (later == first + static_cast<int>(row.size()) && before(i, row[n].first)) later = first + static_cast<int>(n);
        level.offColumn.push_back(row[n].first);
        level.offSource.push_back(row[n].second);
      }
      level.laterStart[i] = later;
      level.offStart[i + 1] = static_cast<int>(level.offColumn.size());
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
  if (threads <= 1 || levels_[0].rows < kCycleRowsPerThread) {
    applyWith(hierarchy, inR, outZ, sweeps, false);
    return;
  }
#pragma omp parallel num_threads(threads)
  applyInTeam(hierarchy, inR, outZ, sweeps);
}

void AmgFloatCycle::applyInTeam(const AmgHierarchy& hierarchy, const Eigen::VectorXd& inR, Eigen::VectorXd& outZ,
                                int sweeps) {
  if (omp_get_num_threads() == 1) {
    applyWith(hierarchy, inR, outZ, sweeps, false);
  } else if (levels_[0].rows < kCycleRowsPerThread) {
#pragma omp single
    applyWith(hierarchy, inR, outZ, sweeps, false);
  } else {
    applyWith(hierarchy, inR, outZ, sweeps, true);
  }
}

void AmgFloatCycle::applyWith(const AmgHierarchy& hierarchy, const Eigen::VectorXd& inR, Eigen::VectorXd& outZ,
                              int sweeps, bool shared) {
  Level& finest = levels_[0];
  once(shared, [&] { outZ.resize(inR.size()); });
  forRows(shared, finest.rows, [&](int i) {
    finest.b[i] = Float4{static_cast<float>(inR[3 * i]), static_cast<float>(inR[3 * i + 1]),
                         static_cast<float>(inR[3 * i + 2]), 0.0f};
  });
  cycle(hierarchy, 0, std::max(sweeps, 1), shared);
  forRows(shared, finest.rows, [&](int i) {
    for (int c = 0; c < 3; ++c) outZ[3 * i + c] = finest.x[i][c];
  });
}

template <typename Body>
void AmgFloatCycle::forRows(bool shared, int rows, const Body& body) {
  if (!shared) {
    for (int i = 0; i < rows; ++i) body(i);
    return;
  }
#pragma omp for schedule(static)
  for (int i = 0; i < rows; ++i) body(i);
}

template <typename Body>
void AmgFloatCycle::once(bool shared, const Body& body) {
  if (!shared) {
    body();
    return;
  }
#pragma omp single
  body();
}

void AmgFloatCycle::cycle(const AmgHierarchy& hierarchy, int l, int sweeps, bool shared) {
  Level& level = levels_[l];
  const int n = level.rows;
  const bool coarsest = l + 1 == hierarchy.levelCount();
  if (shared && (coarsest || n < kCycleRowsPerThread)) {
    // Too small to share: this level and those below on one thread of the team.
#pragma omp single
    cycle(hierarchy, l, sweeps, false);
    return;
  }
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
  // First forward sweep from x = 0: the blocks of rows later in the order multiply zeros, skip them.
  sweepForward(level, shared, [&](int i) {
    Float4 sum = b[i];
    for (int k = level.offStart[i]; k < level.laterStart[i]; ++k) sum -= times(off + 3 * k, x[level.offColumn[k]]);
    x[i] = times(inverseDiagonal + 3 * i, sum);
  });
  auto solveRow = [&](int i) {
    Float4 sum = b[i];
    for (int k = level.offStart[i]; k < level.offStart[i + 1]; ++k) sum -= times(off + 3 * k, x[level.offColumn[k]]);
    x[i] = times(inverseDiagonal + 3 * i, sum);
  };
  for (int sweep = 1; sweep < sweeps; ++sweep) sweepForward(level, shared, solveRow);
  if (!coarsest) {
    Level& coarse = levels_[l + 1];
    Float4* r = level.r.data();
    // The residual b - A x. After one sweep from zero each row's equation was met with the rows
    // before it and the diagonal when it was solved: what is left is -(the rows after it) x.
    if (sweeps == 1) {
      forRows(shared, n, [&](int i) {
        Float4 sum = Float4{};
        for (int k = level.laterStart[i]; k < level.offStart[i + 1]; ++k) sum -= times(off + 3 * k, x[level.offColumn[k]]);
        r[i] = sum;
      });
    } else {
      forRows(shared, n, [&](int i) {
        Float4 sum = b[i] - times(level.diagonal.data() + 3 * i, x[i]);
        for (int k = level.offStart[i]; k < level.offStart[i + 1]; ++k) sum -= times(off + 3 * k, x[level.offColumn[k]]);
        r[i] = sum;
      });
    }
    // Restriction: the coarse right-hand side P^T r, gathered by coarse rows (a few on one thread).
    auto restrictRow = [&](int J) {
      Float4 sum = Float4{};
      for (int k = level.transposeStart[J]; k < level.transposeStart[J + 1]; ++k)
        sum += times(level.pt.data() + 3 * k, r[level.transposeColumn[k]]);
      coarse.b[J] = sum;
    };
    if (shared && coarse.rows < kCycleRowsPerThread) {
      once(shared, [&] { forRows(false, coarse.rows, restrictRow); });
    } else {
      forRows(shared, coarse.rows, restrictRow);
    }
    cycle(hierarchy, l + 1, sweeps, shared);
    // Prolongation: x += P e.
    const BlockSparseMatrix& P = hierarchy.level(l).P;
    const Float4* e = coarse.x.data();
    forRows(shared, n, [&](int i) {
      Float4 sum = Float4{};
      for (int k = P.rowStart[i]; k < P.rowStart[i + 1]; ++k) sum += times(level.p.data() + 3 * k, e[P.column[k]]);
      x[i] += sum;
    });
  }
  for (int sweep = 0; sweep < sweeps; ++sweep) sweepBackward(level, shared, solveRow);
}

template <typename Row>
void AmgFloatCycle::sweepForward(const Level& level, bool shared, const Row& row) {
  if (level.split == 0) {
    once(shared, [&] {
      for (int i = 0; i < level.rows; ++i) row(i);
    });
    return;
  }
  forRows(shared, 2, [&](int group) {
    if (group == 0) {
      for (int i = 0; i < level.split; ++i) row(i);
    } else {
      for (int i : level.secondGroup) row(i);
    }
  });
  once(shared, [&] {
    for (int i : level.interfaceRows) row(i);
  });
}

template <typename Row>
void AmgFloatCycle::sweepBackward(const Level& level, bool shared, const Row& row) {
  if (level.split == 0) {
    once(shared, [&] {
      for (int i = level.rows - 1; i >= 0; --i) row(i);
    });
    return;
  }
  once(shared, [&] {
    for (auto i = level.interfaceRows.rbegin(); i != level.interfaceRows.rend(); ++i) row(*i);
  });
  forRows(shared, 2, [&](int group) {
    if (group == 0) {
      for (int i = level.split - 1; i >= 0; --i) row(i);
    } else {
      for (auto i = level.secondGroup.rbegin(); i != level.secondGroup.rend(); ++i) row(*i);
    }
  });
}

}  // namespace weft
