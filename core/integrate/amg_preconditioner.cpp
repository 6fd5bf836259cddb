#include "integrate/amg_preconditioner.h"

#include <algorithm>

namespace weft {
namespace {

constexpr int kNoVertex = -1;  // a dropped pair whose compensation adds nothing

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
  // A's pattern is made of whole 3x3 blocks (SystemMatrix), symmetric: the blocks of row i are
  // those of column block i (columns 3i .. 3i+2, which hold the same rows), in increasing order.
  // One pass over them beside each vertex's weak neighbours (sorted): every step of a tear meets
  // this analysis, so it takes no search and no per-row allocation (measured at 64²: 3.4 ms with a
  // binary search of the weak pairs per block, rows gathered and sorted again).
  const SystemMatrix::Sparse& source = A.matrix();
  const int* outer = source.outerIndexPtr();
  const int* rows = source.innerIndexPtr();
  const std::vector<std::pair<int, int>>& weak = A.weakPairs();  // (i < j), sorted
  const int n = A.vertexCount();
  // Each vertex's weak neighbours, increasing: the pairs (i, v), i < v, come before the (v, j).
  std::vector<int> weakStart(n + 1, 0), weakNeighbour(2 * weak.size());
  for (const auto& [i, j] : weak) {
    ++weakStart[i + 1];
    ++weakStart[j + 1];
  }
  for (int i = 0; i < n; ++i) weakStart[i + 1] += weakStart[i];
  {
    std::vector<int> fill(weakStart.begin(), weakStart.end() - 1);
    for (const auto& [i, j] : weak) {
      weakNeighbour[fill[i]++] = j;
      weakNeighbour[fill[j]++] = i;
    }
  }
  finest_.blockRows = n;
  finest_.blockColumns = n;
  finest_.rowStart.assign(n + 1, 0);
  finest_.column.clear();
  blockCode_.clear();
  diagonalSlot_.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    int w = weakStart[i];
    for (int k = outer[3 * i]; k < outer[3 * i + 1]; k += 3) {
      const int j = rows[k] / 3;
      while (w < weakStart[i + 1] && weakNeighbour[w] < j) ++w;
      if (w < weakStart[i + 1] && weakNeighbour[w] == j) {
        blockCode_.push_back(j < i ? kDroppedFirstSeen : kDroppedSecondSeen);
        continue;
      }
      if (j == i) diagonalSlot_[i] = static_cast<int>(finest_.column.size());
      blockCode_.push_back(static_cast<int>(finest_.column.size()));
      finest_.column.push_back(j);
    }
    finest_.rowStart[i + 1] = static_cast<int>(finest_.column.size());
  }
  finest_.blocks.assign(finest_.column.size(), Mat3::Zero());
  compensation_.assign(n, Mat3::Zero());
  codeStart_.assign(n + 1, 0);
  droppedStart_.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    const int blocks = (outer[3 * i + 1] - outer[3 * i]) / 3;
    codeStart_[i + 1] = codeStart_[i] + blocks;
    droppedStart_[i + 1] = droppedStart_[i] + static_cast<int>(std::count(blockCode_.begin() + codeStart_[i],
                                                                           blockCode_.begin() + codeStart_[i + 1],
                                                                           kDroppedFirstSeen));
  }
  droppedFor_.assign(droppedStart_[n], kNoVertex);
  droppedShare_.assign(droppedStart_[n], Mat3::Zero());
  whole_.blockRows = n;
  whole_.blockColumns = n;
  whole_.rowStart.assign(n + 1, 0);
  whole_.column.clear();
  for (int i = 0; i < n; ++i) {
    for (int k = outer[3 * i]; k < outer[3 * i + 1]; k += 3) whole_.column.push_back(rows[k] / 3);
    whole_.rowStart[i + 1] = static_cast<int>(whole_.column.size());
  }
  whole_.blocks.clear();  // sized by gatherWhole when needed
  analyzedPatternVersion_ = A.patternVersion();
  analyzedSize_ = A.matrix().rows();
}

