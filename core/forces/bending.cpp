// Bending hinges (thesis §2.4): the dihedral angle, its gradient and Hessian in closed form, and
// the hinge energy whose negative gradient is Bridson's force.
//
// Hinge geometry, with x0, x1 the shared edge (p3, p4) and x2, x3 the wings (p1, p2):
//   e  = x1 - x0                         E of Eq. 2.51
//   N1 = e x (x2 - x0)                   = (p1 - p3) x (p1 - p4), Eq. 2.49
//   N2 = (x3 - x0) x e                   = (p2 - p4) x (p2 - p3), Eq. 2.50
//   theta = atan2((N1 x N2) . e/|e|, N1 . N2)
// atan2 gives sin(theta) the sign of (n1 x n2) . E (Eq. 2.58) and is accurate at every angle,
// where Eq. 2.57 (a square root of 1 - n1.n2) loses precision near flat. theta = 0 when flat.
//
// Energy. Eq. 2.56 with |E| and |N1| + |N2| taken at rest (|N| = 2A) reads
//   F_i = k c sin(phi/2) u_i,   c = l0^2 / (2 (A0 + A1)),   phi = theta - theta0,
// and the u_i of Eq. 2.52-2.55 are -grad theta. So F = -grad W with
//   W(phi) = c * integral_0^|phi| k(tau) sin(tau/2) dtau,
// which for a constant k is W = 2 k c (1 - cos(phi/2)) = 4 k c sin^2(phi/4), and for small
// angles k l0^2 phi^2 / (8 (A0 + A1)): the hinge energy of ARCSim (FORMAT.md, "bending").
// A measured k depends on the bend through alpha = kappa/2, kappa = tau l0 / (A0 + A1); the
// table interpolates linearly in alpha, so k is piecewise linear in tau and the integral has a
// closed form per piece (integrateStiffnessPiece). The force is then exactly -grad W.
#include "forces/bending.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Geometry>

