#include "integrate/preconditioned_cg.h"

#include <algorithm>
#include <cmath>

#include <omp.h>

namespace weft {
namespace {

constexpr Eigen::Index kMinimumColumnsPerThread = 6000;  // below this the fork costs more than it saves

// outY = A^T x (= A x for the symmetric A) as Eigen computes it on one thread (a dot product of
// each column of A with x), split into fixed ranges of columns: the same bits for any thread count.
// The fallback of blockProduct below for a pattern that is not made of whole 3x3 blocks.
void multiplyTransposed(const SystemMatrix::Sparse& A, const Eigen::VectorXd& x, Eigen::VectorXd& outY, int threads) {
  const Eigen::Index n = A.cols();
  outY.resize(n);
  const int parts = static_cast<int>(std::clamp<Eigen::Index>(n / kMinimumColumnsPerThread, 1, std::max(threads, 1)));
  if (parts == 1) {
    outY.noalias() = A.transpose() * x;
    return;
  }
#pragma omp parallel for num_threads(parts) schedule(static, 1)
  for (int part = 0; part < parts; ++part) {
    const Eigen::Index begin = n * part / parts;
    const Eigen::Index end = n * (part + 1) / parts;
    outY.segment(begin, end - begin).noalias() = A.middleCols(begin, end - begin).transpose() * x;
  }
}

// One block column's three dot products from block k = begin on (k counts entries of column 3i),
// each continuing its running sum.
inline void blockColumnSums(const double* v0, const double* v1, const double* v2, const int* row, int begin, int end,
                            const double* in, double& t0, double& t1, double& t2) {
  for (int k = begin; k < end; k += 3) {
    const double* xj = in + row[k];
    const double x0 = xj[0], x1 = xj[1], x2 = xj[2];
    t0 += v0[k] * x0;
    t1 += v1[k] * x0;
    t2 += v2[k] * x0;
    t0 += v0[k + 1] * x1;
    t1 += v1[k + 1] * x1;
    t2 += v2[k + 1] * x1;
    t0 += v0[k + 2] * x2;
    t1 += v1[k + 2] * x2;
    t2 += v2[k + 2] * x2;
  }
}

// outY(3i + r) for r = 0..2: the dot products of columns 3i, 3i+1, 3i+2 of A with x, read as 3x3
// blocks. A system matrix's pattern is made of whole blocks (SystemMatrix::setPattern), so the
// three columns of a vertex hold the same rows, in runs of three: one row index per block instead
// of one per entry (12 -> 8.4 bytes per nonzero streamed), x read as contiguous triples, and three
// independent sums per block column instead of one dependency chain. Each sum adds the same
// products in the same order (rows ascending) as Eigen's dot product in multiplyTransposed,
// starting from 0 and added to a zeroed result: the same bits as Eigen, the default solver's
// results unchanged (tested).
void blockColumnsProduct(const SystemMatrix::Sparse& A, const Eigen::VectorXd& x, Eigen::VectorXd& outY, int firstBlock,
                         int endBlock) {
  const int* outer = A.outerIndexPtr();
  const int* rows = A.innerIndexPtr();
  const double* values = A.valuePtr();
  const double* in = x.data();
  double* out = outY.data();
  // One block column at a time (two interleaved, six chains instead of three, measured no faster:
  // 0.113 against 0.107 ms per product at 64²).
  for (int i = firstBlock; i < endBlock; ++i) {
    // Eigen adds each dot product to a zeroed result (0 + -0 = +0): so do we.
    double t0 = 0.0, t1 = 0.0, t2 = 0.0;
    blockColumnSums(values + outer[3 * i], values + outer[3 * i + 1], values + outer[3 * i + 2], rows + outer[3 * i], 0,
                    outer[3 * i + 1] - outer[3 * i], in, t0, t1, t2);
    out[3 * i] = 0.0 + t0;
    out[3 * i + 1] = 0.0 + t1;
    out[3 * i + 2] = 0.0 + t2;
  }
}

// The CG's vector work on long vectors: element-wise updates split over the threads, and dot
// products summed as partial dots over fixed chunks of kDotChunk entries, added in chunk order, so
// the same bits for any thread count; a vector of at most one chunk is Eigen's own dot product
// (the shipped scenes' sizes: their results unchanged).
constexpr Eigen::Index kDotChunk = 8192;

int vectorParts(Eigen::Index n, int threads) {
  return static_cast<int>(std::clamp<Eigen::Index>(n / kMinimumColumnsPerThread, 1, std::max(threads, 1)));
}

int chunkCount(Eigen::Index n) { return static_cast<int>((n + kDotChunk - 1) / kDotChunk); }

// Chunk c's partial dot.
double chunkDot(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int c) {
  const Eigen::Index begin = c * kDotChunk, length = std::min(kDotChunk, a.size() - begin);
  return a.segment(begin, length).dot(b.segment(begin, length));
}

// The partials added in chunk order.
double sumOfChunks(const double* partial, int chunks) {
  double sum = 0.0;
  for (int c = 0; c < chunks; ++c) sum += partial[c];
  return sum;
}

double chunkedDot(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int threads, std::vector<double>& partial) {
  const Eigen::Index n = a.size();
  if (n <= kDotChunk) return a.dot(b);
  const int chunks = chunkCount(n);
  partial.resize(chunks);
#pragma omp parallel for num_threads(std::min(vectorParts(n, threads), chunks)) schedule(static)
  for (int c = 0; c < chunks; ++c) partial[c] = chunkDot(a, b, c);
  return sumOfChunks(partial.data(), chunks);
}

double chunkedNorm(const Eigen::VectorXd& a, int threads, std::vector<double>& partial) {
  return a.size() <= kDotChunk ? a.norm() : std::sqrt(chunkedDot(a, a, threads, partial));
}

// y = y + alpha x, or (with `into`) y = x + alpha y, element by element in fixed ranges.
void axpy(double alpha, const Eigen::VectorXd& x, Eigen::VectorXd& y, int threads, bool into = false) {
  const Eigen::Index n = y.size();
  const int parts = vectorParts(n, threads);
  if (parts == 1) {
    if (into) {
      y = x + alpha * y;
    } else {
      y += alpha * x;
    }
    return;
  }
#pragma omp parallel for num_threads(parts) schedule(static, 1)
  for (int part = 0; part < parts; ++part) {
    const Eigen::Index begin = n * part / parts, end = n * (part + 1) / parts;
    if (into) {
      y.segment(begin, end - begin) = x.segment(begin, end - begin) + alpha * y.segment(begin, end - begin);
    } else {
      y.segment(begin, end - begin) += alpha * x.segment(begin, end - begin);
    }
  }
}

}  // namespace

bool PreconditionedConjugateGradient::hasWholeBlocks(const SystemMatrix::Sparse& A) {
  // Every vertex's three columns: the same length, a multiple of three, rows in runs 3j, 3j+1,
  // 3j+2 (the columns are sorted), and the same rows in all three.
  if (A.rows() != A.cols() || A.cols() % 3 != 0 || !A.isCompressed()) return false;
  const int* outer = A.outerIndexPtr();
  const int* rows = A.innerIndexPtr();
  for (Eigen::Index i = 0; i < A.cols() / 3; ++i) {
    const int length = outer[3 * i + 1] - outer[3 * i];
    if (length % 3 != 0 || outer[3 * i + 2] - outer[3 * i + 1] != length || outer[3 * i + 3] - outer[3 * i + 2] != length)
      return false;
    for (int k = 0; k < length; ++k) {
      const int row = rows[outer[3 * i] + k];
      if (row % 3 != k % 3 || (k % 3 != 0 && row != rows[outer[3 * i] + k - 1] + 1)) return false;
      if (rows[outer[3 * i + 1] + k] != row || rows[outer[3 * i + 2] + k] != row) return false;
    }
  }
  return true;
}

void PreconditionedConjugateGradient::multiply(const SystemMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& outY) {
  // A pattern changes only with its version (SystemMatrix); the storage's address, size and
  // count tell one matrix from another of the same version.
  if (A.patternVersion() != checkedPatternVersion_ || A.matrix().cols() != checkedSize_ ||
      A.matrix().nonZeros() != checkedNonZeros_ || A.matrix().innerIndexPtr() != checkedIndices_) {
    wholeBlocks_ = hasWholeBlocks(A.matrix());
    checkedPatternVersion_ = A.patternVersion();
    checkedSize_ = A.matrix().cols();
    checkedNonZeros_ = A.matrix().nonZeros();
    checkedIndices_ = A.matrix().innerIndexPtr();
  }
  if (!wholeBlocks_) {
    multiplyTransposed(A.matrix(), x, outY, threads_);
    return;
  }
  const Eigen::Index n = A.matrix().cols();
  outY.resize(n);
  const int blocks = static_cast<int>(n / 3);
  const int parts = static_cast<int>(std::clamp<Eigen::Index>(n / kMinimumColumnsPerThread, 1, std::max(threads_, 1)));
  if (parts == 1) {
    blockColumnsProduct(A.matrix(), x, outY, 0, blocks);
    return;
  }
#pragma omp parallel for num_threads(parts) schedule(static, 1)
  for (int part = 0; part < parts; ++part)
    blockColumnsProduct(A.matrix(), x, outY, static_cast<int>(static_cast<long>(blocks) * part / parts),
                        static_cast<int>(static_cast<long>(blocks) * (part + 1) / parts));
}

int PreconditionedConjugateGradient::iterateInTeam(const SystemMatrix& A, double threshold, Preconditioner& preconditioner,
                                                   double rz, Eigen::VectorXd& x, double& residualNorm) {
  // The iterations of solve() below in one parallel region: each thread takes a fixed range of
  // the product's block columns and of the element-wise updates, the dots are the chunked ones
  // (partials over fixed chunks, summed in chunk order by every thread alike, so every thread holds
  // the same scalars and takes the same branches), and the preconditioner is applied by the team
  // (Preconditioner::applyInTeam) or by one of its threads. The same operations on every entry as
  // the loop in solve(), so the same bits. Why: at 64^2 one of these operations takes a few
  // microseconds, about what starting two threads costs on the 2-core machine (docs/solver.md,
  // round 9); barriers cost half of that.
  const Eigen::Index n = x.size();
  const int blocks = static_cast<int>(n / 3);
  const int chunks = chunkCount(n);
  partial_.assign(2 * static_cast<std::size_t>(chunks), 0.0);
  product_.resize(n);
  int iterations = 0;
#pragma omp parallel num_threads(vectorParts(n, threads_))
  {
    const int parts = omp_get_num_threads(), part = omp_get_thread_num();
    const int firstBlock = static_cast<int>(static_cast<long>(blocks) * part / parts);
    const int endBlock = static_cast<int>(static_cast<long>(blocks) * (part + 1) / parts);
    const Eigen::Index begin = n * part / parts, length = n * (part + 1) / parts - begin;
    // a.b as chunkedDot sums it, the chunks shared by the team, into partials at `slot` (two sets,
    // so that one dot's partials are not overwritten while a thread still sums them).
    auto teamDot = [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b, int slot) {
      double* partial = partial_.data() + static_cast<std::size_t>(slot) * chunks;
#pragma omp for schedule(static)
      for (int c = 0; c < chunks; ++c) partial[c] = chunkDot(a, b, c);
      return sumOfChunks(partial, chunks);
    };
    double ownRz = rz, norm = residualNorm;
    int done = 0;
    while (done < maxIterations_) {
      blockColumnsProduct(A.matrix(), direction_, product_, firstBlock, endBlock);
#pragma omp barrier
      const double curvature = teamDot(direction_, product_, 0);
      if (!(curvature > 0.0)) break;  // A (or M) not positive definite along the direction, or NaN
      const double alpha = ownRz / curvature;
      x.segment(begin, length) += alpha * direction_.segment(begin, length);
      residual_.segment(begin, length) += -alpha * product_.segment(begin, length);
#pragma omp barrier
      norm = std::sqrt(teamDot(residual_, residual_, 1));
      ++done;
      if (norm <= threshold) break;
      bool restart = false;
#pragma omp single copyprivate(restart)
      restart = preconditioner.refreshIfStale(A, done);
      preconditioner.applyInTeam(residual_, preconditioned_);
      const double rzNext = teamDot(residual_, preconditioned_, 0);
      if (restart) {
        direction_.segment(begin, length) = preconditioned_.segment(begin, length);
      } else {
        direction_.segment(begin, length) =
            preconditioned_.segment(begin, length) + (rzNext / ownRz) * direction_.segment(begin, length);
      }
      ownRz = rzNext;
#pragma omp barrier
    }
    if (part == 0) {
      iterations = done;
      residualNorm = norm;
    }
  }
  return iterations;
}

LinearSolveResult PreconditionedConjugateGradient::solve(const SystemMatrix& A, const Eigen::VectorXd& b,
                                                        double rhsNormFloor, Preconditioner& preconditioner,
                                                        Eigen::VectorXd& x) {
  // A is symmetric and stored in full, so A = A^T. Eigen multiplies a column-major A^T by a vector
  // as dot products of A's columns with it (reads only); A itself would scatter into the result,
  // whose store-to-load dependencies make it ~1.4x slower. Hence multiply() reads A's columns.
  LinearSolveResult result;
  const double scale = std::max(b.norm(), rhsNormFloor);
  if (!(scale > 0.0)) {  // b = 0 and no floor: the answer is exactly 0 (or b is not finite)
    if (scale == 0.0) x.setZero();
    result.converged = scale == 0.0;
    return result;
  }
  const double threshold = tolerance_ * scale;

  multiply(A, x, residual_);
  residual_ = b - residual_;
  double residualNorm = residual_.norm();
  if (residualNorm > threshold) {
    preconditioner.prepare(A);
    preconditioner.apply(residual_, preconditioned_);
    direction_ = preconditioned_;
    double rz = chunkedDot(residual_, preconditioned_, threads_, partial_);
    // Several threads on a whole-block matrix: the iterations in one parallel region
    // (iterateInTeam), the same operations as below, so the same bits.
    const bool inTeam = wholeBlocks_ && vectorParts(b.size(), threads_) > 1 && b.size() > kDotChunk;
    if (inTeam) result.iterations = iterateInTeam(A, threshold, preconditioner, rz, x, residualNorm);
    while (!inTeam && result.iterations < maxIterations_) {
      multiply(A, direction_, product_);
      const double curvature = chunkedDot(direction_, product_, threads_, partial_);
      if (!(curvature > 0.0)) break;  // A (or M) not positive definite along the direction, or NaN
      const double alpha = rz / curvature;
      axpy(alpha, direction_, x, threads_);
      axpy(-alpha, product_, residual_, threads_);
      ++result.iterations;
      residualNorm = chunkedNorm(residual_, threads_, partial_);
      if (residualNorm <= threshold) break;
      const bool restart = preconditioner.refreshIfStale(A, result.iterations);
      preconditioner.apply(residual_, preconditioned_);
      const double rzNext = chunkedDot(residual_, preconditioned_, threads_, partial_);
      if (restart) {
        direction_ = preconditioned_;
      } else {
        axpy(rzNext / rz, preconditioned_, direction_, threads_, /*into=*/true);
      }
      rz = rzNext;
    }
    preconditioner.solveFinished(result.iterations);
  }
  result.relativeResidual = residualNorm / scale;
  result.converged = residualNorm <= threshold;
  return result;
}

}  // namespace weft
