#pragma once
// M^-1 = one V-cycle of the smoothed-aggregation multigrid hierarchy (amg_hierarchy.h) of the
// system matrix's strong couplings: a preconditioner whose setup and application cost grows
// linearly with the vertex count, unlike a sparse Cholesky factor (n^1.5 on a sheet).
//
// What the V-cycle approximates: like the lagged Cholesky preconditioner, the strong-coupling
// approximation of A (strong_coupling_approximation.h: the bending hinges' wing couplings dropped
// and made up for on the diagonal, M >= A): a 7-block stencil instead of 13 keeps the Galerkin
// products and the sweeps cheap.
//
// Why PCG stays valid: the cycle is symmetric (block Gauss-Seidel forward before the coarse
// correction, backward after it; a symmetrized Galerkin operator on every level; an exact dense
// Cholesky solve on the coarsest), and with a convergent smoother and SPD coarse operators it is
// positive definite. Pinned vertices have identity rows and no couplings in A (see
// SystemMatrix::constrainVertices): they stay out of the coarse spaces and the smoother solves
// them exactly, so the constraints are filtered as the CG's matrix filters them.
//
// Lazy setup: the aggregates and the patterns and index lists of every level are built at the
// first solve; every other solve only gathers the new values and redoes the numbers (prolongator
// smoothing, Galerkin products, coarsest factor). A pattern change (a tear or a cut) patches the
// hierarchy around the change (amg_patch.h) instead of building it anew, which cost a few steps'
// numeric setup (docs/solver.md); a change too large to be local is built anew.
//
// Deterministic: a fixed order of operations; the row-wise parts use solver.threads (fixed row
// ranges, each row computed alike), and the result does not depend on the thread count.
#include <algorithm>
#include <vector>

#include "integrate/amg_float_cycle.h"
#include "integrate/amg_hierarchy.h"
#include "integrate/block_sparse_matrix.h"
#include "integrate/preconditioner.h"
#include "integrate/strong_coupling_approximation.h"

namespace weft {

class AmgPreconditioner final : public Preconditioner {
 public:
  struct Settings {
    AmgSettings hierarchy;
    int smoothingSweeps = 1;  // block Gauss-Seidel sweeps before and after each coarse correction
    bool singlePrecisionCycle = true;  // the V-cycle in float (amg_float_cycle.h); the setup stays in double
    bool patchAfterPatternChange = true;  // a pattern change patches the hierarchy (else: built anew)
    // The first coarse level's Galerkin product takes A itself, the bending hinges' wing couplings
    // included, when their share of A's off-diagonal block norms is at least this at a build (the
    // aggregates, P and the finest sweeps stay on the approximation). On finer meshes bending grows
    // against the membrane and the coarse level built without the wings loses the bending modes
    // (docs/solver.md, "Why the iterations double at 256²": 52 -> 36 CG iterations at 256²).
    double wingShareThreshold = 0.0008;
    // The float cycle sweeps a level of at least this many rows in two groups that two threads
    // take side by side (amg_float_cycle.h); smaller levels in their rows' own order. The same
    // bits on any thread count either way; 0: never split.
    int splitSweepRows = AmgFloatCycle::kDefaultSplitRows;
  };

  AmgPreconditioner() : AmgPreconditioner(Settings{}) {}
  explicit AmgPreconditioner(const Settings& settings) : settings_(settings), hierarchy_(settings.hierarchy) {}

  void prepare(const SystemMatrix& A) override;
  void apply(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) override;
  // The float cycle's passes shared by the team (AmgFloatCycle::applyInTeam), once prepared.
  void applyInTeam(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) override;
  // The row-wise parts (products, residuals, prolongator smoothing, A P) split their rows over the
  // threads in fixed ranges; the Gauss-Seidel sweeps and the scatters (restriction, P^T (A P)) stay
  // on one thread. Every row is computed by the same code in the same order: the same bits.
  void setThreads(int threads) override { threads_ = std::max(threads, 1); }

  // Full (symbolic) setups so far: the first, and pattern changes that could not be patched.
  int fullSetups() const { return fullSetups_; }
  // Pattern changes met by patching the hierarchy (AmgHierarchy::patch).
  int patchedSetups() const { return patchedSetups_; }
  // The wings are in the first coarse level's Galerkin product (Settings::wingShareThreshold).
  bool wingsInGalerkinProduct() const { return wings_; }
  const AmgHierarchy& hierarchy() const { return hierarchy_; }

 private:
  void analyze(const SystemMatrix& A);
  void gather(const SystemMatrix& A);
  // A's values, every block, into whole_, measuring wingShare_ (each step while wings_; before a build).
  void gatherWhole(const SystemMatrix& A);
  void cycle(int l, const Eigen::VectorXd& b, Eigen::VectorXd& x);

  Settings settings_;
  AmgHierarchy hierarchy_;
  AmgFloatCycle floatCycle_;
  BlockSparseMatrix finest_;
  // A itself, every block: the first coarse level's Galerkin operator when wings_. Its values are
  // held only while wings_ or until a build has measured the wings' share (gatherWhole).
  BlockSparseMatrix whole_;
  bool wings_ = false;       // the wings enter the first Galerkin product (Settings::wingShareThreshold)
  double wingShare_ = 0.0;   // their share of the off-diagonal block norms, at the last gather that measured it
  // Per block of A in its storage order (column block by column block): its slot in finest_, or
  // one of these for a dropped (weak) pair.
  static constexpr int kDroppedFirstSeen = -1;   // block (j, i) of column block i, j < i: compensated here
  static constexpr int kDroppedSecondSeen = -2;  // its mirror (j > i): skipped
  std::vector<int> blockCode_;
  std::vector<int> diagonalSlot_;   // per vertex: slot of (i, i) in finest_
  std::vector<Mat3> compensation_;  // per vertex: the dropped pairs' sum for its diagonal block
  // With several threads (gather): per vertex, where its column block starts in blockCode_ and its
  // first dropped pair (j, i), j < i, in the pair buffers; per pair, j and its share for j.
  std::vector<int> codeStart_, droppedStart_;
  std::vector<int> droppedFor_;
  std::vector<Mat3> droppedShare_;
  int analyzedPatternVersion_ = -1;
  Eigen::Index analyzedSize_ = -1;
  int fullSetups_ = 0;
  int patchedSetups_ = 0;
  int threads_ = 1;
};

}  // namespace weft
