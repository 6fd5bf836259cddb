#include "forces/membrane.h"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace weft {
namespace {

// Sylvester's criterion: a symmetric matrix is positive definite when its leading principal
// minors are positive. A few products, where an eigen-decomposition costs hundreds.
bool isPositiveDefinite(const Mat3& m) {
  if (!(m(0, 0) > 0.0)) return false;
  if (!(m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0) > 0.0)) return false;
  return m.determinant() > 0.0;
}

// Clamps the negative eigenvalues of a symmetric 3x3 matrix to zero. A positive definite matrix
// (the common case: the material tangent of a convex law) is already its own positive part;
// otherwise Eigen's iterative solver, which keeps its accuracy when eigenvalues cluster (the
// closed-form computeDirect does not).
Mat3 positivePart(const Mat3& m) {
  if (isPositiveDefinite(m)) return m;
  Eigen::SelfAdjointEigenSolver<Mat3> eig(m);
  const Vec3 values = eig.eigenvalues().cwiseMax(0.0);
  return eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
}

// Clamps the negative eigenvalues of a symmetric 2x2 matrix [[a, b], [b, c]] to zero, in closed form.
Mat2 positivePart(const Mat2& m) {
  const double a = m(0, 0), b = m(0, 1), c = m(1, 1);
  const double det = a * c - b * b;
  if (det >= 0.0) return a + c >= 0.0 ? m : Mat2::Zero();  // both eigenvalues have the trace's sign
  // One eigenvalue of each sign, mean +- r. The positive part is lambda+ times the projector on
  // its eigenvector, (m - lambda- I) / (lambda+ - lambda-) = (m - lambda- I) / (2r).
  const double half = 0.5 * (a - c);
  const double r = std::sqrt(half * half + b * b);
  const double lambdaPlus = 0.5 * (a + c) + r;
  // The diagonal of m - lambda- I is (r + half, r - half), whose product is b^2: the smaller one
  // is taken as b^2 over the larger, free of cancellation.
  double first, second;
  if (half >= 0.0) {
    first = r + half;
    second = b * b / first;
  } else {
    second = r - half;
    first = b * b / second;
  }
  const double scale = lambdaPlus / (2.0 * r);
  Mat2 out;
  out << scale * first, scale * b, scale * b, scale * second;
  return out;
}

