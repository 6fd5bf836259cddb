#pragma once
// The multigrid V-cycle of AmgPreconditioner in single precision: each level's operator,
// prolongator and restriction copied into float blocks after every numeric setup (which stays in
// double), the cycle's vectors in float, the coarsest level's dense solve in double.
//
// Why: the cycle streams every level's blocks four times per CG iteration (two sweeps, the
// restriction, the prolongation) and is bound by those bytes, not by its arithmetic (a 64² sheet's
// levels are ~4 MB of double blocks, more than the caches hold). Float halves them, and the padded
// columns turn a block's 18 scalar operations into 6 vector ones: one cycle at 64² went from
// 0.34 to 0.18 ms, the CG iterations unchanged (26 to 1e-6, also to 1e-8 .. 1e-12). A
// preconditioner only has to be a fixed symmetric positive definite operator, not an exact one:
// the CG's own products, vectors and stopping test stay in double, so the answer's accuracy is
// unchanged, and rounding in the cycle (relative 6e-8) only perturbs M^-1 far below what one
// V-cycle leaves unresolved anyway (mixed-precision multigrid preconditioning, e.g. Goeddeke,
// Strzodka & Turek 2007, "Performance and accuracy of hardware-oriented native-, emulated- and
// mixed-precision solvers in FEM simulations"). Measured iterations: docs/solver.md.
//
// Layout: a 3x3 block is three padded columns of four floats (48 bytes instead of 72), a vertex's
// vector entry four floats, so a block times a vector is three broadcasts, three multiplies and
// two adds of 4-wide vectors (GCC's vector extensions: SSE on x86-64, plain scalar code where
// there is none; either way each lane is one IEEE float operation, so the bits do not depend on
// the target's vector width). The diagonal blocks are left out of the copy (the smoother applies
// their inverses instead). P^T is stored as its own block rows so that the restriction gathers
// instead of scattering: rows in parallel, each summed in the same order for any thread count.
#include <vector>

#include <Eigen/Core>

#include "integrate/amg_hierarchy.h"

namespace weft {

class AmgFloatCycle {
 public:
  using Float4 = float __attribute__((vector_size(16)));

  // A level this large has its sweeps split in two groups (Level). One thread does the same work
  // either way, but the order differs from the rows' own, and so do the results' last bits: this
  // keeps every level of the shipped scenes (up to 1,600 vertices) in the rows' own order, their
  // results unchanged; from 64² on (4,096 rows) two threads share the finest sweeps. (Splitting the
  // coarse levels of a few hundred rows too was measured to move the 64² ball's crack growth past
  // its test's 10% band: docs/solver.md, round 8.)
  static constexpr int kDefaultSplitRows = 2048;

  // Patterns of every level (after AmgHierarchy::build); levels of at least `splitRows` rows are
  // swept in two groups (0: none).
  void build(const AmgHierarchy& hierarchy, int splitRows = kDefaultSplitRows);
  // Values of every level (after AmgHierarchy::build or refresh). Row-wise over `threads`.
  void refresh(const AmgHierarchy& hierarchy, int threads);
  // outZ = one V-cycle applied to inR (both double): `sweeps` block Gauss-Seidel sweeps forward
  // before each coarse correction and backward after it.
  void apply(const AmgHierarchy& hierarchy, const Eigen::VectorXd& inR, Eigen::VectorXd& outZ, int sweeps, int threads);
  // The same cycle, called by every thread of an enclosing parallel region (apply opens one of
  // `threads` for it): its row-wise passes and the two groups of a split sweep are shared among
  // them, a level too small to share (and the levels below it) runs on one of them, and each pass
  // ends with a barrier, so it returns on every thread with outZ complete. Barriers instead of a
  // parallel region per pass (on the 2-core machine a fork and join costs ~3 µs, a barrier
  // ~1.5 µs, a pass at 64^2 10-20 µs).
  void applyInTeam(const AmgHierarchy& hierarchy, const Eigen::VectorXd& inR, Eigen::VectorXd& outZ, int sweeps);
  bool built() const { return !levels_.empty(); }

 private:
  struct Level {
    int rows = 0;
    // The Gauss-Seidel sweeps' row order. split == 0: rows in increasing order. Otherwise (a level
    // large enough for two threads, amg_float_cycle.cpp) three groups, each in increasing order: the rows below
    // `split`, then `secondGroup` (rows from `split` on that touch no row below it), then
    // `interfaceRows` (the others). No row of the first group is coupled to one of the second, so
    // two threads sweep those side by side, and the interface after them, exactly as one thread
    // sweeping the whole order: the result does not depend on the thread count.
    int split = 0;
    std::vector<int> secondGroup, interfaceRows;
    // Off-diagonal blocks of A by rows: offStart[i] .. offStart[i+1]-1, the blocks of rows that
    // come before row i in the sweep order first (columns increasing within each group);
    // laterStart[i] is the first block of a row that comes after it.
    std::vector<int> offStart, laterStart, offColumn, offSource;  // offSource: the block's slot in the level's A
    std::vector<int> diagonalSource;                             // slot of A_ii, or -1
    std::vector<Float4> off;                                     // 3 per block: its columns
    std::vector<Float4> inverseDiagonal;                         // 3 per vertex
    std::vector<Float4> diagonal;                                // 3 per vertex (residuals after several sweeps)
    // Towards the next coarser level (empty on the coarsest): P's blocks in P's own pattern, and
    // P^T by coarse rows with each block's slot in P.
    std::vector<Float4> p;
    std::vector<int> transposeStart, transposeColumn, transposeSource;
    std::vector<Float4> pt;
    std::vector<Float4> b, x, r;
  };

  // apply's body: every pass shared by the calling team, or all of it on the calling thread.
  void applyWith(const AmgHierarchy& hierarchy, const Eigen::VectorXd& inR, Eigen::VectorXd& outZ, int sweeps,
                 bool shared);
  // One V-cycle from level l down. `shared`: called by every thread of a team, which shares its
  // row-wise passes and the two groups of a split sweep (omp for; a level too small to share, and
  // those below it, on one thread: omp single), each pass ending in a barrier; otherwise plain
  // loops on the calling thread. The same operations on every row either way, so the same bits.
  void cycle(const AmgHierarchy& hierarchy, int l, int sweeps, bool shared);
  // `row(i)` for every row of the level in its sweep order (forward) or in reverse (backward), the
  // first two groups on two threads of the team when there are.
  template <typename Row>
  static void sweepForward(const Level& level, bool shared, const Row& row);
  template <typename Row>
  static void sweepBackward(const Level& level, bool shared, const Row& row);
  template <typename Body>
  static void forRows(bool shared, int rows, const Body& body);
  template <typename Body>
  static void once(bool shared, const Body& body);

  std::vector<Level> levels_;
  Eigen::VectorXd coarsestRhs_, coarsestSolution_;
};

}  // namespace weft
