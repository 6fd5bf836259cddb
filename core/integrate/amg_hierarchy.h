#pragma once
// A smoothed-aggregation algebraic multigrid hierarchy over 3x3 vertex blocks, after Tamstorf,
// Jones & McCormick 2015, "Smoothed aggregation multigrid for cloth simulation", and Vanek, Mandel
// & Brezina 1996, "Algebraic multigrid by smoothed aggregation for second and fourth order elliptic
// problems":
//   - strength of connection: block (i, j) is strong when |A_ij|_F >= theta sqrt(|A_ii|_F |A_jj|_F);
//   - aggregation (Vanek et al., three passes; amg_aggregation.h): a vertex whose strong neighbours
//     are all free roots an aggregate of itself and them; the rest join a neighbouring aggregate
//     or form new ones.
//     A vertex without strong neighbours (a pinned vertex: its row is the identity) stays out of
//     the coarse space and is left to the smoother, which solves it exactly;
//   - tentative prolongator T: the three translations of each aggregate (T_iJ = I when vertex i is
//     in aggregate J). Only translations: the coarse levels keep 3x3 blocks. The rotations of
//     Tamstorf et al.'s near-null space are not included (see docs/solver.md);
//   - prolongator P = (I - omega D^-1 A) T, omega = 4 / (3 rho(D^-1 A)) (Vanek et al.), D the
//     3x3 block diagonal, rho estimated by a fixed number of power iterations (deterministic) at
//     the build and kept while the topology holds;
//   - Galerkin coarse operator A_c = P^T A P, symmetrized (rounding would otherwise leave it
//     slightly unsymmetric and the V-cycle with it);
//   - coarsest level: a dense Cholesky factorization.
//
// Lazy setup (as in Li et al. 2025, "MGPBD"): build() does everything for a new pattern:
// aggregates, the patterns of P, A P and A_c and the index lists that fill them. refresh() redoes
// only the numbers for new values of the finest matrix in the same pattern: the Galerkin products
// always, the prolongators' smoothing only when asked (they may be kept from the last build while
// the topology holds). Nothing is allocated by refresh(). patch() takes a pattern that changed
// locally (a tear, a cut): it keeps the aggregates and rows away from the change and redoes the
// rest (amg_patch.h), level by level, then the numbers. The patterns and index lists of a
// transfer, whole or in part: amg_transfer_pattern.h.
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "integrate/block_sparse_matrix.h"

namespace weft {

// A block pattern as it stood before a change: a BlockSparseMatrix's rows without values.
struct BlockPattern {
  std::vector<int> rowStart;  // rows + 1 entries
  std::vector<int> column;    // increasing within a row
  int rows() const { return rowStart.empty() ? 0 : static_cast<int>(rowStart.size()) - 1; }
};

struct AmgSettings {
  double strengthThreshold = 0.02;  // theta above (dimensionless)
  int coarsestVertices = 48;        // stop coarsening at or below this many vertices (dense solve)
  int maxDenseVertices = 400;       // a coarsest level larger than this (coarsening stalled) is only smoothed
  double stallRatio = 0.85;         // stop when a level would keep more than this share of the vertices
  int maxLevels = 12;
  int powerIterations = 8;          // for the estimate of rho(D^-1 A) of each level
  bool resmoothProlongators = true;  // refresh() recomputes P from the new A (else P is kept from build(): measured
                                    // 30 -> 40 CG iterations per step over 1 s of the falling 64² sheet)
  // patch(): a level whose patch would aggregate more than this share of its vertices again is
  // built anew instead (a change that is not local; the finest level: the whole hierarchy).
  double patchLimit = 0.25;
  // patch(): coarse levels with fewer vertices than this are built anew below the patched ones
  // (their build is cheap, and it keeps them as a fresh build would make them); the finest level
  // is always patched.
  int patchMinimumVertices = 1000;
};

class AmgHierarchy {
 public:
  struct Level {
    BlockSparseMatrix A;                 // this level's operator
    std::vector<Mat3> inverseDiagonal;   // (A_ii)^-1, for the smoother and the prolongator smoothing
    // Towards the next coarser level (empty on the coarsest):
    std::vector<int> aggregateOf;        // per vertex, its aggregate (= coarse vertex) or -1
    BlockSparseMatrix P;                 // prolongator: rows = this level's vertices, columns = aggregates
    BlockSparseMatrix AP;                // A P, the first half of the Galerkin product
    std::vector<int> tentativeSlots;     // per vertex i: the slot of P(i, aggregateOf[i]) or -1
    std::vector<int> smoothingSlots;     // per block (i, j) of A: the slot of P(i, aggregateOf[j]) or -1
    std::vector<int> productSlots;       // per (block (i, j) of A, block (j, K) of P) in order: slot of AP(i, K)
    std::vector<int> productStart;       // per row i of A: where its entries in productSlots start (n + 1)
    std::vector<int> galerkinSlots;      // per (block (i, I) of P, block (i, K) of AP) in order: slot of A_c(I, K)
    std::vector<int> transposeSlots;     // per block (I, K) of A: the slot of (K, I) (coarse levels: symmetrizing)
    double omega = 0.0;                  // prolongator smoothing weight
    // V-cycle scratch.
    Eigen::VectorXd rhs, solution, residual;
  };