void AmgPreconditioner::gather(const SystemMatrix& A) {
  // One pass over A, column block by column block: the finest level's row i is column block i
  // (A is symmetric), each block read as three runs of three values. A dropped pair (j, i), j < i,
  // met in column block i, adds its compensation (strong_coupling_approximation.h) to both
  // diagonals, summed apart and added at the end. The matrix StrongCouplingApproximation builds
  // for the lagged Cholesky (to rounding: the compensation's fast form), without its intermediate
  // copy of A (measured: that copy and its scattered reads were a quarter of the numeric setup at
  // 64²).
  const int* outer = A.matrix().outerIndexPtr();
  const double* values = A.matrix().valuePtr();
  const int n = finest_.blockRows;
  const int* rows = A.matrix().innerIndexPtr();
  const int parts = finest_.threadsFor(threads_);
  // Column block i: its kept blocks into finest_, its dropped pairs' shares for i into
  // compensation_[i] (after zeroing it: a vertex's own shares are the first it receives), and each
  // share for j (< i) to `shareForJ(j, share, pair)` (j = kNoVertex: nothing to add).
  auto gatherColumn = [&](int i, const auto& shareForJ) {
    const double* v[3] = {values + outer[3 * i], values + outer[3 * i + 1], values + outer[3 * i + 2]};
    const int length = outer[3 * i + 1] - outer[3 * i];
    const int* code = blockCode_.data() + codeStart_[i];
    int pair = droppedStart_[i];
    for (int k = 0; k < length; k += 3, ++code) {
      if (*code >= 0) {  // block (i, j)(r, c) = A(3j + c, 3i + r): row r is column 3i + r's run
        Mat3& block = finest_.blocks[*code];
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) block(r, c) = v[r][k + c];
      } else if (*code == kDroppedFirstSeen) {  // B = A_ji, j < i: B(r, c) = A(3j + r, 3i + c)
        Mat3 B;
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 3; ++r) B(r, c) = v[c][k + r];
        Mat3 forJ, forI;
        const int thisPair = pair++;
        if (!strongCouplingCompensationFast(B, forJ, forI)) {
          shareForJ(kNoVertex, Mat3(), thisPair);
          continue;
        }
        shareForJ(rows[outer[3 * i] + k] / 3, forJ, thisPair);
        compensation_[i] += forI;
      }
    }
  };
  if (parts == 1) {
    std::fill(compensation_.begin(), compensation_.end(), Mat3::Zero());
    for (int i = 0; i < n; ++i)
      gatherColumn(i, [&](int j, const Mat3& share, int) {
        if (j != kNoVertex) compensation_[j] += share;
      });
  } else {
    // The columns side by side, each pair's share for j kept; then those shares added by ranges of
    // j, in the columns' order. Every vertex's sum takes the same terms in the same order as above:
    // first its own column's shares (in column i only i's own diagonal is written), then those of
    // the later columns.
#pragma omp parallel for num_threads(parts) schedule(static)
    for (int i = 0; i < n; ++i) {
      compensation_[i] = Mat3::Zero();
      gatherColumn(i, [&](int j, const Mat3& share, int pair) {
        droppedFor_[pair] = j;
        if (j != kNoVertex) droppedShare_[pair] = share;
      });
    }
#pragma omp parallel for num_threads(parts) schedule(static, 1)
    for (int part = 0; part < parts; ++part) {
      const int first = static_cast<int>(static_cast<long>(n) * part / parts);
      const int end = static_cast<int>(static_cast<long>(n) * (part + 1) / parts);
      for (int pair = 0; pair < droppedStart_[n]; ++pair) {
        const int j = droppedFor_[pair];
        if (j >= first && j < end) compensation_[j] += droppedShare_[pair];
      }
    }
  }
