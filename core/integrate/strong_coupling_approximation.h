#pragma once
// M: the system matrix A without its weak couplings (SystemMatrix::weakPairs(): the wing vertices
// of bending hinges), for a preconditioner to factor. Why: those couplings join vertices two apart
// across the mesh, so they widen the separators of the nested-dissection ordering; dropping them
// cuts the Cholesky fill ~2.6x and the factorization flops ~5x (64x64 sheet), while the
// preconditioned CG needs ~7-10 iterations instead of 1 with the exact factor.
//
// Each dropped pair of blocks B = A_ij = A_ji^T is made up for on the diagonal blocks:
//   A_ii += B B^T / s + t I,   A_jj += B^T B / s + t I,   s = |B|_F,  t >= sqrt(s^2 - s1^2),
// s1 the largest singular value of B. Then D = [[A_ii-part, -B], [-B^T, A_jj-part]] is positive
// semidefinite: in B's singular bases that needs s_k <= s_k^2 / s + t for every singular value, and
// t >= sqrt(s^2 - s1^2) covers both s1 and the others. So M - A (a sum of such D) is too, M >= A > 0:
// M is always factorizable and the CG converges. A bending block is nearly rank one (t ~ 0), and
// then this is the tightest such compensation (s I on both diagonals, the simple bound, leaves the
// CG ~12-13 iterations instead of ~7-10). s1^2 is bounded from below by a few power iterations on
// B^T B, which only makes t larger: still safe.
//
// The pattern and the index maps are built once per pattern: refilling allocates nothing.
#include <vector>

#include "integrate/system_matrix.h"

namespace weft {

// What the diagonal blocks get for one dropped pair B = A_ij (the formula above): outForI is added
// to A_ii, outForJ to A_jj. False (nothing to add) when B = 0.
bool strongCouplingCompensation(const Mat3& B, Mat3& outForI, Mat3& outForJ);
// The same bound with two divisions and two square roots instead of ~30 and 6 (the power
// iterations run on B^T B / s^2, whose entries are at most 1 and largest eigenvalue at least 1/3,
// unnormalized; the Rayleigh quotient does not depend on the iterate's length). Rounds
// differently, so the lagged Cholesky, whose results the goldens hold, keeps the function above;
// the multigrid uses this one.
bool strongCouplingCompensationFast(const Mat3& B, Mat3& outForI, Mat3& outForJ);

class StrongCouplingApproximation {
 public:
  // Builds M's pattern and the maps from A's storage. Call when A's pattern changed.
  void setPattern(const SystemMatrix& A);
  // M's values from A's current values.
  void refill(const SystemMatrix& A);
  const SystemMatrix::Sparse& matrix() const { return approximation_; }

 private:
  SystemMatrix::Sparse approximation_;
  std::vector<int> sourceOffsets_;          // for each entry of M, the offset of the same entry in A
  std::vector<int> droppedColumnOffsets_;   // 3 per weak pair: offset of entry (3i, 3j + c) in A, c = 0..2
  std::vector<int> compensatedColumns_;     // 6 per weak pair: offsets of (3i, 3i + c), then (3j, 3j + c), in M
};

}  // namespace weft
