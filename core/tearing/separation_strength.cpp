#include "tearing/separation_strength.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace weft {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The integral of the outward unit normal n(theta) = (cos, sin) from 0 to theta, up to a constant.
Vec2 g(double theta) { return Vec2(std::sin(theta), -std::cos(theta)); }

// `angle` moved by whole turns into [from, from + 2 pi).
double wrapFrom(double angle, double from) {
  double a = std::fmod(angle - from, kTwoPi);
  if (a < 0.0) a += kTwoPi;
  return from + a;
}

// The traction force on the vertex from the part of the fan inside the arc [from, from + length]
// (length <= 2 pi): each sector's overlap with the arc, at most two pieces when it wraps past the
// arc's start.
Vec2 arcForce(const VertexFan& fan, double from, double length) {
  Vec2 force = Vec2::Zero();
  const double to = from + length;
  for (const FanSector& sector : fan.sectors) {
    const double a = wrapFrom(sector.start, from);
    const double b = a + sector.span;
    if (a < to) force += sector.stress * (g(std::min(b, to)) - g(a));
    if (b > from + kTwoPi) force += sector.stress * (g(std::min(b - kTwoPi, to)) - g(from));
  }
  return force;
}

// Eq. 2.70-2.71 for the two sides' forces.
double balancedPull(const Vec2& q1, const Vec2& q2) {
  const double n1 = q1.norm(), n2 = q2.norm();
  if (!(n1 > 0.0) || !(n2 > 0.0) || !(q1.dot(q2) < 0.0)) return 0.0;
  const Vec2 direction = (q1 / n1 - q2 / n2).normalized();
  return std::min(q1.dot(direction), -q2.dot(direction));
}

}  // namespace

VertexFan vertexFan(const ClothMesh& mesh, int vertex, const std::vector<int>& around,
                    const std::vector<Mat2>& triangleStress) {
  VertexFan fan;
  fan.sectors.reserve(around.size());
  for (int t : around) {
    const Triangle& tri = mesh.tris[t];
    const int k = tri.v[0] == vertex ? 0 : tri.v[1] == vertex ? 1 : 2;
    const Vec2 first = tri.rest[(k + 1) % 3] - tri.rest[k];
    const Vec2 second = tri.rest[(k + 2) % 3] - tri.rest[k];
    FanSector sector;
    sector.start = std::atan2(first.y(), first.x());
    // Counter-clockwise triangles: the second edge is the first turned by the corner's angle.
    sector.span = std::atan2(first.x() * second.y() - first.y() * second.x(), first.dot(second));
    sector.stress = triangleStress[t];
    fan.sectors.push_back(sector);
    // The corner's first edge runs from v[k] to v[k+1] (Triangle::edge[k]); on a boundary, the
    // fan starts here.
    if (mesh.edges[tri.edge[k]].isBoundary()) {
      fan.closed = false;
      fan.openStart = sector.start;
    }
    fan.openSpan += sector.span;
  }
  if (fan.closed) fan.openSpan = kTwoPi;
  return fan;
}

double separationStrength(const VertexFan& fan, double angle) {
  if (fan.closed) {
    // Side 1 lies counter-clockwise of the line's direction, side 2 clockwise (Figure 2.9).
    const Vec2 q1 = arcForce(fan, angle, std::numbers::pi);
    const Vec2 q2 = arcForce(fan, angle + std::numbers::pi, std::numbers::pi);
    return 0.5 * balancedPull(q1, q2);
  }
  const double ray = wrapFrom(angle, fan.openStart);
  const double before = std::min(ray - fan.openStart, fan.openSpan);
  const Vec2 q1 = arcForce(fan, fan.openStart, before);
  const Vec2 q2 = arcForce(fan, fan.openStart + before, fan.openSpan - before);
  return balancedPull(q1, q2);
}

double separationStrengthBound(const VertexFan& fan) {
  double sum = 0.0;
  for (const FanSector& sector : fan.sectors) {
    // The largest principal value of a 2x2 symmetric tensor: mean + radius of Mohr's circle.
    const Mat2& s = sector.stress;
    const double mean = 0.5 * (s(0, 0) + s(1, 1));
    const double radius = std::hypot(0.5 * (s(0, 0) - s(1, 1)), s(0, 1));
    sum += std::max(0.0, mean + radius) * sector.span;
  }
  // |q1| + |q2| <= sum; zeta <= min(|q1|, |q2|) <= sum / 2, halved again at an interior vertex.
  return (fan.closed ? 0.25 : 0.5) * sum;
}

}  // namespace weft
