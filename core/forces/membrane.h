#pragma once
// The triangle membrane element of the thesis (§2.2, Eq. 2.13-2.33).
#include <array>

#include <Eigen/Core>

#include "forces/bending.h"  // HessianMode
#include "material/elasticity.h"
#include "mesh/cloth_mesh.h"

namespace weft {

// Precomputed rest data of one triangle: the weights r_u, r_v (Eq. 2.19-2.25) with which the
// deformed weft and warp directions are U = sum r_ui P_i and V = sum r_vi P_i (Eq. 2.26-2.27).
// Each sums to zero over the corners (U and V ignore a translation); the Hessian relies on it.
struct MembraneElement {
  std::array<int, 3> v{kNone, kNone, kNone};
  Eigen::Vector3d ru = Eigen::Vector3d::Zero();
  Eigen::Vector3d rv = Eigen::Vector3d::Zero();
  double restArea = 0.0;  // |d|/2 (m^2)
};

struct MembraneResult {
  double energy = 0.0;
  Eigen::Vector3d strain = Eigen::Vector3d::Zero();  // (e_uu, e_vv, gamma_uv)
  Eigen::Vector3d stress = Eigen::Vector3d::Zero();  // (s_uu, s_vv, s_uv) N/m
  Eigen::Matrix<double, 9, 1> force = Eigen::Matrix<double, 9, 1>::Zero();
  Eigen::Matrix<double, 9, 9> hessian = Eigen::Matrix<double, 9, 9>::Zero();  // d^2 energy / dx^2
};

// What one triangle adds to the cloth's sums, in the form the assembly reads: the Hessian as its
// six distinct 3x3 blocks, and not written at all (not even zeroed) when none was asked for.
struct MembraneContribution {
  double energy = 0.0;
  Eigen::Vector3d strain = Eigen::Vector3d::Zero();  // (e_uu, e_vv, gamma_uv)
  Eigen::Vector3d stress = Eigen::Vector3d::Zero();  // (s_uu, s_vv, s_uv) N/m
  std::array<Eigen::Vector3d, 3> force;
  SymmetricBlocks<3> hessian;  // d^2 energy / dx^2; written only when mode != None
};

// r_u, r_v of a triangle whose corners are rotated into the weft/warp frame (U at weftAngleRad
// from material x). Returns restArea == 0 for a degenerate triangle.
MembraneElement makeMembraneElement(const Triangle& triangle, double weftAngleRad);

MembraneResult evaluateMembrane(const MembraneElement& element, const ElasticitySettings& elasticity,
                                const Vec3& xa, const Vec3& xb, const Vec3& xc, HessianMode mode);
// The same evaluation with the law prepared once for many triangles, written into `outContribution`
// (the form the cloth's assembly uses).
void evaluateMembrane(const MembraneElement& element, const PreparedElasticity& law, const Vec3& xa, const Vec3& xb,
                      const Vec3& xc, HessianMode mode, MembraneContribution& outContribution);

}  // namespace weft