#pragma omp parallel for num_threads(parts) schedule(static)
  for (int i = 0; i < n; ++i)
    if (diagonalSlot_[i] >= 0) finest_.blocks[diagonalSlot_[i]] += compensation_[i];
}

void AmgPreconditioner::gatherWhole(const SystemMatrix& A) {
  // A itself into whole_, and the wings' share of the off-diagonal coupling (block Frobenius norms).
  const int* outer = A.matrix().outerIndexPtr();
  const double* values = A.matrix().valuePtr();
  const int n = whole_.blockRows;
  whole_.blocks.resize(whole_.column.size());
  double weakNorms = 0.0, offDiagonalNorms = 0.0;
  int slot = 0;
  const int* code = blockCode_.data();
  for (int i = 0; i < n; ++i) {
    const double* v[3] = {values + outer[3 * i], values + outer[3 * i + 1], values + outer[3 * i + 2]};
    const int length = outer[3 * i + 1] - outer[3 * i];
    for (int k = 0; k < length; k += 3, ++slot, ++code) {
      Mat3& block = whole_.blocks[slot];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) block(r, c) = v[r][k + c];
      if (whole_.column[slot] == i) continue;
      const double norm = block.norm();
      offDiagonalNorms += norm;
      if (*code < 0) weakNorms += norm;
    }
  }
  wingShare_ = offDiagonalNorms > 0.0 ? weakNorms / offDiagonalNorms : 0.0;
}

void AmgPreconditioner::prepare(const SystemMatrix& A) {
  const bool patternChanged = A.patternVersion() != analyzedPatternVersion_ || A.matrix().rows() != analyzedSize_;
  BlockPattern previousFinest, previousWhole;
  if (patternChanged) {
    previousFinest.rowStart = std::move(finest_.rowStart);
    previousFinest.column = std::move(finest_.column);
    previousWhole.rowStart = std::move(whole_.rowStart);
    previousWhole.column = std::move(whole_.column);
    analyze(A);
  }
  const bool setUp = patternChanged || hierarchy_.levelCount() == 0;
  gather(A);
  if (wings_) gatherWhole(A);
  if (setUp) {
    hierarchy_.setFinestProductOperator(wings_ ? &whole_ : nullptr);
    if (hierarchy_.levelCount() > 0 && settings_.patchAfterPatternChange &&
        hierarchy_.patch(finest_, previousFinest, threads_, wings_ ? &previousWhole : nullptr)) {
      ++patchedSetups_;
    } else {
      // A build decides whether the wings enter the first Galerkin product (see Settings); a
      // patch keeps the decision (the hierarchy's patterns follow it).
      if (!wings_) gatherWhole(A);
      wings_ = wingShare_ >= settings_.wingShareThreshold;
      if (!wings_) std::vector<Mat3>().swap(whole_.blocks);  // not read until the next build's gatherWhole
      hierarchy_.setFinestProductOperator(wings_ ? &whole_ : nullptr);
      hierarchy_.build(finest_);
      ++fullSetups_;
    }
    if (settings_.singlePrecisionCycle) floatCycle_.build(hierarchy_, settings_.splitSweepRows);
  } else {
    hierarchy_.refresh(finest_, threads_);
  }
  if (settings_.singlePrecisionCycle) floatCycle_.refresh(hierarchy_, threads_);
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
  if (settings_.singlePrecisionCycle) {
    floatCycle_.apply(hierarchy_, inR, outZ, settings_.smoothingSweeps, threads_);
    return;
  }
  cycle(0, inR, outZ);
}

void AmgPreconditioner::applyInTeam(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) {
  if (!settings_.singlePrecisionCycle || hierarchy_.levelCount() == 0) {
    Preconditioner::applyInTeam(inR, outZ);
    return;
  }
  floatCycle_.applyInTeam(hierarchy_, inR, outZ, settings_.smoothingSweeps);
}

}  // namespace weft
