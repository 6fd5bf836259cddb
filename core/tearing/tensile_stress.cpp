#include "tearing/tensile_stress.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "forces/membrane.h"
#include "sim/cloth.h"

namespace weft {

Mat2 tensilePart(const Mat2& stress) {
  const Eigen::SelfAdjointEigenSolver<Mat2> eigen(stress);
  const Vec2 clamped = eigen.eigenvalues().cwiseMax(0.0);
  return eigen.eigenvectors() * clamped.asDiagonal() * eigen.eigenvectors().transpose();
}

Mat2 stressInMaterialFrame(const Vec3& stressUV, double weftAngleRad) {
  // The weft/warp axes are the material axes turned by the weft angle: R's columns are U and V in
  // material coordinates, and a tensor transforms as R S R^T.
  const double c = std::cos(weftAngleRad), s = std::sin(weftAngleRad);
  Mat2 R;
  R << c, -s, s, c;
  Mat2 S;
  S << stressUV[0], stressUV[2], stressUV[2], stressUV[1];
  return R * S * R.transpose();
}

void tensileStresses(const Cloth& cloth, std::vector<Mat2>& outStress) {
  const ClothMesh& mesh = cloth.mesh;
  const PreparedElasticity law = prepareElasticity(cloth.material.elasticity);
  outStress.resize(mesh.tris.size());
  MembraneContribution contribution;
  for (std::size_t t = 0; t < mesh.tris.size(); ++t) {
    const MembraneElement& element = cloth.membranes[t];
    evaluateMembrane(element, law, mesh.x[element.v[0]], mesh.x[element.v[1]], mesh.x[element.v[2]], HessianMode::None,
                     contribution);
    const Mat2 stress = stressInMaterialFrame(contribution.stress, cloth.weftAngleRad);
    // A non-finite stress (a blown-up step) must not tear: it is treated as no stress.
    outStress[t] = stress.allFinite() ? tensilePart(stress) : Mat2::Zero();
  }
}

}  // namespace weft
