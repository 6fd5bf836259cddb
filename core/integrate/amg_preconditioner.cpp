#include "integrate/amg_preconditioner.h"

#include <algorithm>

namespace weft {
namespace {

// Forward (i = 0 .. n-1) or backward block Gauss-Seidel sweep on A x = b.
void gaussSeidelSweep(const AmgHierarchy::Level& level, const Eigen::VectorXd& b, Eigen::VectorXd& x, bool forward) {
  const BlockSparseMatrix& A = level.A;
  const int n = A.blockRows;
  for (int step = 0; step < n; ++step) {
    const int i = forward ? step : n - 1 - step;
    Vec3 sum = b.segment<3>(3 * i);
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      const int j = A.column[k];
      if (j != i) sum.noalias() -= A.blocks[k] * x.segment<3>(3 * j);
    }
    x.segment<3>(3 * i) = level.inverseDiagonal[i] * sum;
  }
}

// The first forward sweep from x = 0: the blocks right of the diagonal multiply zeros, skip them.
// Then the residual b - A x of that x is -(strictly upper part of A) x: each row's equation was
// met with the lower part and the diagonal at the moment it was solved. Both halve their work.
void gaussSeidelSweepFromZero(const AmgHierarchy::Level& level, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const BlockSparseMatrix& A = level.A;
  for (int i = 0; i < A.blockRows; ++i) {
    Vec3 sum = b.segment<3>(3 * i);
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1] && A.column[k] < i; ++k)
      sum.noalias() -= A.blocks[k] * x.segment<3>(3 * A.column[k]);
    x.segment<3>(3 * i) = level.inverseDiagonal[i] * sum;
  }
}

void residualAfterOneForwardSweep(const AmgHierarchy::Level& level, const Eigen::VectorXd& x, Eigen::VectorXd& outR,
                                  int threads) {
  const BlockSparseMatrix& A = level.A;
  outR.resize(x.size());
#pragma omp parallel for num_threads(A.threadsFor(threads)) schedule(static)
  for (int i = 0; i < A.blockRows; ++i) {
    Vec3 sum = Vec3::Zero();
    for (int k = A.rowStart[i + 1] - 1; k >= A.rowStart[i] && A.column[k] > i; --k)
      sum.noalias() -= A.blocks[k] * x.segment<3>(3 * A.column[k]);
    outR.segment<3>(3 * i) = sum;
  }
}

}  // namespace

void AmgPreconditioner::analyze(const SystemMatrix& A) {
  dropsWeakCouplings_ = !A.weakPairs().empty();
  if (dropsWeakCouplings_) approximation_.setPattern(A);
  const SystemMatrix::Sparse& source = dropsWeakCouplings_ ? approximation_.matrix() : A.matrix();
  // Row i of the (symmetric) block pattern = the block rows of column 3i.
  const int n = A.vertexCount();
  std::vector<std::vector<int>> columnsOfRow(n);
  for (int i = 0; i < n; ++i)
    for (int k = source.outerIndexPtr()[3 * i]; k < source.outerIndexPtr()[3 * i + 1]; ++k)
      columnsOfRow[i].push_back(source.innerIndexPtr()[k] / 3);
  finest_.setPattern(n, n, columnsOfRow);
  gatherOffsets_.resize(3 * static_cast<size_t>(finest_.blockCount()));
  const int* rows = source.innerIndexPtr();
  for (int i = 0; i < n; ++i)
    for (int s = finest_.rowStart[i]; s < finest_.rowStart[i + 1]; ++s)
      for (int c = 0; c < 3; ++c) {
        const int col = 3 * finest_.column[s] + c;
        const int* begin = rows + source.outerIndexPtr()[col];
        const int* end = rows + source.outerIndexPtr()[col + 1];
        gatherOffsets_[3 * s + c] = static_cast<int>(std::lower_bound(begin, end, 3 * i) - rows);
      }
  analyzedPatternVersion_ = A.patternVersion();
  analyzedSize_ = A.matrix().rows();
}

void AmgPreconditioner::gather(const SystemMatrix& A) {
  if (dropsWeakCouplings_) approximation_.refill(A);
  const double* values = dropsWeakCouplings_ ? approximation_.matrix().valuePtr() : A.matrix().valuePtr();
#pragma omp parallel for num_threads(finest_.threadsFor(threads_)) schedule(static)
  for (int s = 0; s < finest_.blockCount(); ++s)
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) finest_.blocks[s](r, c) = values[gatherOffsets_[3 * s + c] + r];
}

void AmgPreconditioner::prepare(const SystemMatrix& A) {
  const bool patternChanged = A.patternVersion() != analyzedPatternVersion_ || A.matrix().rows() != analyzedSize_;
  if (patternChanged) analyze(A);
  gather(A);
  if (patternChanged || hierarchy_.levelCount() == 0) {
    hierarchy_.build(finest_);
    ++fullSetups_;
  } else {
    hierarchy_.refresh(finest_, threads_);
  }
}

void AmgPreconditioner::cycle(int l, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  AmgHierarchy::Level& level = hierarchy_.level(l);
  x.setZero(b.size());
  const bool coarsest = l + 1 == hierarchy_.levelCount();
  if (coarsest && hierarchy_.coarsestFactored()) {
    x = hierarchy_.coarsestFactor().solve(b);
    return;
  }
  gaussSeidelSweepFromZero(level, b, x);
  for (int sweep = 1; sweep < settings_.smoothingSweeps; ++sweep) gaussSeidelSweep(level, b, x, true);
  if (!coarsest) {
    AmgHierarchy::Level& coarse = hierarchy_.level(l + 1);
    if (settings_.smoothingSweeps == 1) {
      residualAfterOneForwardSweep(level, x, level.residual, threads_);
    } else {
      level.A.multiply(x, level.residual, threads_);
      level.residual = b - level.residual;
    }
    coarse.rhs.setZero(3 * static_cast<Eigen::Index>(coarse.A.blockRows));
    level.P.addTransposeProduct(level.residual, coarse.rhs);
    cycle(l + 1, coarse.rhs, coarse.solution);
    level.P.multiply(coarse.solution, level.residual, threads_);
    x += level.residual;
  }
  for (int sweep = 0; sweep < settings_.smoothingSweeps; ++sweep) gaussSeidelSweep(level, b, x, false);
}

void AmgPreconditioner::apply(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) {
  if (hierarchy_.levelCount() == 0) {  // not prepared: M = I
    outZ = inR;
    return;
  }
  cycle(0, inR, outZ);
}

}  // namespace weft