namespace weft {

namespace {

using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

// A hinge is treated as degenerate (no force) when a wing's height over the edge falls below
// this fraction of the edge length, or the edge has no length: its normal is then undefined.
constexpr double kDegenerateHeightRatio = 1e-12;

constexpr int kCurvatureSamples = 5;        // columns of the measured table
constexpr double kCurvatureSampleStep = 5;  // alpha between two columns (1/m)

// [v]x, the matrix of the cross product v x w.
Mat3 crossMatrix(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

// A plain 3-vector for the per-hinge arithmetic that runs every step. Eigen evaluates a Vector3d
// as a 2-wide packet plus a scalar, and its temporaries, stored as scalars and reloaded as packets,
// stall the CPU (failed store forwarding) for longer than the arithmetic itself takes. The exact
// Hessian of theta, a validation tool, keeps Eigen.
struct Plain3 {
  double x, y, z;
};

Plain3 plain(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
Vec3 toEigen(const Plain3& v) { return Vec3(v.x, v.y, v.z); }
Plain3 operator-(const Plain3& a, const Plain3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Plain3 operator+(const Plain3& a, const Plain3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Plain3 operator*(double s, const Plain3& a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(const Plain3& a, const Plain3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Plain3 cross(const Plain3& a, const Plain3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// The hinge's four corners.
struct HingeCorners {
  Plain3 x0, x1, x2, x3;
};

struct HingeGeometry {
  Plain3 e;           // x1 - x0
  double length = 0;  // |e|
  Plain3 n1, n2;      // N1, N2 (not normalised: |N| is twice the triangle area)
  double theta = 0;   // signed dihedral angle (rad)
  bool degenerate = true;
};

HingeGeometry hingeGeometry(const HingeCorners& x) {
  HingeGeometry g;
  g.e = x.x1 - x.x0;
  g.length = std::sqrt(dot(g.e, g.e));
  g.n1 = cross(g.e, x.x2 - x.x0);
  g.n2 = cross(x.x3 - x.x0, g.e);
  // |N| = height * |e|, so this compares each wing's height with the edge length (squared: no root).
  const double minNormal = kDegenerateHeightRatio * g.length * g.length;
  const double minNormalSquared = minNormal * minNormal;
  g.degenerate = !(g.length > 0.0) || !(dot(g.n1, g.n1) > minNormalSquared) || !(dot(g.n2, g.n2) > minNormalSquared);
  if (g.degenerate) return g;
  g.theta = std::atan2(dot(cross(g.n1, g.n2), g.e) / g.length, dot(g.n1, g.n2));
  return g;
}

// Blocks of a 12-vector / 12x12 matrix by hinge vertex.
auto block(Vec12& v, int i) { return v.segment<3>(3 * i); }
auto block(Mat12& m, int i, int j) { return m.block<3, 3>(3 * i, 3 * j); }

// Everything the gradient and Hessian of theta are built from. With m_t = N_t/|N_t|^2,
//   d theta/d x2 = -l m1,   d theta/d x3 = -l m2,
//   d theta/d x0 = -(s1 m1 + s2 m2),   s1 = (x2 - x1).e / l,   s2 = (x3 - x1).e / l,
//   d theta/d x1 =  (t1 m1 + t2 m2),   t1 = (x2 - x0).e / l,   t2 = (x3 - x0).e / l,
// i.e. minus Bridson's u_i (Eq. 2.52-2.55; Eq. 2.55 as printed lacks u4's minus sign, without
// which the u_i would not sum to zero).
struct DihedralTerms {
  double l;
  Plain3 m1, m2;
  double p1, p2, q1, q2;  // (x2-x1).e, (x3-x1).e, (x2-x0).e, (x3-x0).e
};

DihedralTerms dihedralTerms(const HingeGeometry& g, const HingeCorners& x) {
  DihedralTerms t;
  t.l = g.length;
  t.m1 = (1.0 / dot(g.n1, g.n1)) * g.n1;  // one division, not three
  t.m2 = (1.0 / dot(g.n2, g.n2)) * g.n2;
  t.p1 = dot(x.x2 - x.x1, g.e);
  t.p2 = dot(x.x3 - x.x1, g.e);
  t.q1 = dot(x.x2 - x.x0, g.e);
  t.q2 = dot(x.x3 - x.x0, g.e);
  return t;
}

// d theta / d x_i for the four corners.
std::array<Plain3, 4> dihedralGradient(const DihedralTerms& t) {
  const double inverseLength = 1.0 / t.l;
  return {-inverseLength * (t.p1 * t.m1 + t.p2 * t.m2), inverseLength * (t.q1 * t.m1 + t.q2 * t.m2), -t.l * t.m1,
          -t.l * t.m2};
}

// The Hessian of theta: the product rule applied to the gradient above, block by block
// (H_ij = d grad_i / d x_j). The pieces:
//   dl/dx0 = -e/l, dl/dx1 = e/l;
//   dm/dx_j = (I - 2 n n^T)/|N|^2 dN/dx_j, n = N/|N|;
//   for a triangle (a, b, c) with N = (b - a) x (c - a):
//     dN/da = [c - b]x, dN/db = [a - c]x, dN/dc = [b - a]x;
//   the dot products p, q are bilinear, so their gradients are read off directly.
// The result is symmetric up to round-off; it is symmetrised on return.
Mat12 dihedralHessian(const HingeGeometry& g, const DihedralTerms& terms, const Vec3& x0, const Vec3& x1,
                      const Vec3& x2, const Vec3& x3) {
  const struct {  // the terms, with Eigen vectors
    double l;
    Vec3 m1, m2;
    double p1, p2, q1, q2;
  } t{terms.l, toEigen(terms.m1), toEigen(terms.m2), terms.p1, terms.p2, terms.q1, terms.q2};
  const Vec3 e = toEigen(g.e);
  const Vec3 unitEdge = e / t.l;
  const Vec3 zero = Vec3::Zero();
  const std::array<Vec3, 4> dl{-unitEdge, unitEdge, zero, zero};

  const Vec3 n1 = toEigen(g.n1).normalized();
  const Vec3 n2 = toEigen(g.n2).normalized();
  const Mat3 reflect1 = (Mat3::Identity() - 2.0 * n1 * n1.transpose()) / toEigen(g.n1).squaredNorm();
  const Mat3 reflect2 = (Mat3::Identity() - 2.0 * n2 * n2.transpose()) / toEigen(g.n2).squaredNorm();
  // Triangle 1 is (x0, x1, x2), triangle 2 is (x0, x3, x1).
  const std::array<Mat3, 4> dm1{reflect1 * crossMatrix(x2 - x1), reflect1 * crossMatrix(x0 - x2),
                                reflect1 * crossMatrix(e), Mat3::Zero()};
  const std::array<Mat3, 4> dm2{reflect2 * crossMatrix(x1 - x3), reflect2 * crossMatrix(x3 - x0), Mat3::Zero(),
                                reflect2 * crossMatrix(-e)};

  const std::array<Vec3, 4> dp1{-(x2 - x1), (x2 - x1) - e, e, zero};
  const std::array<Vec3, 4> dp2{-(x3 - x1), (x3 - x1) - e, zero, e};
  const std::array<Vec3, 4> dq1{-e - (x2 - x0), x2 - x0, e, zero};
  const std::array<Vec3, 4> dq2{-e - (x3 - x0), x3 - x0, zero, e};
  // d(p/l) = dp/l - p dl/l^2
  auto quotientGradient = [&](double p, const Vec3& dp, int j) { return Vec3(dp / t.l - p * dl[j] / (t.l * t.l)); };

  Mat12 h;
  for (int j = 0; j < 4; ++j) {
    block(h, 0, j) = -(t.m1 * quotientGradient(t.p1, dp1[j], j).transpose() + (t.p1 / t.l) * dm1[j] +
                       t.m2 * quotientGradient(t.p2, dp2[j], j).transpose() + (t.p2 / t.l) * dm2[j]);
    block(h, 1, j) = t.m1 * quotientGradient(t.q1, dq1[j], j).transpose() + (t.q1 / t.l) * dm1[j] +
                     t.m2 * quotientGradient(t.q2, dq2[j], j).transpose() + (t.q2 / t.l) * dm2[j];
    block(h, 2, j) = -(t.m1 * dl[j].transpose() + t.l * dm1[j]);
    block(h, 3, j) = -(t.m2 * dl[j].transpose() + t.l * dm2[j]);
  }
  return 0.5 * (h + h.transpose());
}

// The stiffness of one hinge as a function of its bend tau = |theta - theta0|: k_j at
// tau_j = j * knotSpacing, linear in between, constant past the last knot.
struct StiffnessCurve {
  std::array<double, kCurvatureSamples> knots{};
  double knotSpacing = 1.0;  // rad
};

StiffnessCurve stiffnessCurve(const BendingHinge& hinge, const BendingSettings& settings) {
  StiffnessCurve curve;
  // alpha = kappa/2 = tau l0 / (2 (A0 + A1)), so alpha_j = 5 j falls at tau_j = 10 j (A0 + A1) / l0.
  curve.knotSpacing = kCurvatureSampleStep * 2.0 * hinge.restAreaSum / hinge.restLength;
  if (settings.model == BendingSettings::Model::Measured) {
    // Rows at 0, 45 and 90 degrees from the weft, linear in between (FORMAT.md, "bending").
    const double rowPosition = std::clamp(hinge.edgeAngle / (kPi / 4.0), 0.0, 2.0);
    const int row = std::min(static_cast<int>(rowPosition), 1);
    const double w = rowPosition - row;
    for (int j = 0; j < kCurvatureSamples; ++j) {
      curve.knots[j] = settings.stiffnessScale *
                       ((1.0 - w) * settings.measured[row][j] + w * settings.measured[row + 1][j]);
    }
  } else if (settings.model == BendingSettings::Model::Constant) {
    curve.knots.fill(settings.stiffnessScale * settings.stiffness);
  }
  return curve;
}

// k(tau) and dk/dtau (the slope of the piece holding tau; 0 past the last knot).
struct StiffnessAt {
  double k;
  double slope;
};

StiffnessAt stiffnessAt(const StiffnessCurve& curve, double tau) {
  const double position = tau / curve.knotSpacing;
  if (!(position < kCurvatureSamples - 1)) return {curve.knots.back(), 0.0};  // clamped beyond the table
  const int j = static_cast<int>(position);
  const double slope = (curve.knots[j + 1] - curve.knots[j]) / curve.knotSpacing;
  return {curve.knots[j] + slope * (tau - j * curve.knotSpacing), slope};
}

// 2 sin(d/2) - d cos(d/2) (= integral_0^d u sin(u/2) du / 2); its Taylor series for small d,
// where the two terms cancel to O(d^3).
double sineMoment(double d) {
  if (d < 0.1) {
    const double d2 = d * d;
    return d * d2 * (1.0 / 12.0 - d2 * (1.0 / 480.0 - d2 / 53760.0));
  }
  return 2.0 * std::sin(0.5 * d) - d * std::cos(0.5 * d);
}

// integral_a^{a+d} (k_a + s (tau - a)) sin(tau/2) dtau in closed form, written with half-angle
// products so that it keeps full relative precision for small angles:
//   integral sin(tau/2)                 = 2 (cos(a/2) - cos((a+d)/2)) = 4 sin((2a+d)/4) sin(d/4)
//   integral (tau - a) sin(tau/2)       = cos(a/2) int_0^d u sin(u/2) du + sin(a/2) int_0^d u cos(u/2) du
//   int_0^d u sin(u/2) du = 2 (2 sin(d/2) - d cos(d/2)),   int_0^d u cos(u/2) du = 2 d sin(d/2) - 8 sin^2(d/4)
//
// The first piece (a = 0) holds most hinges; there cos(a/2) = 1 and sin(a/2) = 0, so its sines and
// cosines of a and the cosine moment drop out (the same numbers, three fewer trigonometric calls).
double integrateStiffnessPiece(double a, double d, double kStart, double slope) {
  const double quarter = std::sin(0.25 * d);
  if (a == 0.0) {
    const double constantPart = 4.0 * quarter * quarter;
    if (slope == 0.0) return kStart * constantPart;
    return kStart * constantPart + slope * (2.0 * sineMoment(d));
  }
  const double constantPart = 4.0 * std::sin(0.25 * (2.0 * a + d)) * quarter;
  if (slope == 0.0) return kStart * constantPart;
  const double momentSin = 2.0 * sineMoment(d);
  const double momentCos = 2.0 * d * std::sin(0.5 * d) - 8.0 * quarter * quarter;
  return kStart * constantPart + slope * (std::cos(0.5 * a) * momentSin + std::sin(0.5 * a) * momentCos);
}

// integral_0^tau k(t) sin(t/2) dt, piece by piece.
double stiffnessIntegral(const StiffnessCurve& curve, double tau) {
  double sum = 0.0;
  for (int j = 0; j < kCurvatureSamples; ++j) {
    const double start = j * curve.knotSpacing;
    if (start >= tau) break;
    const bool last = j == kCurvatureSamples - 1;
    const double end = last ? tau : std::min(tau, start + curve.knotSpacing);
    const double slope = last ? 0.0 : (curve.knots[j + 1] - curve.knots[j]) / curve.knotSpacing;
    sum += integrateStiffnessPiece(start, end - start, curve.knots[j], slope);
  }
  return sum;
}

// theta - theta0 wrapped into (-pi, pi], so that a rest fold near +-pi is measured the short way.
double bendAngle(double theta, double restAngle) {
  double phi = theta - restAngle;
  if (phi > kPi) phi -= 2.0 * kPi;
  if (phi <= -kPi) phi += 2.0 * kPi;
  return phi;
}

// The vertex of `t` that is neither a nor b.
int oppositeVertex(const Triangle& t, int a, int b) {
  for (int id : t.v) {
    if (id != a && id != b) return id;
  }
  return kNone;
}

}  // namespace

std::optional<BendingHinge> makeBendingHinge(const ClothMesh& mesh, int edgeId, double weftAngleRad,
                                             bool restFromCurrent) {
  const Edge& edge = mesh.edges[edgeId];
  if (edge.tri[0] == kNone || edge.tri[1] == kNone) return std::nullopt;  // a border edge bends nothing (§2.4)
  const Triangle& first = mesh.tris[edge.tri[0]];
  const Triangle& second = mesh.tris[edge.tri[1]];

  // Take the edge in the direction the first triangle runs along it, so that the first
  // triangle is (x0, x1, x2) and, the mesh being counter-clockwise in material space, the
  // second is (x0, x3, x1): both normals then agree on a flat sheet (theta = 0).
  int corner = kNone;
  for (int k = 0; k < 3; ++k) {
    const int a = first.v[k];
    const int b = first.v[(k + 1) % 3];
    if ((a == edge.v[0] && b == edge.v[1]) || (a == edge.v[1] && b == edge.v[0])) corner = k;
  }
  if (corner == kNone) return std::nullopt;

  BendingHinge hinge;
  hinge.edge = edgeId;
  hinge.v = {first.v[corner], first.v[(corner + 1) % 3], first.v[(corner + 2) % 3],
             oppositeVertex(second, first.v[corner], first.v[(corner + 1) % 3])};
  if (hinge.v[3] == kNone) return std::nullopt;

  const Vec2 restEdge = first.rest[(corner + 1) % 3] - first.rest[corner];
  const double area0 = std::abs(restArea(first));
  const double area1 = std::abs(restArea(second));
  hinge.restLength = restEdge.norm();
  hinge.restAreaSum = area0 + area1;
  if (!(area0 > 0.0) || !(area1 > 0.0) || !(hinge.restLength > 0.0)) return std::nullopt;

  // Edge direction in the weft/warp frame (material space rotated by -weftAngleRad). Taking
  // absolute values folds it into [0, pi/2]: an edge has no orientation, and the table treats
  // +45 and -45 degrees alike.
  const double cosWeft = std::cos(weftAngleRad);
  const double sinWeft = std::sin(weftAngleRad);
  const double alongWeft = cosWeft * restEdge.x() + sinWeft * restEdge.y();
  const double alongWarp = -sinWeft * restEdge.x() + cosWeft * restEdge.y();
  hinge.edgeAngle = std::atan2(std::abs(alongWarp), std::abs(alongWeft));

  if (restFromCurrent) {
    const HingeGeometry g = hingeGeometry(
        {plain(mesh.x[hinge.v[0]]), plain(mesh.x[hinge.v[1]]), plain(mesh.x[hinge.v[2]]), plain(mesh.x[hinge.v[3]])});
    hinge.restAngle = g.degenerate ? 0.0 : g.theta;
  }
  return hinge;
}

std::vector<BendingHinge> buildBendingHinges(const ClothMesh& mesh, double weftAngleRad, bool restFromCurrent) {
  std::vector<BendingHinge> hinges;
  for (int id = 0; id < mesh.edgeCount(); ++id) {
    if (std::optional<BendingHinge> hinge = makeBendingHinge(mesh, id, weftAngleRad, restFromCurrent)) {
      hinges.push_back(*hinge);
    }
  }
  return hinges;
}

void evaluateHinge(const BendingHinge& hinge, const BendingSettings& settings, const Vec3& x0, const Vec3& x1,
                   const Vec3& x2, const Vec3& x3, HessianMode mode, HingeContribution& out) {
  // A hinge without stiffness or normal contributes a finite zero rather than NaN.
  auto contributeNothing = [&] {
    out.energy = 0.0;
    for (Vec3& f : out.force) f.setZero();
    if (mode != HessianMode::None) out.hessian.setZero();
  };
  if (!bendingEnabled(settings) || !(hinge.restLength > 0.0) || !(hinge.restAreaSum > 0.0)) return contributeNothing();
  const HingeCorners corners{plain(x0), plain(x1), plain(x2), plain(x3)};
  const HingeGeometry g = hingeGeometry(corners);
  if (g.degenerate) return contributeNothing();

  const double c = hinge.restLength * hinge.restLength / (2.0 * hinge.restAreaSum);
  const StiffnessCurve curve = stiffnessCurve(hinge, settings);
  const double phi = bendAngle(g.theta, hinge.restAngle);
  const double tau = std::abs(phi);
  const StiffnessAt k = stiffnessAt(curve, tau);
  // sin(phi/2) from sin(tau/2): the sine is odd (and the cosine below even), exactly so in floating
  // point, which saves evaluating both of phi and of tau.
  const double sinHalfTau = std::sin(0.5 * tau);
  const double sinHalfPhi = phi < 0.0 ? -sinHalfTau : sinHalfTau;

  // W(phi) = c int_0^|phi| k sin(tau/2), W' = c k sin(phi/2) (Eq. 2.56), W'' = c (k' sin|phi|/2 + k cos(phi/2)/2).
  out.energy = c * stiffnessIntegral(curve, tau);
  const double dW = c * k.k * sinHalfPhi;
  const DihedralTerms terms = dihedralTerms(g, corners);
  const std::array<Plain3, 4> gradTheta = dihedralGradient(terms);
  for (int i = 0; i < 4; ++i) out.force[i] = toEigen(-dW * gradTheta[i]);

  if (mode == HessianMode::None) return;
  const double cosHalfTau = std::cos(0.5 * tau);
  const double d2W = c * (k.slope * sinHalfTau + 0.5 * k.k * cosHalfTau);
  if (mode == HessianMode::Exact) {
    Vec12 gradient;
    for (int i = 0; i < 4; ++i) block(gradient, i) = toEigen(gradTheta[i]);
    const Mat12 exact = d2W * gradient * gradient.transpose() + dW * dihedralHessian(g, terms, x0, x1, x2, x3);
    int stored = 0;  // blocks (i, j), i <= j, row by row
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) out.hessian.upper[stored++] = exact.block<3, 3>(3 * i, 3 * j);
  } else {
    // Gauss-Newton: drop W' times the (indefinite) Hessian of theta and clamp W'' at zero. This
    // is positive semi-definite, and exact wherever W' = 0, i.e. at the rest angle. The Hessian
    // of theta is never formed here: the blocks are outer products of the gradient's pieces.
    const double weight = std::max(d2W, 0.0);
    int stored = 0;  // blocks (i, j), i <= j, row by row
    for (int i = 0; i < 4; ++i) {
      const Plain3 a = weight * gradTheta[i];
      for (int j = i; j < 4; ++j) {
        const Plain3& b = gradTheta[j];
        out.hessian.upper[stored++] << a.x * b.x, a.x * b.y, a.x * b.z,  //
            a.y * b.x, a.y * b.y, a.y * b.z,                             //
            a.z * b.x, a.z * b.y, a.z * b.z;
      }
    }
  }
}

HingeResult evaluateHinge(const BendingHinge& hinge, const BendingSettings& settings, const Vec3& x0, const Vec3& x1,
                          const Vec3& x2, const Vec3& x3, HessianMode mode) {
  HingeContribution contribution;
  evaluateHinge(hinge, settings, x0, x1, x2, x3, mode, contribution);
  HingeResult out;
  out.energy = contribution.energy;
  for (int i = 0; i < 4; ++i) out.force.segment<3>(3 * i) = contribution.force[i];
  if (mode != HessianMode::None) out.hessian = contribution.hessian.dense();
  return out;
}

bool bendingEnabled(const BendingSettings& settings) {
  if (settings.stiffnessScale == 0.0) return false;
  switch (settings.model) {
    case BendingSettings::Model::None:
      return false;
    case BendingSettings::Model::Constant:
      return settings.stiffness != 0.0;
    case BendingSettings::Model::Measured:
      for (const auto& row : settings.measured) {
        for (double k : row) {
          if (k != 0.0) return true;
        }
      }
      return false;
  }
  return false;
}

}  // namespace weft
