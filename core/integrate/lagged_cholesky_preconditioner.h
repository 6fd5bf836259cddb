#pragma once
// M = a sparse Cholesky factor, from an earlier solve, of the system matrix A or of its
// strong-coupling approximation (strong_coupling_approximation.h), refactored only when it has
// gone stale. M stays SPD, so the CG converges with a stale factor too, only more slowly.
//
// What is factored: by default the strong-coupling approximation, ~4x cheaper to factor than A on
// a 64x64 sheet (bending hinges widen the separators of A). A fresh factor of it leaves the CG
// ~7-10 iterations, against 1 for a fresh factor of A; in motion, where every step refactors, the
// approximation still wins ~3x.
//
// When to refactor:
//   - on the first solve and whenever the matrix pattern changes (a tear or cut);
//   - in the middle of a solve that, with an old factor, reaches the stale limit: the iterations a
//     fresh factor needed last time, plus what a factorization costs in iterations (estimated from
//     the flop counts of the factorization and of one iteration: deterministic, unlike a clock).
//     Beyond that limit refactoring would have been cheaper. The CG restarts with the new factor;
//   - up front, without trying the old factor, for the next `probeInterval` solves after such a
//     mid-solve refactor. The interval doubles (up to kMaxProbeInterval) each time the old factor
//     fails again and drops back to 1 once it succeeds.
// Why the up-front rule: on a moving stiff sheet the matrix changes too much from one step to the
// next (the stiff in-plane directions rotate, triangles go slack or taut) for the previous factor
// to help (a one-step-old exact factor needs 75-600 iterations on a 64x64 sheet), so trying it
// every step would waste the stale limit each time. At rest the factor stays good for many steps.
//
// If a factorization fails (A not numerically positive definite), that solve falls back to block
// Jacobi and the next one factors again.
#include "integrate/block_jacobi_preconditioner.h"
#include "integrate/preconditioner.h"
#include "integrate/sparse_cholesky.h"
#include "integrate/strong_coupling_approximation.h"

namespace weft {

class LaggedCholeskyPreconditioner final : public Preconditioner {
 public:
  enum class Factored { StrongCouplings, WholeMatrix };
  static constexpr int kMaxProbeInterval = 16;
  // Lower bound of the iterations a factorization is taken to cost (guards tiny systems).
  static constexpr int kMinFactorizationCostInIterations = 8;

  explicit LaggedCholeskyPreconditioner(Factored factored = Factored::StrongCouplings) : factored_(factored) {}

  void prepare(const SystemMatrix& A) override;
  void apply(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) override;
  bool refreshIfStale(const SystemMatrix& A, int iterationsThisSolve) override;
  void solveFinished(int iterations) override;
  int factorizations() const override { return factorizations_; }
  // Iterations after which an old factor counts as stale (see above).
  int staleIterationLimit() const { return freshIterations_ + factorizationCostInIterations_; }
  int factorizationCostInIterations() const { return factorizationCostInIterations_; }

 private:
  bool dropsWeakCouplings(const SystemMatrix& A) const;
  void analyze(const SystemMatrix& A);
  void refactor(const SystemMatrix& A);

  Factored factored_;
  SparseCholesky cholesky_;
  StrongCouplingApproximation approximation_;
  BlockJacobiPreconditioner fallback_;
  int analyzedPatternVersion_ = -1;
  Eigen::Index analyzedSize_ = -1;
  int factorizationCostInIterations_ = kMinFactorizationCostInIterations;
  int freshIterations_ = 0;        // iterations of the last solve that started with a fresh factor
  bool startedFresh_ = false;      // this solve started with a factor of its own matrix
  bool factorIsCurrent_ = false;   // the factor is of the matrix of the solve in progress
  bool usingFallback_ = false;
  int upFrontRefactorsLeft_ = 0;
  int probeInterval_ = 1;
  int factorizations_ = 0;
};

}  // namespace weft
