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

struct UsableSamples {
  Coefficients zeroStrain;
  std::array<Coefficients, 5> directions;
  Coefficients directionMean;  // Lavg: integral mean of the piecewise-linear L over [0, 90] deg
};

UsableSamples usableSamples(const MeasuredElasticity& measured) {
  UsableSamples out;
  out.zeroStrain = usableSample(measured.zeroStrain);
  constexpr std::array<double, 5> kTrapezoid{0.125, 0.25, 0.25, 0.25, 0.125};
  out.directionMean.setZero();
  for (int i = 0; i < 5; ++i) {
    out.directions[i] = usableSample(measured.directions[i]);
    out.directionMean += kTrapezoid[i] * out.directions[i];
  }
  return out;
}

// ---- The interpolation coordinates q = (s, t, w) as functions of the strain -------------------

// Value, gradient and Hessian of one coordinate with respect to (h, b, m).
struct Coordinate {
  double value = 0.0;
  Vec3 grad = Vec3::Zero();
  Mat3 hess = Mat3::Zero();
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

  // d and its derivatives on the (h, b) block; zero (the subgradient mean) at the cone tip.
  Vec3 gradD = Vec3::Zero();
  Mat3 hessD = Mat3::Zero();
  if (hasDirection && order >= 1) {
    gradD << h / d, b / d, 0.0;
    if (order >= 2) {
      const double d3 = d * d * d;
      hessD(0, 0) = b * b / d3;
      hessD(1, 1) = h * h / d3;
      hessD(0, 1) = hessD(1, 0) = -h * b / d3;
    }
  }

  InterpolationCoordinates q;

