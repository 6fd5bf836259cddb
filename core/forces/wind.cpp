// The flat-plate wind model described in wind.h.
#include "forces/wind.h"

#include <cassert>
#include <cmath>

#include <Eigen/Geometry>

namespace weft {

Vec3 windVelocityAt(const WindSpec& wind, double time) {
  return wind.velocity * (1.0 + wind.gustAmplitude * std::sin(2.0 * kPi * wind.gustFrequency * time));
}

void addWindForces(const ClothMesh& mesh, const WindSpec& wind, double time, std::vector<Vec3>& forces) {
  assert(static_cast<int>(forces.size()) == mesh.vertexCount());
  const Vec3 windVelocity = windVelocityAt(wind, time);
  for (const Triangle& t : mesh.tris) {
    const Vec3& xa = mesh.x[t.v[0]];
    const Vec3& xb = mesh.x[t.v[1]];
    const Vec3& xc = mesh.x[t.v[2]];
    const Vec3 areaNormal = (xb - xa).cross(xc - xa);  // |areaNormal| = 2 A
    const double doubleArea = areaNormal.norm();
    if (!(doubleArea > 0.0)) continue;  // a collapsed triangle has no normal and no area to catch wind
    const Vec3 n = areaNormal / doubleArea;
    const double area = 0.5 * doubleArea;

    const Vec3 relative = windVelocity - (mesh.v[t.v[0]] + mesh.v[t.v[1]] + mesh.v[t.v[2]]) / 3.0;
    const double speedSquared = relative.squaredNorm();
    if (!(speedSquared > 0.0)) continue;  // moving with the air
    const double normalSpeed = relative.dot(n);
    const double pressure = 0.5 * wind.airDensity * area;  // 1/2 rho A

    const Vec3 drag = pressure * wind.drag * normalSpeed * std::abs(normalSpeed) * n;
    // n minus its component along the relative wind, scaled by v_n: two-sided, zero edge-on and
    // face-on, of size sin(a) cos(a) |v|^2 in between.
    const Vec3 lift = pressure * wind.lift * std::sqrt(speedSquared) * normalSpeed *
                      (n - (normalSpeed / speedSquared) * relative);
    const Vec3 share = (drag + lift) / 3.0;
    for (int id : t.v) forces[id] += share;
  }
}

bool windEnabled(const WindSpec& wind) { return wind.velocity.squaredNorm() > 0.0; }

}  // namespace weft
