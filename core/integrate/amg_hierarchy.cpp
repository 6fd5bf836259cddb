#include "integrate/amg_hierarchy.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>  // computeInverseAndDetWithCheck

#include "integrate/amg_aggregation.h"
#include "integrate/amg_patch.h"
#include "integrate/amg_transfer_pattern.h"

namespace weft {
namespace {

Mat3 safeInverse(const Mat3& block) {
  Mat3 inverse;
  bool invertible = false;
  double determinant = 0.0;
  block.computeInverseAndDetWithCheck(inverse, determinant, invertible);
  return invertible && inverse.allFinite() ? inverse : Mat3::Identity();  // cannot happen for an SPD A; stay finite
}

}  // namespace

void AmgHierarchy::build(const BlockSparseMatrix& finest) {
  levels_.clear();
  levels_.emplace_back();
  levels_[0].A = finest;
  computeDiagonal(levels_[0]);
  buildBelow(0);
  factorCoarsest();
}

void AmgHierarchy::buildBelow(int l) {
  levels_.resize(l + 1);
  for (;; ++l) {
    if (levels_[l].A.blockRows <= settings_.coarsestVertices || l + 1 >= settings_.maxLevels) break;
    if (!coarsen(l)) break;
    estimateOmega(levels_[l]);
    smoothProlongator(levels_[l]);
    galerkinProduct(l);
    computeDiagonal(levels_[l + 1]);
  }
}

bool AmgHierarchy::patch(const BlockSparseMatrix& finest, const BlockPattern& previousFinest, int threads,
                         const BlockPattern* previousProduct) {
  if (finestProduct_ != nullptr && previousProduct == nullptr) return false;  // cannot tell what changed
  if (levels_.size() < 2) return false;  // nothing coarsened: a build is as cheap
  levels_[0].A = finest;
  computeDiagonal(levels_[0], threads);
  TransferPatch transfer;
  const BlockPattern* previous = &previousFinest;
  BlockPattern previousCoarse;
  std::vector<int> seeds;
  for (int l = 0;; ++l) {
    const bool large = l == 0 || levels_[l].A.blockRows >= settings_.patchMinimumVertices;
    const bool product = l == 0 && finestProduct_ != nullptr;
    if (l + 1 < levelCount() && large &&
        patchTransfer(levels_[l], levels_[l + 1], *previous, seeds, settings_, transfer, product ? finestProduct_ : nullptr,
                      product ? previousProduct : nullptr)) {
      smoothProlongator(levels_[l], threads);  // omega kept from the build
      galerkinProduct(l, threads);
      computeDiagonal(levels_[l + 1], threads);
      previousCoarse = std::move(transfer.previousCoarse);
      previous = &previousCoarse;
      seeds = std::move(transfer.coarseSeeds);
      continue;
    }
    if (l == 0) return false;
    buildBelow(l);
    break;
  }
  factorCoarsest();
  return true;
}

void AmgHierarchy::refresh(const BlockSparseMatrix& finest, int threads) {
  // Same size: no allocation. By rows on the threads that gathered them (the same static split),
  // so each copies what its own cache holds (a copy on one thread read the other core's half).
  {
    BlockSparseMatrix& A = levels_[0].A;
#pragma omp parallel for num_threads(finest.threadsFor(threads)) schedule(static)
    for (int i = 0; i < A.blockRows; ++i)
      std::copy(finest.blocks.begin() + finest.rowStart[i], finest.blocks.begin() + finest.rowStart[i + 1],
                A.blocks.begin() + A.rowStart[i]);
  }
  for (int l = 0; l + 1 < levelCount(); ++l) {
    computeDiagonal(levels_[l], threads);
    // omega is kept from the build: rho(D^-1 A) hardly moves while the topology holds, and its
    // power iterations would cost as much as three V-cycles per step. Any omega gives a valid P.
    if (settings_.resmoothProlongators) smoothProlongator(levels_[l], threads);
    galerkinProduct(l, threads);
  }
  computeDiagonal(levels_.back());
  factorCoarsest();
}

bool AmgHierarchy::coarsen(int l) {
  Level& fine = levels_[l];
  const BlockSparseMatrix& A = fine.A;
  const int n = A.blockRows;
  std::vector<int> everyVertex(n);
  for (int i = 0; i < n; ++i) everyVertex[i] = i;
  fine.aggregateOf.assign(n, amg::kUnassigned);
  AggregateIds ids({}, 0);
  aggregateFreeVertices(A, settings_.strengthThreshold, everyVertex, fine.aggregateOf, ids);
  const int coarseCount = ids.end();
  if (coarseCount == 0 || coarseCount > settings_.stallRatio * n) {
    fine.aggregateOf.clear();
    return false;
  }
  Level coarse;
  setTransferPattern(fine, coarse, coarseCount, nullptr, nullptr, l == 0 ? finestProduct_ : nullptr);
  levels_.push_back(std::move(coarse));
  return true;
}

void AmgHierarchy::computeDiagonal(Level& level, int threads) {
  const BlockSparseMatrix& A = level.A;
  level.inverseDiagonal.resize(A.blockRows);
#pragma omp parallel for num_threads(A.threadsFor(threads)) schedule(static)
  for (int i = 0; i < A.blockRows; ++i) {
    const int d = A.find(i, i);
    level.inverseDiagonal[i] = d >= 0 ? safeInverse(A.blocks[d]) : Mat3::Identity();
  }
}

void AmgHierarchy::estimateOmega(Level& level) {
  // rho(D^-1 A) by power iteration from a fixed, non-smooth start vector. The estimate is from
  // below; the 1.1 margin keeps omega on the safe side of 4 / (3 rho) (Vanek et al. 1996).
  const BlockSparseMatrix& A = level.A;
  const Eigen::Index size = 3 * static_cast<Eigen::Index>(A.blockRows);
  powerA_.resize(size);
  for (Eigen::Index k = 0; k < size; ++k) powerA_[k] = 1.0 + 0.5 * static_cast<double>((k * 7919) % 13) / 13.0;
  powerA_ /= powerA_.norm();
  double rho = 1.0;
  for (int iteration = 0; iteration < settings_.powerIterations; ++iteration) {
    A.multiply(powerA_, powerB_);
    for (int i = 0; i < A.blockRows; ++i) powerB_.segment<3>(3 * i) = level.inverseDiagonal[i] * powerB_.segment<3>(3 * i);
    const double norm = powerB_.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) break;
    rho = norm;  // |D^-1 A x| with |x| = 1
    powerA_ = powerB_ / norm;
  }
  level.omega = 4.0 / (3.0 * 1.1 * std::max(rho, 1e-12));
}