  explicit AmgHierarchy(const AmgSettings& settings = {}) : settings_(settings) {}

  // Builds the hierarchy for `finest` (pattern and values; vertices with an identity row and no
  // couplings are fine).
  void build(const BlockSparseMatrix& finest);
  // Takes the values of `finest`, which must have the pattern build() saw, and redoes the numbers.
  // Row-wise parts over `threads` (same bits for any count).
  void refresh(const BlockSparseMatrix& finest, int threads = 1);
  // Takes `finest` (pattern and values) whose pattern differs from `previousFinest`, the pattern
  // the hierarchy was last built or patched for, by a local change (rows added at the end, blocks
  // added or removed in a few rows): patches the levels from the finest down while they are large
  // (AmgSettings::patchMinimumVertices), builds the smaller ones anew, and redoes the numbers.
  // Returns false, leaving the hierarchy to be built (build()), when there is no coarse level yet
  // or the change is not local (AmgSettings::patchLimit).
  // `previousProduct`: the finest product operator's pattern before the change (needed when one is set).
  bool patch(const BlockSparseMatrix& finest, const BlockPattern& previousFinest, int threads = 1,
             const BlockPattern* previousProduct = nullptr);

  // The operator whose Galerkin product P^T B P makes the first coarse level, in place of the
  // finest level's own (which still decides the aggregates, P and the smoother): A with the
  // couplings the finest operator approximates away. Same rows and values kept up to date by the
  // caller (it must outlive the hierarchy's next build or refresh). nullptr: the finest's own.
  void setFinestProductOperator(const BlockSparseMatrix* operatorB) { finestProduct_ = operatorB; }
  int levelCount() const { return static_cast<int>(levels_.size()); }
  const Level& level(int l) const { return levels_[l]; }
  Level& level(int l) { return levels_[l]; }
  // The coarsest level's factorization succeeded (else the V-cycle skips the coarse correction).
  bool coarsestFactored() const { return coarsestFactored_; }
  const Eigen::LLT<Eigen::MatrixXd>& coarsestFactor() const { return coarsestFactor_; }
  // Operator complexity: stored blocks of all levels / of the finest.
  double operatorComplexity() const;

 private:
  bool coarsen(int l);           // symbolic setup of level l -> l + 1 (aggregates, patterns, slots); false: stop here
  void buildBelow(int l);        // builds the levels below l anew (level l's operator and diagonal are set)
  void computeDiagonal(Level& level, int threads = 1);
  void estimateOmega(Level& level);
  void smoothProlongator(Level& level, int threads = 1);
  void galerkinProduct(int l, int threads = 1);   // numeric: AP and A_c of level l + 1
  void factorCoarsest();

  AmgSettings settings_;
  const BlockSparseMatrix* finestProduct_ = nullptr;
  std::vector<int> galerkinRowStart_;  // galerkinProduct's scratch: per fine row, its first galerkinSlots entry
  std::vector<Level> levels_;
  Eigen::MatrixXd coarsestDense_;
  Eigen::LLT<Eigen::MatrixXd> coarsestFactor_;
  bool coarsestFactored_ = false;
  std::vector<int> symmetricSlots_;  // scratch of galerkinProduct
  Eigen::VectorXd powerA_, powerB_;
};

}  // namespace weft
