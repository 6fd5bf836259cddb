#include "collision/exact_sign.h"

#include <array>
#include <cassert>
#include <cmath>

#include <gmpxx.h>

namespace weft {

namespace {

// A double split into a rounded value and the exact error of that rounding.
struct Split {
  double value;
  double error;
};

// a + b == value + error exactly (Knuth's branch-free two-sum). Relies on IEEE round-to-nearest
// and on the compiler not reassociating, i.e. no -ffast-math.
Split twoSum(double a, double b) {
  const double sum = a + b;
  const double bPart = sum - a;
  const double aPart = sum - bPart;
  return {sum, (a - aPart) + (b - bPart)};
}

// a * b == value + error exactly, provided the error does not underflow: the fused multiply-add
// evaluates a * b - value with one rounding, and that difference is representable.
Split twoProduct(double a, double b) {
  const double product = a * b;
  return {product, std::fma(a, b, -product)};
}

// An exact running sum of doubles, kept as a nonoverlapping expansion (the representation of
// Priest's and Shewchuk's exact arithmetic, written here from its description): components in
// increasing magnitude whose significant bits do not overlap, so the largest one alone has the
// sign of the sum. Adding a double threads it through the components from the smallest up, keeping each
// rounding error as a component; zero errors are dropped so the expansion stays as short as the
// value needs. Each add lengthens it by at most one component, hence the capacity: the number of
// adds.
template <int kCapacity>
class ExactSum {
 public:
  void add(double x) {
    if (x == 0.0) return;
    assert(size_ < kCapacity);
    int kept = 0;
    for (int i = 0; i < size_; ++i) {
      const Split s = twoSum(x, components_[i]);
      if (s.error != 0.0) components_[kept++] = s.error;
      x = s.value;
    }
    if (x != 0.0) components_[kept++] = x;
    size_ = kept;
  }
  // Adds sign * x * y * z exactly.
  void addProduct(int sign, double x, double y, double z) {
    const Split xy = twoProduct(x, y);
    const Split high = twoProduct(xy.value, z);
    const Split low = twoProduct(xy.error, z);
    add(sign * high.value);
    add(sign * high.error);
    add(sign * low.value);
    add(sign * low.error);
  }
  void addProduct(int sign, double x, double y) {
    const Split xy = twoProduct(x, y);
    add(sign * xy.value);
    add(sign * xy.error);
  }
  int sign() const {
    if (size_ == 0) return 0;
    return components_[size_ - 1] > 0.0 ? 1 : -1;
  }

 private:
  std::array<double, kCapacity> components_;
  int size_ = 0;
};

// Expansion arithmetic is exact when no product of differences underflows or overflows. With
// every nonzero coordinate in [2^-300, 2^300], every coordinate, difference part and product is a
// multiple of 2^-352, 2^-704 and 2^-1056 (each >= 2^-1074, the smallest subnormal) and below
// 2^903: nothing is lost.
bool expansionIsExact(double x) {
  const double m = std::fabs(x);
  return m == 0.0 || (m >= 0x1p-300 && m <= 0x1p300);
}

// The parts of a - b: value and error, both possibly zero.
std::array<double, 2> differenceParts(double a, double b) {
  const Split d = twoSum(a, -b);
  return {d.value, d.error};
}

int rationalSign(const mpq_class& value) { return sgn(value); }

}  // namespace

int exactOrient2dSign(const Vec2& a, const Vec2& b, const Vec2& c) {
  assert(a.allFinite() && b.allFinite() && c.allFinite());
  bool expansionsSuffice = true;
  for (const Vec2* p : {&a, &b, &c}) {
    for (int k = 0; k < 2; ++k) expansionsSuffice = expansionsSuffice && expansionIsExact((*p)[k]);
  }
  if (!expansionsSuffice) {
    const mpq_class ux = mpq_class(b.x()) - mpq_class(a.x()), uy = mpq_class(b.y()) - mpq_class(a.y());
    const mpq_class vx = mpq_class(c.x()) - mpq_class(a.x()), vy = mpq_class(c.y()) - mpq_class(a.y());
    return rationalSign(mpq_class(ux * vy - uy * vx));
  }
  // det = ux vy - uy vx, every factor a two-part difference: 2 terms x 4 part products x 2 parts.
  const std::array<double, 2> ux = differenceParts(b.x(), a.x()), uy = differenceParts(b.y(), a.y());
  const std::array<double, 2> vx = differenceParts(c.x(), a.x()), vy = differenceParts(c.y(), a.y());
  ExactSum<16> det;
  for (double p : ux) {
    for (double q : vy) det.addProduct(1, p, q);
  }
  for (double p : uy) {
    for (double q : vx) det.addProduct(-1, p, q);
  }
  return det.sign();
}

int exactOrient3dSign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  assert(a.allFinite() && b.allFinite() && c.allFinite() && d.allFinite());
  bool expansionsSuffice = true;
  for (const Vec3* p : {&a, &b, &c, &d}) {
    for (int k = 0; k < 3; ++k) expansionsSuffice = expansionsSuffice && expansionIsExact((*p)[k]);
  }
  if (!expansionsSuffice) {
    mpq_class u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = mpq_class(b[k]) - mpq_class(a[k]);
      v[k] = mpq_class(c[k]) - mpq_class(a[k]);
      w[k] = mpq_class(d[k]) - mpq_class(a[k]);
    }
    return rationalSign(mpq_class(u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
                                  u[2] * (v[0] * w[1] - v[1] * w[0])));
  }
  std::array<double, 2> u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = differenceParts(b[k], a[k]);
    v[k] = differenceParts(c[k], a[k]);
    w[k] = differenceParts(d[k], a[k]);
  }
  // det[u, v, w] = sum over the permutations (p, q, r) of (0, 1, 2) of sign * u_p v_q w_r:
  // 6 terms x 8 part products x 4 parts each.
  struct Term {
    int sign, p, q, r;
  };
  constexpr Term kTerms[6] = {{1, 0, 1, 2}, {1, 1, 2, 0}, {1, 2, 0, 1}, {-1, 0, 2, 1}, {-1, 2, 1, 0}, {-1, 1, 0, 2}};
  ExactSum<192> det;
  for (const Term& term : kTerms) {
    for (double x : u[term.p]) {
      if (x == 0.0) continue;
      for (double y : v[term.q]) {
        if (y == 0.0) continue;
        for (double z : w[term.r]) {
          if (z != 0.0) det.addProduct(term.sign, x, y, z);
        }
      }
    }
  }
  return det.sign();
}

}  // namespace weft