void AmgHierarchy::smoothProlongator(Level& level, int threads) {
  // P = (I - omega D^-1 A) T: T puts I at (i, aggregateOf[i]). Row i of A writes row i of P only.
  BlockSparseMatrix& P = level.P;
  const BlockSparseMatrix& A = level.A;
#pragma omp parallel for num_threads(A.threadsFor(threads)) schedule(static)
  for (int i = 0; i < A.blockRows; ++i) {
    std::fill(P.blocks.begin() + P.rowStart[i], P.blocks.begin() + P.rowStart[i + 1], Mat3::Zero());
    if (level.tentativeSlots[i] >= 0) P.blocks[level.tentativeSlots[i]] += Mat3::Identity();
    const Mat3 scaledInverse = level.omega * level.inverseDiagonal[i];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
      if (level.smoothingSlots[k] >= 0) P.blocks[level.smoothingSlots[k]].noalias() -= scaledInverse * A.blocks[k];
  }
}

void AmgHierarchy::galerkinProduct(int l, int threads) {
  Level& fine = levels_[l];
  Level& coarse = levels_[l + 1];
  const BlockSparseMatrix& A = l == 0 && finestProduct_ != nullptr ? *finestProduct_ : fine.A;
  const BlockSparseMatrix& P = fine.P;
  BlockSparseMatrix& AP = fine.AP;
  // Row i of A writes row i of A P only: rows in parallel (each zeroed by its thread), each summed
  // in the same order.
#pragma omp parallel for num_threads(A.threadsFor(threads)) schedule(static)
  for (int i = 0; i < A.blockRows; ++i) {
    std::fill(AP.blocks.begin() + AP.rowStart[i], AP.blocks.begin() + AP.rowStart[i + 1], Mat3::Zero());
    const int* slot = fine.productSlots.data() + fine.productStart[i];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      const int j = A.column[k];
      for (int p = P.rowStart[j]; p < P.rowStart[j + 1]; ++p) AP.blocks[*slot++].noalias() += A.blocks[k] * P.blocks[p];
    }
  }
  // P^T (A P) scatters into the coarse rows: block (i, I) of P adds P(i, I)^T (A P)(i, .) to coarse
  // row I. Each thread takes a range of coarse rows and goes through the fine rows in order, adding
  // what falls in its range: every coarse block receives the same terms in the same order as from
  // one thread going through them all.
  BlockSparseMatrix& Ac = coarse.A;
  const int parts = std::min(A.threadsFor(threads), std::max(1, Ac.blockRows));
  galerkinRowStart_.resize(A.blockRows + 1);
  galerkinRowStart_[0] = 0;
  for (int i = 0; i < A.blockRows; ++i)
    galerkinRowStart_[i + 1] =
        galerkinRowStart_[i] + (P.rowStart[i + 1] - P.rowStart[i]) * (AP.rowStart[i + 1] - AP.rowStart[i]);
