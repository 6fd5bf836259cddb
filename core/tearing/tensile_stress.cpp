#include "tearing/tensile_stress.h"

#include <algorithm>
#include <cmath>

#include "forces/membrane.h"
#include "forces/membrane_ahead.h"
#include "sim/cloth.h"

namespace weft {

Mat2 tensilePart(const Mat2& stress) {
  // Closed form (Mohr's circle): principal stresses mean +- radius, and the projector onto the
  // larger one's direction, P = (S - lambda2 I) / (lambda1 - lambda2).
  const double mean = 0.5 * (stress(0, 0) + stress(1, 1));
  const double half = 0.5 * (stress(0, 0) - stress(1, 1));
  const double radius = std::sqrt(half * half + stress(0, 1) * stress(0, 1));
  const double larger = mean + radius, smaller = mean - radius;
  if (smaller >= 0.0) return stress;                         // all tension
  if (larger <= 0.0) return Mat2::Zero();                    // all compression
  // One principal stress of each sign (radius > 0): keep the tensile one.
  return larger * (stress - smaller * Mat2::Identity()) / (2.0 * radius);
}

Mat2 weftToMaterial(double weftAngleRad) {
  // The weft/warp axes are the material axes turned by the weft angle: R's columns are U and V in
  // material coordinates.
  const double c = std::cos(weftAngleRad), s = std::sin(weftAngleRad);
  Mat2 R;
  R << c, -s, s, c;
  return R;
}

Mat2 stressInMaterialFrame(const Vec3& stressUV, const Mat2& weftToMaterial) {
  // A tensor transforms as R S R^T.
  Mat2 S;
  S << stressUV[0], stressUV[2], stressUV[2], stressUV[1];
  return weftToMaterial * S * weftToMaterial.transpose();
}

Mat2 stressInMaterialFrame(const Vec3& stressUV, double weftAngleRad) {
  return stressInMaterialFrame(stressUV, weftToMaterial(weftAngleRad));
}

namespace {

// sigma+ in the material frame of a membrane stress in the weft/warp frame.
Mat2 tensileOf(const Vec3& stressUV, const Mat2& rotation) {
  const Mat2 stress = stressInMaterialFrame(stressUV, rotation);
  // A non-finite stress (a blown-up step) must not tear: it is treated as no stress.
  return stress.allFinite() ? tensilePart(stress) : Mat2::Zero();
}

Mat2 tensileStressOf(const Cloth& cloth, const PreparedElasticity& law, const Mat2& rotation, int t,
                     MembraneContribution& contribution) {
  const ClothMesh& mesh = cloth.mesh;
  const MembraneElement& element = cloth.membranes[t];
  evaluateMembrane(element, law, mesh.x[element.v[0]], mesh.x[element.v[1]], mesh.x[element.v[2]], HessianMode::None,
                   contribution);
  return tensileOf(contribution.stress, rotation);
}

}  // namespace

void tensileStresses(const Cloth& cloth, const MembraneAhead* ahead, std::vector<Mat2>& outStress) {
  const PreparedElasticity law = prepareElasticity(cloth.material.elasticity);
  outStress.resize(cloth.mesh.tris.size());
  const Mat2 rotation = weftToMaterial(cloth.weftAngleRad);  // once: a sine and cosine per triangle cost a tenth
  if (ahead != nullptr && !ahead->serves(cloth.material.elasticity)) ahead = nullptr;
  MembraneContribution contribution;
  for (int t = 0; t < cloth.mesh.triangleCount(); ++t) {
    const MembraneElement& element = cloth.membranes[t];
    const std::vector<Vec3>& x = cloth.mesh.x;
    const MembraneContribution* found =
        ahead != nullptr ? ahead->find(t, element, x[element.v[0]], x[element.v[1]], x[element.v[2]]) : nullptr;
    outStress[t] = found != nullptr ? tensileOf(found->stress, rotation) : tensileStressOf(cloth, law, rotation, t, contribution);
  }
}

void tensileStresses(const Cloth& cloth, std::vector<Mat2>& outStress) { tensileStresses(cloth, nullptr, outStress); }

void tensileStresses(const Cloth& cloth, const std::vector<int>& triangles, std::vector<Mat2>& ioStress) {
  const PreparedElasticity law = prepareElasticity(cloth.material.elasticity);
  ioStress.resize(cloth.mesh.tris.size(), Mat2::Zero());
  const Mat2 rotation = weftToMaterial(cloth.weftAngleRad);
  MembraneContribution contribution;
  for (int t : triangles) ioStress[t] = tensileStressOf(cloth, law, rotation, t, contribution);
}

}  // namespace weft