// Minus the sum of two blocks (each possibly transposed), as an exactly symmetric matrix: the
// diagonal block of a Hessian whose block rows sum to zero, from the upper triangle of the sum.
template <bool TransposeFirst, bool TransposeSecond>
void setNegatedSymmetricSum(const Mat3& first, const Mat3& second, Mat3& m) {
  for (int r = 0; r < 3; ++r) {
    for (int c = r; c < 3; ++c) {
      const double a = TransposeFirst ? first(c, r) : first(r, c);
      const double b = TransposeSecond ? second(c, r) : second(r, c);
      m(r, c) = m(c, r) = -(a + b);
    }
  }
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

void evaluateMembrane(const MembraneElement& element, const PreparedElasticity& law, const Vec3& xa, const Vec3& xb,
                      const Vec3& xc, HessianMode mode, MembraneContribution& out) {
  if (element.restArea <= 0.0) {  // degenerate: a finite zero
    out.energy = 0.0;
    out.strain.setZero();
    out.stress.setZero();
    for (Vec3& f : out.force) f.setZero();
    if (mode != HessianMode::None) out.hessian.setZero();
    return;
  }
  // Scalar code below, not Eigen's 3-vectors: their temporaries go through the stack with packet
  // loads of scalar stores, which stall the CPU (store forwarding) for longer than the arithmetic.
  const double ru[3] = {element.ru[0], element.ru[1], element.ru[2]};
  const double rv[3] = {element.rv[0], element.rv[1], element.rv[2]};
  // Deformed weft and warp directions (Eq. 2.26-2.27).
  double U[3], V[3];
  for (int r = 0; r < 3; ++r) {
    U[r] = ru[0] * xa[r] + ru[1] * xb[r] + ru[2] * xc[r];
    V[r] = rv[0] * xa[r] + rv[1] * xb[r] + rv[2] * xc[r];
  }
  // Green strain (Eq. 2.29-2.31); the shear is the engineering shear U.V.
  const double uu = U[0] * U[0] + U[1] * U[1] + U[2] * U[2];
  const double vv = V[0] * V[0] + V[1] * V[1] + V[2] * V[2];
  const double uv = U[0] * V[0] + U[1] * V[1] + U[2] * V[2];
  out.strain = Eigen::Vector3d(0.5 * (uu - 1.0), 0.5 * (vv - 1.0), uv);

  const bool wantTangent = mode != HessianMode::None;
  const ElasticityResponse response = evaluateElasticity(law, out.strain, wantTangent);
  const double area = element.restArea;
  out.energy = area * response.energyDensity;
  out.stress = response.stress;
  const double s[3] = {response.stress[0], response.stress[1], response.stress[2]};

  // The strain's gradient: de_uu/dx_i = r_ui U, de_vv/dx_i = r_vi V, dgamma/dx_i = r_ui V + r_vi U.
  // Nodal forces, Eq. 2.32: F_i = -|d|/2 (s_uu r_ui U + s_vv r_vi V + s_uv (r_ui V + r_vi U)),
  // gathered by direction.
  for (int i = 0; i < 3; ++i) {
    const double alongU = -area * (s[0] * ru[i] + s[2] * rv[i]);
    const double alongV = -area * (s[1] * rv[i] + s[2] * ru[i]);
    for (int r = 0; r < 3; ++r) out.force[i][r] = alongU * U[r] + alongV * V[r];
  }
  if (!wantTangent) return;

  // Jacobian, Eq. 2.33, as the Hessian of the energy: the material term B^T T B plus the
  // geometric (stress) term (r_i^T S r_j) I with S the 2x2 stress tensor [[s_uu, s_uv], [s_uv, s_vv]].
  Mat3 tangent = response.tangent;
  Mat2 S;
  S << s[0], s[2], s[2], s[1];
  if (mode == HessianMode::Definite) {
    // Under compression the stress term (negative principal stress) and, for measured data, the
    // strain-dependence of C can make the Hessian indefinite. We keep the linear systems positive
    // definite by clamping the negative eigenvalues of both the 3x3 material tangent and the 2x2
    // stress tensor: each term is then a sum of PSD pieces, and nothing changes in pure tension
    // with a convex material, where the exact Hessian is already definite.
    tangent = positivePart(tangent);
    S = positivePart(S);
  }
  double T[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) T[r][c] = area * tangent(r, c);
  const double Suu = area * S(0, 0), Suv = area * S(0, 1), Svv = area * S(1, 1);

  // The columns of B for vertex i are B_i = G_i W^T with W = [U V] and G_i = [[r_ui, 0], [0, r_vi],
  // [r_vi, r_ui]] (rows e_uu, e_vv, gamma), so each 3x3 block of B^T T B is W (G_i^T T G_j) W^T:
  // a 2x2 core between U and V instead of a 9x9 product. The geometric term adds (r_i^T S r_j) I.
  double tg[3][3][2];  // T G_j, row by row
  for (int j = 0; j < 3; ++j) {
    for (int r = 0; r < 3; ++r) {
      tg[j][r][0] = ru[j] * T[r][0] + rv[j] * T[r][2];
      tg[j][r][1] = rv[j] * T[r][1] + ru[j] * T[r][2];
    }
  }
  auto setOffDiagonalBlock = [&](int i, int j, Mat3& block) {
    // core = G_i^T T G_j; W core = [first second].
    const double c00 = ru[i] * tg[j][0][0] + rv[i] * tg[j][2][0];
    const double c01 = ru[i] * tg[j][0][1] + rv[i] * tg[j][2][1];
    const double c10 = rv[i] * tg[j][1][0] + ru[i] * tg[j][2][0];
    const double c11 = rv[i] * tg[j][1][1] + ru[i] * tg[j][2][1];
    const double geometric = ru[i] * (Suu * ru[j] + Suv * rv[j]) + rv[i] * (Suv * ru[j] + Svv * rv[j]);
    for (int r = 0; r < 3; ++r) {
      const double first = c00 * U[r] + c10 * V[r];
      const double second = c01 * U[r] + c11 * V[r];
      for (int c = 0; c < 3; ++c) block(r, c) = first * U[c] + second * V[c];
      block(r, r) += geometric;
    }
  };
  // Blocks stored (0,0), (0,1), (0,2), (1,1), (1,2), (2,2).
  std::array<Mat3, 6>& blocks = out.hessian.upper;
  setOffDiagonalBlock(0, 1, blocks[1]);
  setOffDiagonalBlock(0, 2, blocks[2]);
  setOffDiagonalBlock(1, 2, blocks[4]);
  // r_u and r_v each sum to zero over the corners (U and V ignore a translation), so every block
  // row of the Hessian sums to zero: each diagonal block is minus the others in its row.
  setNegatedSymmetricSum<false, false>(blocks[1], blocks[2], blocks[0]);  // -(H01 + H02)
  setNegatedSymmetricSum<true, false>(blocks[1], blocks[4], blocks[3]);   // -(H10 + H12)
  setNegatedSymmetricSum<true, true>(blocks[2], blocks[4], blocks[5]);    // -(H20 + H21)
}

MembraneResult evaluateMembrane(const MembraneElement& element, const ElasticitySettings& elasticity,
                                const Vec3& xa, const Vec3& xb, const Vec3& xc, HessianMode mode) {
  MembraneContribution contribution;
  evaluateMembrane(element, prepareElasticity(elasticity), xa, xb, xc, mode, contribution);
  MembraneResult out;
  out.energy = contribution.energy;
  out.strain = contribution.strain;
  out.stress = contribution.stress;
  for (int i = 0; i < 3; ++i) out.force.segment<3>(3 * i) = contribution.force[i];
  if (mode != HessianMode::None) out.hessian = contribution.hessian.dense();
  return out;
}

}  // namespace weft