#pragma omp parallel for num_threads(parts) schedule(static, 1)
  for (int part = 0; part < parts; ++part) {
    const int first = static_cast<int>(static_cast<long>(Ac.blockRows) * part / parts);
    const int end = static_cast<int>(static_cast<long>(Ac.blockRows) * (part + 1) / parts);
    std::fill(Ac.blocks.begin() + Ac.rowStart[first], Ac.blocks.begin() + Ac.rowStart[end], Mat3::Zero());
    for (int i = 0; i < A.blockRows; ++i) {
      const int length = AP.rowStart[i + 1] - AP.rowStart[i];
      const int* slot = fine.galerkinSlots.data() + galerkinRowStart_[i];
      for (int p = P.rowStart[i]; p < P.rowStart[i + 1]; ++p, slot += length) {
        if (P.column[p] < first || P.column[p] >= end) continue;
        const Mat3 transposed = P.blocks[p].transpose();
        for (int w = 0; w < length; ++w) Ac.blocks[slot[w]].noalias() += transposed * AP.blocks[AP.rowStart[i] + w];
      }
    }
  }
  // Symmetrized pair by pair: the pair of slots s <= t is done where s lies (no other touches t),
  // by the same coarse-row ranges, so each thread reads the rows it has just summed.
#pragma omp parallel for num_threads(parts) schedule(static, 1)
  for (int part = 0; part < parts; ++part) {
    const int first = static_cast<int>(static_cast<long>(Ac.blockRows) * part / parts);
    const int end = static_cast<int>(static_cast<long>(Ac.blockRows) * (part + 1) / parts);
    for (int s = Ac.rowStart[first]; s < Ac.rowStart[end]; ++s) {
      const int t = coarse.transposeSlots[s];
      if (t < s) continue;
      const Mat3 symmetric = 0.5 * (Ac.blocks[s] + Ac.blocks[t].transpose());
      Ac.blocks[s] = symmetric;
      Ac.blocks[t] = symmetric.transpose();
    }
  }
}

void AmgHierarchy::factorCoarsest() {
  const BlockSparseMatrix& A = levels_.back().A;
  coarsestFactored_ = false;
  if (A.blockRows > settings_.maxDenseVertices) return;
  // Nothing coarsened at all on a system larger than the coarsest size: no coupling is strong
  // against its diagonal (a step so short that the mass dominates), so the matrix is nearly its
  // block diagonal, which the smoother's sweeps invert. A dense factor would cost O(n^3) per
  // refresh for nothing (measured: a 20² sheet at 300 substeps, 65 s for 4 steps against 0.4 s
  // smoothed).
  if (levels_.size() == 1 && A.blockRows > settings_.coarsestVertices) return;
  const Eigen::Index size = 3 * static_cast<Eigen::Index>(A.blockRows);
  coarsestDense_.setZero(size, size);
  for (int i = 0; i < A.blockRows; ++i)
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) coarsestDense_.block<3, 3>(3 * i, 3 * A.column[k]) = A.blocks[k];
  coarsestFactor_.compute(coarsestDense_);
  coarsestFactored_ = coarsestFactor_.info() == Eigen::Success;
}

double AmgHierarchy::operatorComplexity() const {
  if (levels_.empty() || levels_[0].A.blockCount() == 0) return 0.0;
  double total = 0.0;
  for (const Level& level : levels_) total += level.A.blockCount();
  return total / levels_[0].A.blockCount();
}

}  // namespace weft
