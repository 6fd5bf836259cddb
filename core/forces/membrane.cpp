#include "forces/membrane.h"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace weft {
namespace {

// Clamps the negative eigenvalues of a small symmetric matrix to zero.
template <int N>
Eigen::Matrix<double, N, N> positivePart(const Eigen::Matrix<double, N, N>& m) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eig(m);
  Eigen::Matrix<double, N, 1> values = eig.eigenvalues().cwiseMax(0.0);
  return eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace

MembraneElement makeMembraneElement(const Triangle& triangle, double weftAngleRad) {
  // Rotate the material coordinates into the weft/warp frame: U at weftAngleRad from material x.
  const double c = std::cos(weftAngleRad), s = std::sin(weftAngleRad);
  double u[3], v[3];
  for (int k = 0; k < 3; ++k) {
    const Vec2& p = triangle.rest[k];
    u[k] = c * p.x() + s * p.y();
    v[k] = -s * p.x() + c * p.y();
  }
  MembraneElement e;
  e.v = triangle.v;
  const double d = u[0] * (v[1] - v[2]) + u[1] * (v[2] - v[0]) + u[2] * (v[0] - v[1]);  // Eq. 2.25
  if (!(std::abs(d) > 0.0) || !std::isfinite(d)) return e;  // degenerate: restArea stays 0
  // Eq. 2.19-2.24 (the thesis prints r_uc with a typo; this is the solution of Eq. 2.13-2.18).
  e.ru = Eigen::Vector3d(v[1] - v[2], v[2] - v[0], v[0] - v[1]) / d;
  e.rv = Eigen::Vector3d(u[2] - u[1], u[0] - u[2], u[1] - u[0]) / d;
  e.restArea = 0.5 * std::abs(d);
  return e;
}

MembraneResult evaluateMembrane(const MembraneElement& element, const ElasticitySettings& elasticity,
                                const Vec3& xa, const Vec3& xb, const Vec3& xc, HessianMode mode) {
  MembraneResult out;
  if (element.restArea <= 0.0) return out;
  const Eigen::Vector3d& ru = element.ru;
  const Eigen::Vector3d& rv = element.rv;
  // Deformed weft and warp directions (Eq. 2.26-2.27).
  const Vec3 U = ru[0] * xa + ru[1] * xb + ru[2] * xc;
  const Vec3 V = rv[0] * xa + rv[1] * xb + rv[2] * xc;
  // Green strain (Eq. 2.29-2.31); the shear is the engineering shear U.V.
  out.strain = Eigen::Vector3d(0.5 * (U.dot(U) - 1.0), 0.5 * (V.dot(V) - 1.0), U.dot(V));

  const bool wantTangent = mode != HessianMode::None;
  const ElasticityResponse response = evaluateElasticity(elasticity, out.strain, wantTangent);
  const double area = element.restArea;
  out.energy = area * response.energyDensity;
  out.stress = response.stress;
  const Eigen::Vector3d& s = response.stress;

  // B: rows are d(e_uu, e_vv, gamma)/dx, 3 x 9; de_uu/dx_i = r_ui U, de_vv/dx_i = r_vi V,
  // dgamma/dx_i = r_ui V + r_vi U.
  Eigen::Matrix<double, 3, 9> B;
  for (int i = 0; i < 3; ++i) {
    B.block<1, 3>(0, 3 * i) = ru[i] * U.transpose();
    B.block<1, 3>(1, 3 * i) = rv[i] * V.transpose();
    B.block<1, 3>(2, 3 * i) = (ru[i] * V + rv[i] * U).transpose();
  }
  // Nodal forces, Eq. 2.32: F_j = -|d|/2 (s_uu r_uj U + s_vv r_vj V + s_uv (r_uj V + r_vj U)).
  out.force = -area * B.transpose() * s;
  if (!wantTangent) return out;

  // Jacobian, Eq. 2.33, as the Hessian of the energy: the material term B^T T B plus the
  // geometric (stress) term (r_i^T S r_j) I with S the 2x2 stress tensor [[s_uu, s_uv], [s_uv, s_vv]].
  Eigen::Matrix3d tangent = response.tangent;
  Eigen::Matrix2d S;
  S << s[0], s[2], s[2], s[1];
  if (mode == HessianMode::Definite) {
    // Under compression the stress term (negative principal stress) and, for measured data, the
    // strain-dependence of C can make the Hessian indefinite. We keep the linear systems positive
    // definite by clamping the negative eigenvalues of both the 3x3 material tangent and the 2x2
    // stress tensor: each term is then a sum of PSD pieces, and nothing changes in pure tension
    // with a convex material, where the exact Hessian is already definite.
    tangent = positivePart<3>(tangent);
    S = positivePart<2>(S);
  }
  out.hessian.noalias() = area * B.transpose() * tangent * B;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d ri(ru[i], rv[i]);
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector2d rj(ru[j], rv[j]);
      out.hessian.block<3, 3>(3 * i, 3 * j).diagonal().array() += area * ri.dot(S * rj);
    }
  }
  return out;
}

}  // namespace weft
