// Membrane constitutive law: isotropic St. Venant-Kirchhoff (thesis Eq. 2.11) and the measured
// fabrics of Wang, Ramamoorthi & O'Brien 2011 (thesis §2.5, Eq. 2.59-2.60; data layout in
// shared/data/wang2011/FORMAT.md).
//
// ---- Measured model: decisions ------------------------------------------------------------------
// 1. File coefficients (c11, c12, c22, c33) act on e = (e_uu, e_vv, g), g = U.V the engineering
//    shear, through C = [[2c11, 2c12, 0], [2c12, 2c22, 0], [0, 0, c33]]. ARCSim tabulates k = 2c,
//    and the force routine its integrator runs carries 2*c33*E_uv^2 per area with E_uv = g/2, i.e.
//    1/2*c33*g^2: we follow the dynamics the data was fitted with. The data's axis u (c11) is Weft's
//    U (weft) direction.
// 2. Every sample is clamped at 0 before use (as the thesis does for Table 4.14; ARCSim clamps after
//    interpolating). Then c12 is limited to 0.95*sqrt(c11*c22): a stability guard so that C stays
//    positive definite for data with c12^2 >= c11*c22 (navy-sparkle-sweat, 22.5 deg row). The set
//    of samples obeying both limits is a convex cone, so every blend below stays inside it.
// 3. C(e) = (1-s)*C0 + s*[w*L(t) + (1-w)*Lavg], with
//      lambda = sqrt(largest eigenvalue of 2G+I)      the largest principal stretch,
//      s = clamp((lambda-1)/(referenceStretch-1), 0, 1),
//      t = |phi| / 22.5 deg in [0, 4]                 phi in (-90, 90] the angle of lambda's
//                                                     eigenvector from U, folded by the fabric's
//                                                     mirror symmetry (ARCSim clamps instead),
//      L(t)                                           rows 1-5 interpolated linearly in t,
//      Lavg = mean of L over [0, 90] deg              trapezoid weights 1/8, 1/4, 1/4, 1/4, 1/8,
//      w = smoothstep(d/delta), delta = 0.01          d the half eigen-gap of 2G+I.
//    At an equibiaxial strain the principal direction is undefined and C would jump there; w fades
//    the direction dependence out as d -> 0, and w*dt/de stays bounded (w ~ d^2, dt/de ~ 1/d).
// 4. psi = 1/2 e^T C(e) e and the stress and tangent are its exact derivatives (C varies with e).
//
// ---- Derivation ---------------------------------------------------------------------------------
// Work in (h, b, m) = (e_uu - e_vv, g, 1 + e_uu + e_vv), a linear map of e: (h, b, m) = J e + (0,0,1)
// with J = [[1,-1,0], [0,0,1], [1,1,0]]. Then 2G+I = [[m+h, b], [b, m-h]] and
//      d = sqrt(h^2 + b^2),  mu = m + d,  lambda = sqrt(mu),  phi = 1/2 atan2(b, h).
// Gradients and Hessians in (h, b, m), with n = (h, b)/d and P = I - n n^T on the (h, b) block:
//      grad d = (n, 0)                       hess d = P/d
//      grad mu = (n, 1)                      hess mu = hess d
//      grad lambda = grad mu/(2 lambda)      hess lambda = hess mu/(2 lambda) - grad mu grad mu^T/(4 lambda^3)
//      s = (lambda-1)/r, r = referenceStretch-1:  grad s = grad lambda/r, hess s = hess lambda/r
//      t = k atan2(|b|, h), k = 4/pi, y = |b|, sigma = sign(b):
//          grad t = k (-y, sigma h, 0)/d^2
//          t_hh = 2k h y/d^4,  t_bb = -2k h y/d^4,  t_hb = k sigma (y^2 - h^2)/d^4
//      w = 3x^2 - 2x^3, x = d/delta:  w' = 6x(1-x)/delta,  w'' = (6-12x)/delta^2
//          grad w = w' grad d,  hess w = w'' n n^T + w' hess d
// A clamped coordinate (s at 0 or 1, w at 1) has zero derivatives. With q = (s, t, w):
//      C_s = w L + (1-w) Lavg - C0,  C_t = s w L',  C_w = s (L - Lavg)
//      C_st = w L',  C_sw = L - Lavg,  C_tw = s L',  C_ss = C_tt = C_ww = 0 (L is piecewise linear)
//      P_j = 1/2 e^T C_j e,  P_jk = 1/2 e^T C_jk e,  grad_e q = J^T grad_hbm q,  hess_e q = J^T hess J
//      stress  = C e + sum_j P_j grad q_j
//      tangent = C + sum_j [(C_j e) grad q_j^T + grad q_j (C_j e)^T] + sum_j P_j hess q_j
//                  + sum_{j != k} P_jk grad q_j grad q_k^T
// Remaining non-smooth places, all of measure zero: the fold at 0 and 90 deg (b = 0), the rows'
// knots in t and the clamps of s (the cone of lambda on the equibiaxial line d = 0 is rounded
// off for s, see interpolationCoordinates). Below d = kTinyGap the
// angle is undefined: w = 0, and the d-dependent derivatives are dropped (their subgradient mean).
#include "material/elasticity.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/Dense>

