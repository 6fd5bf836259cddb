#pragma once
// Bending between the two triangles of every interior edge (Bridson, Marino & Fedkiw 2003, as the
// thesis gives it in §2.4, Eq. 2.49-2.58).
//
// Bridson's force F_i = k_e |E|^2/(|N1|+|N2|) sin(theta/2) u_i is, with the coefficient taken at
// rest, minus the gradient of a hinge energy of the dihedral angle theta (the u_i are the gradient
// of theta up to sign), so we evaluate it as such: energy, force = -gradient, and a Hessian.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "material/material.h"
#include "mesh/cloth_mesh.h"

namespace weft {

// One interior edge and its two wings: v[0], v[1] are the edge's endpoints (p3, p4 in the thesis),
// v[2] and v[3] the opposite vertices of its two triangles (p1, p2).
struct BendingHinge {
  int edge = kNone;
  std::array<int, 4> v{kNone, kNone, kNone, kNone};
  double restAngle = 0.0;    // dihedral angle at rest (rad); 0 for a flat rest shape
  double restLength = 0.0;   // rest length of the edge (m)
  double restAreaSum = 0.0;  // A0 + A1, rest areas of the two triangles (m^2)
  double edgeAngle = 0.0;    // direction of the edge in the weft/warp frame, folded into [0, pi/2] (rad)
};

enum class HessianMode {
  None,      // energy and force only
  Exact,     // the true second derivative (may be indefinite), for validation
  Definite,  // positive semi-definite approximation used by the solvers
};

// A symmetric element Hessian over N vertices, kept as its distinct 3x3 vertex blocks: block
// (i, j) for i <= j, row by row; block (j, i) is the transpose of block (i, j).
template <int N>
struct SymmetricBlocks {
  static constexpr int kCount = N * (N + 1) / 2;
  static constexpr int index(int i, int j) { return i * N - i * (i - 1) / 2 + (j - i); }  // needs i <= j

  std::array<Eigen::Matrix3d, kCount> upper;  // left uninitialised until an evaluation asks for a Hessian

  Eigen::Matrix3d& operator()(int i, int j) { return upper[index(i, j)]; }
  const Eigen::Matrix3d& operator()(int i, int j) const { return upper[index(i, j)]; }
  void setZero() {
    for (Eigen::Matrix3d& b : upper) b.setZero();
  }
  // The full 3N x 3N matrix.
  Eigen::Matrix<double, 3 * N, 3 * N> dense() const {
    Eigen::Matrix<double, 3 * N, 3 * N> m;
    for (int i = 0; i < N; ++i) {
      for (int j = i; j < N; ++j) {
        m.template block<3, 3>(3 * i, 3 * j) = (*this)(i, j);
        if (j != i) m.template block<3, 3>(3 * j, 3 * i) = (*this)(i, j).transpose();
      }
    }
    return m;
  }
};

// What one hinge adds to the cloth's sums, in the form the assembly reads: no dense 12x12 matrix,
// and no Hessian at all (not even zeroed) when none was asked for.
struct HingeContribution {
  double energy = 0.0;
  std::array<Eigen::Vector3d, 4> force;  // (f0, f1, f2, f3)
  SymmetricBlocks<4> hessian;            // d^2 energy / dx^2; written only when mode != None
};

struct HingeResult {
  double energy = 0.0;
  Eigen::Matrix<double, 12, 1> force = Eigen::Matrix<double, 12, 1>::Zero();  // (f0, f1, f2, f3)
  Eigen::Matrix<double, 12, 12> hessian = Eigen::Matrix<double, 12, 12>::Zero();  // d^2 energy / dx^2
};

// Builds one hinge per interior edge, from the mesh's rest coordinates and current positions
// (the rest angle is taken as flat unless `restFromCurrent`).
std::vector<BendingHinge> buildBendingHinges(const ClothMesh& mesh, double weftAngleRad, bool restFromCurrent = false);

// The hinge of one edge, as buildBendingHinges makes it; nothing for a border edge or a degenerate
// pair of triangles. Lets a topology change refresh the few hinges it touched.
std::optional<BendingHinge> makeBendingHinge(const ClothMesh& mesh, int edge, double weftAngleRad,
                                             bool restFromCurrent = false);

// Evaluates one hinge at positions x0..x3 (ordered as BendingHinge::v).
HingeResult evaluateHinge(const BendingHinge& hinge, const BendingSettings& settings, const Vec3& x0, const Vec3& x1,
                          const Vec3& x2, const Vec3& x3, HessianMode mode);
// The same evaluation written into `outContribution` (the form the cloth's assembly uses).
void evaluateHinge(const BendingHinge& hinge, const BendingSettings& settings, const Vec3& x0, const Vec3& x1,
                   const Vec3& x2, const Vec3& x3, HessianMode mode, HingeContribution& outContribution);

// True when the material has any bending stiffness (a zero-stiffness cloth runs no bending stage).
bool bendingEnabled(const BendingSettings& settings);

}  // namespace weft
