#include "rigid/mass_properties.h"

#include <cassert>
#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "util/input_error.h"

namespace weft {

namespace {

// The three volume integrals over the solid, taken about `reference` (see the header).
struct VolumeIntegrals {
  Vec3 reference = Vec3::Zero();
  double volume = 0.0;               // ∫ 1
  Vec3 firstMoment = Vec3::Zero();   // ∫ (x - reference)
  Mat3 secondMoment = Mat3::Zero();  // ∫ (x - reference)(x - reference)ᵀ
};

Vec3 boundingBoxCentre(const TriangleMesh& mesh) {
  if (mesh.vertices.empty()) return Vec3::Zero();
  Vec3 low = mesh.vertices.front(), high = mesh.vertices.front();
  for (const Vec3& v : mesh.vertices) {
    low = low.cwiseMin(v);
    high = high.cwiseMax(v);
  }
  return 0.5 * (low + high);
}

VolumeIntegrals integrate(const TriangleMesh& mesh, bool withSecondMoment) {
  VolumeIntegrals sums;
  sums.reference = boundingBoxCentre(mesh);
  for (const std::array<int, 3>& t : mesh.triangles) {
    const Vec3 p = mesh.vertices[t[0]] - sums.reference;
    const Vec3 q = mesh.vertices[t[1]] - sums.reference;
    const Vec3 s = mesh.vertices[t[2]] - sums.reference;
    const double d = p.dot(q.cross(s));  // six times the signed tetrahedron's volume
    const Vec3 sum = p + q + s;
    sums.volume += d / 6.0;
    sums.firstMoment += (d / 24.0) * sum;
    if (withSecondMoment) {
      sums.secondMoment +=
          (d / 120.0) * (p * p.transpose() + q * q.transpose() + s * s.transpose() + sum * sum.transpose());
    }
  }
  return sums;
}

void requirePositiveVolume(double volume, const std::string& meshName) {
  if (volume > 0.0) return;
  std::ostringstream what;
  what << "encloses a volume of " << volume << " m^3; ";
  what << (volume < 0.0
               ? "its triangles are turned inward (clockwise seen from outside): reverse every triangle's vertex order"
               : "a solid needs a closed surface around a non-zero volume");
  throw InputError(meshName, "", what.str());
}

}  // namespace

double signedVolume(const TriangleMesh& mesh) { return integrate(mesh, /*withSecondMoment=*/false).volume; }

MassProperties computeMassProperties(const TriangleMesh& mesh, double density, const std::string& meshName) {
  assert(std::isfinite(density) && density > 0.0);
  const VolumeIntegrals sums = integrate(mesh, /*withSecondMoment=*/true);
  requirePositiveVolume(sums.volume, meshName);

  // Parallel-axis shift of the second moment from the reference point to the centre of mass.
  const Vec3 offset = sums.firstMoment / sums.volume;  // centre of mass - reference
  const Mat3 central = sums.secondMoment - sums.volume * offset * offset.transpose();

  MassProperties properties;
  properties.volume = sums.volume;
  properties.mass = density * sums.volume;
  properties.centreOfMass = sums.reference + offset;
  properties.inertia = density * (central.trace() * Mat3::Identity() - central);
  // The sum is symmetric in exact arithmetic; make it so in floating point too (eigen-solvers and
  // tests compare the two halves).
  properties.inertia = 0.5 * (properties.inertia + properties.inertia.transpose()).eval();
  return properties;
}

Vec3 recentreAtCentreOfMass(TriangleMesh& ioMesh, const std::string& meshName) {
  const VolumeIntegrals sums = integrate(ioMesh, /*withSecondMoment=*/false);
  requirePositiveVolume(sums.volume, meshName);
  const Vec3 centre = sums.reference + sums.firstMoment / sums.volume;
  for (Vec3& v : ioMesh.vertices) v -= centre;
  return centre;
}

}  // namespace weft