#include "util/types.h"

namespace weft {
namespace {

// (c11, c12, c22, c33) in N/m, as in the data files; linear combinations of samples stay here.
using Coefficients = Eigen::Vector4d;

constexpr double kEquibiaxialBlend = 0.01;  // delta: eigen-gap over which the direction fades in
constexpr double kStretchRounding = 1e-3;   // eigen-gap below which lambda's cone is rounded off for s
constexpr double kTinyGap = 1e-12;          // below this half eigen-gap the principal direction is undefined
constexpr double kCouplingLimit = 0.95;     // c12 <= 0.95 sqrt(c11 c22) keeps C positive definite

// ---- Coefficients and the matrix they stand for -------------------------------------------------

// Decision 2: clamp at zero, then limit the coupling.
Coefficients usableSample(const StretchCoefficients& raw) {
  Coefficients c(std::max(raw[0], 0.0), std::max(raw[1], 0.0), std::max(raw[2], 0.0), std::max(raw[3], 0.0));
  c[1] = std::min(c[1], kCouplingLimit * std::sqrt(c[0] * c[2]));
  return c;
}

// Decision 1: C = [[2c11, 2c12, 0], [2c12, 2c22, 0], [0, 0, c33]].
Mat3 toMatrix(const Coefficients& c) {
  Mat3 m;
  m << 2 * c[0], 2 * c[1], 0, 2 * c[1], 2 * c[2], 0, 0, 0, c[3];
  return m;
}

Vec3 apply(const Coefficients& c, const Vec3& e) {
  return Vec3(2 * (c[0] * e[0] + c[1] * e[1]), 2 * (c[1] * e[0] + c[2] * e[1]), c[3] * e[2]);
}

// 1/2 e^T C e.
double halfQuadratic(const Coefficients& c, const Vec3& e) {
  return c[0] * e[0] * e[0] + 2 * c[1] * e[0] * e[1] + c[2] * e[1] * e[1] + 0.5 * c[3] * e[2] * e[2];
}

// Eq. 2.11: E = Eh/(1-nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1-nu)/2]], stiffnessScale applied.
Mat3 isotropicMatrix(const ElasticitySettings& settings) {
  const double nu = settings.poissonRatio;
  const double factor = settings.stiffnessScale * settings.youngModulus / (1.0 - nu * nu);
  Mat3 e;
  e << 1, nu, 0, nu, 1, 0, 0, 0, 0.5 * (1.0 - nu);
  return factor * e;
}

// ---- The interpolation coordinates q = (s, t, w) as functions of the strain -------------------
//
// This runs for every triangle at every step, so it is written with plain doubles: Eigen evaluates
// its 3-vectors as a 2-wide packet plus a scalar, and reloading a temporary stored as scalars
// with packets stalls the CPU (failed store forwarding) for longer than the arithmetic takes.

// Value, gradient and Hessian of one coordinate with respect to (h, b, m). A coordinate held at a
// clamp, or undefined, has zero derivatives: `varies` is false and grad and hess are not set.
struct Coordinate {
  double value = 0.0;
  bool varies = false;
  double grad[3];
  double hess[3][3];  // symmetric, both triangles set
};

struct InterpolationCoordinates {
  Coordinate stretch;    // s in [0, 1]
  Coordinate angle;      // t in [0, 4], units of 22.5 deg
  Coordinate direction;  // w in [0, 1], weight of the direction-dependent rows
};

// order 0: values only; 1: and gradients; 2: and Hessians.
InterpolationCoordinates interpolationCoordinates(const Vec3& e, double referenceStretch, int order) {
  const double h = e[0] - e[1];
  const double b = e[2];
  const double m = 1.0 + e[0] + e[1];
  const double d = std::sqrt(h * h + b * b);  // strains are O(1): no overflow to guard against
  const bool hasDirection = d > kTinyGap;

  // d and its derivatives on the (h, b) block (the m row and column are zero); zero (the
  // subgradient mean) at the cone tip.
  double gradD[2] = {0.0, 0.0};
  double hessD[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  // (Divisions are written as products with one reciprocal: a division costs several products.)
  const double inverseD = hasDirection ? 1.0 / d : 0.0;
  if (hasDirection && order >= 1) {
    gradD[0] = h * inverseD;
    gradD[1] = b * inverseD;
    if (order >= 2) {
      const double inverseD3 = inverseD * inverseD * inverseD;
      hessD[0][0] = b * b * inverseD3;
      hessD[1][1] = h * h * inverseD3;
      hessD[0][1] = hessD[1][0] = -h * b * inverseD3;
    }
  }

  InterpolationCoordinates q;

  // s from the largest principal stretch lambda = sqrt(m + d). lambda has a cone on the
  // equibiaxial line d = 0 (its tangent grows like 1/d), so for s alone d is replaced below
  // r = kStretchRounding by the cubic d~ = 2 d^2/r - d^3/r^2: C1 at d = r, zero with zero slope at
  // d = 0 (so s stays 0 at rest) and smooth in (h, b), which keeps the tangent bounded.
  double roundedD = d;
  double gradRoundedD[2] = {gradD[0], gradD[1]};
  double hessRoundedD[2][2] = {{hessD[0][0], hessD[0][1]}, {hessD[1][0], hessD[1][1]}};
  if (d < kStretchRounding) {
    const double r = kStretchRounding;
    roundedD = 2.0 * d * d / r - d * d * d / (r * r);
    const double f = 4.0 / r - 3.0 * d / (r * r);  // d~ = f-weighted: grad d~ = f (h, b)
    gradRoundedD[0] = f * h;
    gradRoundedD[1] = f * b;
    hessRoundedD[0][0] = hessRoundedD[1][1] = f;
    hessRoundedD[0][1] = hessRoundedD[1][0] = 0.0;
    if (d > 0.0) {
      const double c = 3.0 / (r * r * d);
      hessRoundedD[0][0] -= c * h * h;
      hessRoundedD[1][1] -= c * b * b;
      hessRoundedD[0][1] = hessRoundedD[1][0] = -c * h * b;
    }
  }
  const double mu = m + roundedD;
  const double span = referenceStretch - 1.0;
  if (mu >= referenceStretch * referenceStretch) {
    q.stretch.value = 1.0;
  } else if (mu > 1.0) {
    const double lambda = std::sqrt(mu);
    q.stretch.value = (lambda - 1.0) / span;
    if (order >= 1) {
      Coordinate& s = q.stretch;
      s.varies = true;
      const double gradMu[3] = {gradRoundedD[0], gradRoundedD[1], 1.0};
      const double gradScale = 1.0 / (2.0 * lambda * span);  // grad s = grad mu / (2 lambda r)
      for (int i = 0; i < 3; ++i) s.grad[i] = gradMu[i] * gradScale;
      if (order >= 2) {
        // hess s = (hess mu / (2 lambda) - grad mu grad mu^T / (4 lambda mu)) / r.
        const double outerScale = 1.0 / (4.0 * lambda * mu * span);
        for (int i = 0; i < 3; ++i) {
          for (int j = i; j < 3; ++j) {
            const double hessMu = i < 2 && j < 2 ? hessRoundedD[i][j] : 0.0;
            s.hess[i][j] = s.hess[j][i] = hessMu * gradScale - gradMu[i] * gradMu[j] * outerScale;
          }
        }
      }
    }
  }

  if (!hasDirection) return q;  // t undefined, w = 0

  // t = k atan2(|b|, h): the fold phi -> |phi| is the fabric's mirror symmetry about U.
  constexpr double k = 4.0 / kPi;
  const double y = std::abs(b);
  const double sign = b < 0.0 ? -1.0 : 1.0;
  q.angle.value = k * std::atan2(y, h);
  if (order >= 1) {
    Coordinate& t = q.angle;
    t.varies = true;
    const double inverseD2 = inverseD * inverseD;
    t.grad[0] = -k * y * inverseD2;
    t.grad[1] = k * sign * h * inverseD2;
    t.grad[2] = 0.0;
    if (order >= 2) {
      const double inverseD4 = inverseD2 * inverseD2;
      t.hess[0][0] = 2.0 * k * h * y * inverseD4;
      t.hess[1][1] = -t.hess[0][0];
      t.hess[0][1] = t.hess[1][0] = k * sign * (y * y - h * h) * inverseD4;
      t.hess[0][2] = t.hess[1][2] = t.hess[2][0] = t.hess[2][1] = t.hess[2][2] = 0.0;
    }
  }

  // w = smoothstep(d / delta).
  const double x = d / kEquibiaxialBlend;
  if (x >= 1.0) {
    q.direction.value = 1.0;
  } else {
    q.direction.value = x * x * (3.0 - 2.0 * x);
    if (order >= 1) {
      Coordinate& w = q.direction;
      w.varies = true;
      const double slope = 6.0 * x * (1.0 - x) / kEquibiaxialBlend;
      w.grad[0] = slope * gradD[0];
      w.grad[1] = slope * gradD[1];
      w.grad[2] = 0.0;
      if (order >= 2) {
        const double curvature = (6.0 - 12.0 * x) / (kEquibiaxialBlend * kEquibiaxialBlend);
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j) w.hess[i][j] = curvature * gradD[i] * gradD[j] + slope * hessD[i][j];
        w.hess[0][2] = w.hess[1][2] = w.hess[2][0] = w.hess[2][1] = w.hess[2][2] = 0.0;
      }
    }
  }
  return q;
}

// L(t) and its slope dL/dt; t on a knot takes the segment to its right (the last one at t = 4).
struct DirectionRow {
  Coefficients value;
  Coefficients slope;
};

DirectionRow directionRow(const PreparedElasticity& samples, double t) {
  const int segment = std::clamp(static_cast<int>(std::floor(t)), 0, 3);
  const double f = std::clamp(t - segment, 0.0, 1.0);
  const Coefficients& lo = samples.directions[segment];
  const Coefficients& hi = samples.directions[segment + 1];
  return {lo + f * (hi - lo), hi - lo};
}

// J^T v: a gradient in (h, b, m) as a gradient in e = (e_uu, e_vv, g).
void toStrainGradient(const double v[3], double out[3]) {
  out[0] = v[0] + v[2];
  out[1] = v[2] - v[0];
  out[2] = v[1];
}

// J^T K J for a symmetric K in (h, b, m): a Hessian in (h, b, m) as a Hessian in e. The columns of
// J select h + m (for e_uu), m - h (for e_vv) and b (for g), so the product needs only sums.
void toStrainHessian(const double k[3][3], double out[3][3]) {
  const double kUU[3] = {k[0][0] + k[0][2], k[1][0] + k[1][2], k[2][0] + k[2][2]};  // K J e_uu-column
  const double kVV[3] = {k[0][2] - k[0][0], k[1][2] - k[1][0], k[2][2] - k[2][0]};  // K J e_vv-column
  out[0][0] = kUU[0] + kUU[2];
  out[1][1] = kVV[2] - kVV[0];
  out[2][2] = k[1][1];
  out[0][1] = out[1][0] = kVV[0] + kVV[2];
  out[0][2] = out[2][0] = k[0][1] + k[2][1];
  out[1][2] = out[2][1] = k[2][1] - k[0][1];
}

// ---- The two models -----------------------------------------------------------------------------

ElasticityResponse evaluateIsotropic(const PreparedElasticity& law, const Vec3& e) {
  ElasticityResponse r;
  r.tangent = law.isotropicMatrix;  // constant E, Eq. 2.11 (already scaled)
  r.stress = r.tangent * e;         // Eq. 2.12
  r.energyDensity = 0.5 * e.dot(r.stress);
  return r;
}

ElasticityResponse evaluateMeasured(const PreparedElasticity& samples, const Vec3& strain, bool wantTangent) {
  const InterpolationCoordinates q = interpolationCoordinates(strain, samples.referenceStretch, wantTangent ? 2 : 1);
  const double s = q.stretch.value;
  const double w = q.direction.value;
  const DirectionRow row = directionRow(samples, q.angle.value);
  const Coefficients& zero = samples.zeroStrain;
  const Coefficients& mean = samples.directionMean;

  const Coefficients stretched = w * row.value + (1.0 - w) * mean;
  const Coefficients c = (1.0 - s) * zero + s * stretched;
  // First derivatives of C with respect to (s, t, w).
  const std::array<Coefficients, 3> dC{stretched - zero, s * w * row.slope, s * (row.value - mean)};
  const std::array<const Coordinate*, 3> coords{&q.stretch, &q.angle, &q.direction};

  // Only the coordinates that vary contribute below (the others have zero derivatives).
  const double e[3] = {strain[0], strain[1], strain[2]};
  const double ce[3] = {2 * (c[0] * e[0] + c[1] * e[1]), 2 * (c[1] * e[0] + c[2] * e[1]), c[3] * e[2]};  // C e
  double stress[3] = {ce[0], ce[1], ce[2]};
  double gradE[3][3];  // grad_e q_j
  double p[3];         // P_j = 1/2 e^T C_j e
  for (int j = 0; j < 3; ++j) {
    p[j] = halfQuadratic(dC[j], strain);
    if (!coords[j]->varies) continue;
    toStrainGradient(coords[j]->grad, gradE[j]);
    for (int i = 0; i < 3; ++i) stress[i] += p[j] * gradE[j][i];
  }

  const double scale = samples.stiffnessScale;
  ElasticityResponse r;
  r.energyDensity = 0.5 * (e[0] * ce[0] + e[1] * ce[1] + e[2] * ce[2]) * scale;
  for (int i = 0; i < 3; ++i) r.stress[i] = stress[i] * scale;
  if (!wantTangent) return r;

  double mixed[3][3] = {};      // sum_j (C_j e) grad q_j^T
  double curvature[3][3] = {};  // the second-derivative terms, gathered in (h, b, m) and mapped once
  for (int j = 0; j < 3; ++j) {
    if (!coords[j]->varies) continue;
    const Vec3 cje = apply(dC[j], strain);
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        mixed[a][b] += cje[a] * gradE[j][b];
        curvature[a][b] += p[j] * coords[j]->hess[a][b];
      }
    }
  }
  auto addCross = [&](const Coefficients& cjk, const Coordinate& qj, const Coordinate& qk) {
    if (!qj.varies || !qk.varies) return;
    const double pjk = halfQuadratic(cjk, strain);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) curvature[a][b] += pjk * (qj.grad[a] * qk.grad[b] + qj.grad[b] * qk.grad[a]);
  };
  addCross(w * row.slope, q.stretch, q.angle);         // C_st
  addCross(row.value - mean, q.stretch, q.direction);  // C_sw
  addCross(s * row.slope, q.angle, q.direction);       // C_tw
  double curvatureE[3][3];
  toStrainHessian(curvature, curvatureE);
  const double cm[3][3] = {{2 * c[0], 2 * c[1], 0.0}, {2 * c[1], 2 * c[2], 0.0}, {0.0, 0.0, c[3]}};  // C itself
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) r.tangent(a, b) = (cm[a][b] + mixed[a][b] + mixed[b][a] + curvatureE[a][b]) * scale;
  return r;
}

}  // namespace