  // s from the largest principal stretch lambda = sqrt(m + d). lambda has a cone on the
  // equibiaxial line d = 0 (its tangent grows like 1/d), so for s alone d is replaced below
  // r = kStretchRounding by the cubic d~ = 2 d^2/r - d^3/r^2: C1 at d = r, zero with zero slope at
  // d = 0 (so s stays 0 at rest) and smooth in (h, b), which keeps the tangent bounded.
  double roundedD = d;
  Vec3 gradRoundedD = gradD;
  Mat3 hessRoundedD = hessD;
  if (d < kStretchRounding) {
    const double r = kStretchRounding;
    roundedD = 2.0 * d * d / r - d * d * d / (r * r);
    const double f = 4.0 / r - 3.0 * d / (r * r);  // d~ = f-weighted: grad d~ = f (h, b)
    gradRoundedD << f * h, f * b, 0.0;
    hessRoundedD.setZero();
    hessRoundedD(0, 0) = hessRoundedD(1, 1) = f;
    if (d > 0.0) {
      const double c = 3.0 / (r * r * d);
      hessRoundedD(0, 0) -= c * h * h;
      hessRoundedD(1, 1) -= c * b * b;
      hessRoundedD(0, 1) = hessRoundedD(1, 0) = -c * h * b;
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
      const Vec3 gradMu = gradRoundedD + Vec3(0.0, 0.0, 1.0);
      q.stretch.grad = gradMu / (2.0 * lambda * span);
      if (order >= 2) {
        q.stretch.hess = (hessRoundedD / (2.0 * lambda) - gradMu * gradMu.transpose() / (4.0 * lambda * mu)) / span;
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
    const double d2 = d * d;
    q.angle.grad << -k * y / d2, k * sign * h / d2, 0.0;
    if (order >= 2) {
      const double d4 = d2 * d2;
      q.angle.hess(0, 0) = 2.0 * k * h * y / d4;
      q.angle.hess(1, 1) = -q.angle.hess(0, 0);
      q.angle.hess(0, 1) = q.angle.hess(1, 0) = k * sign * (y * y - h * h) / d4;
    }
  }

  // w = smoothstep(d / delta).
  const double x = d / kEquibiaxialBlend;
  if (x >= 1.0) {
    q.direction.value = 1.0;
  } else {
    q.direction.value = x * x * (3.0 - 2.0 * x);
    if (order >= 1) {
      const double slope = 6.0 * x * (1.0 - x) / kEquibiaxialBlend;
      q.direction.grad = slope * gradD;
      if (order >= 2) {
        const double curvature = (6.0 - 12.0 * x) / (kEquibiaxialBlend * kEquibiaxialBlend);
        q.direction.hess = curvature * gradD * gradD.transpose() + slope * hessD;
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

DirectionRow directionRow(const UsableSamples& samples, double t) {
  const int segment = std::clamp(static_cast<int>(std::floor(t)), 0, 3);
  const double f = std::clamp(t - segment, 0.0, 1.0);
  const Coefficients& lo = samples.directions[segment];
  const Coefficients& hi = samples.directions[segment + 1];
  return {lo + f * (hi - lo), hi - lo};
}

// J^T v: a gradient in (h, b, m) as a gradient in e = (e_uu, e_vv, g).
Vec3 toStrainGradient(const Vec3& v) { return Vec3(v[0] + v[2], v[2] - v[0], v[1]); }

Mat3 hbmJacobian() {
  Mat3 j;
  j << 1, -1, 0, 0, 0, 1, 1, 1, 0;
  return j;
}

// ---- The two models -----------------------------------------------------------------------------

ElasticityResponse evaluateIsotropic(const ElasticitySettings& settings, const Vec3& e) {
  ElasticityResponse r;
  r.tangent = elasticityMatrix(settings, e);  // constant E, Eq. 2.11 (already scaled)
  r.stress = r.tangent * e;                    // Eq. 2.12
  r.energyDensity = 0.5 * e.dot(r.stress);
  return r;
}

ElasticityResponse evaluateMeasured(const ElasticitySettings& settings, const Vec3& e, bool wantTangent) {
  const UsableSamples samples = usableSamples(settings.measured);
  const InterpolationCoordinates q =
      interpolationCoordinates(e, settings.measured.referenceStretch, wantTangent ? 2 : 1);
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

  ElasticityResponse r;
  const Vec3 ce = apply(c, e);
  r.energyDensity = 0.5 * e.dot(ce);
  r.stress = ce;
  std::array<Vec3, 3> gradE;  // grad_e q_j
  std::array<double, 3> p;    // P_j = 1/2 e^T C_j e
  for (int j = 0; j < 3; ++j) {
    gradE[j] = toStrainGradient(coords[j]->grad);
    p[j] = halfQuadratic(dC[j], e);
    r.stress += p[j] * gradE[j];
  }

  if (wantTangent) {
    Mat3 mixed = Mat3::Zero();  // sum_j (C_j e) grad q_j^T
    for (int j = 0; j < 3; ++j) mixed += apply(dC[j], e) * gradE[j].transpose();
    // Second-derivative terms, gathered in (h, b, m) and mapped once.
    Mat3 curvature = p[0] * q.stretch.hess + p[1] * q.angle.hess + p[2] * q.direction.hess;
    auto addCross = [&](const Coefficients& cjk, const Coordinate& qj, const Coordinate& qk) {
      const Mat3 outer = qj.grad * qk.grad.transpose();
      curvature += halfQuadratic(cjk, e) * (outer + outer.transpose());
    };
    addCross(w * row.slope, q.stretch, q.angle);           // C_st
    addCross(row.value - mean, q.stretch, q.direction);    // C_sw
    addCross(s * row.slope, q.angle, q.direction);         // C_tw
    const Mat3 j = hbmJacobian();
    r.tangent = toMatrix(c) + mixed + mixed.transpose() + j.transpose() * curvature * j;
  }

  const double scale = settings.stiffnessScale;
  r.energyDensity *= scale;
  r.stress *= scale;
  r.tangent *= scale;
  return r;
}

}  // namespace

ElasticityResponse evaluateElasticity(const ElasticitySettings& settings, const Eigen::Vector3d& strain,
                                      bool wantTangent) {
  if (settings.model == ElasticitySettings::Model::Isotropic) return evaluateIsotropic(settings, strain);
  return evaluateMeasured(settings, strain, wantTangent);
}

Eigen::Matrix3d elasticityMatrix(const ElasticitySettings& settings, const Eigen::Vector3d& strain) {
  if (settings.model == ElasticitySettings::Model::Isotropic) {
    // Eq. 2.11: E = Eh/(1-nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1-nu)/2]].
    const double nu = settings.poissonRatio;
    const double factor = settings.stiffnessScale * settings.youngModulus / (1.0 - nu * nu);
    Mat3 e;
    e << 1, nu, 0, nu, 1, 0, 0, 0, 0.5 * (1.0 - nu);
    return factor * e;
  }
  assert(settings.measured.referenceStretch > 1.0);
  const UsableSamples samples = usableSamples(settings.measured);
  const InterpolationCoordinates q = interpolationCoordinates(strain, settings.measured.referenceStretch, 0);
  const double s = q.stretch.value;
  const double w = q.direction.value;
  const Coefficients l = directionRow(samples, q.angle.value).value;
  const Coefficients c = (1.0 - s) * samples.zeroStrain + s * (w * l + (1.0 - w) * samples.directionMean);
  return settings.stiffnessScale * toMatrix(c);
}

}  // namespace weft