PreparedElasticity prepareElasticity(const ElasticitySettings& settings) {
  PreparedElasticity law;
  law.model = settings.model;
  law.stiffnessScale = settings.stiffnessScale;
  law.referenceStretch = settings.measured.referenceStretch;
  if (settings.model == ElasticitySettings::Model::Isotropic) {
    law.isotropicMatrix = isotropicMatrix(settings);
    return law;
  }
  law.zeroStrain = usableSample(settings.measured.zeroStrain);
  constexpr std::array<double, 5> kTrapezoid{0.125, 0.25, 0.25, 0.25, 0.125};
  law.directionMean.setZero();
  for (int i = 0; i < 5; ++i) {
    law.directions[i] = usableSample(settings.measured.directions[i]);
    law.directionMean += kTrapezoid[i] * law.directions[i];
  }
  return law;
}

ElasticityResponse evaluateElasticity(const PreparedElasticity& law, const Eigen::Vector3d& strain, bool wantTangent) {
  if (law.model == ElasticitySettings::Model::Isotropic) return evaluateIsotropic(law, strain);
  return evaluateMeasured(law, strain, wantTangent);
}

ElasticityResponse evaluateElasticity(const ElasticitySettings& settings, const Eigen::Vector3d& strain,
                                      bool wantTangent) {
  return evaluateElasticity(prepareElasticity(settings), strain, wantTangent);
}

Eigen::Matrix3d elasticityMatrix(const ElasticitySettings& settings, const Eigen::Vector3d& strain) {
  if (settings.model == ElasticitySettings::Model::Isotropic) return isotropicMatrix(settings);
  assert(settings.measured.referenceStretch > 1.0);
  const PreparedElasticity samples = prepareElasticity(settings);
  const InterpolationCoordinates q = interpolationCoordinates(strain, samples.referenceStretch, 0);
  const double s = q.stretch.value;
  const double w = q.direction.value;
  const Coefficients l = directionRow(samples, q.angle.value).value;
  const Coefficients c = (1.0 - s) * samples.zeroStrain + s * (w * l + (1.0 - w) * samples.directionMean);
  return settings.stiffnessScale * toMatrix(c);
}

}  // namespace weft
