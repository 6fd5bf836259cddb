#pragma once
// Membrane constitutive law in the cloth's weft/warp frame (thesis §2.2 and §2.5).
//
// Strain is the Green strain written as a 3-vector e = (e_uu, e_vv, gamma_uv) with the
// engineering shear gamma_uv = U.V (thesis Eq. 2.29-2.31); stress is its work conjugate
// s = (s_uu, s_vv, s_uv) in N/m, so that the energy per unit rest area is psi(e) and s = dpsi/de.
//
// Isotropic: psi = 1/2 e^T E e with E from Young's modulus and Poisson ratio (thesis Eq. 2.11).
// Measured (Wang, Ramamoorthi & O'Brien 2011): psi = 1/2 e^T C(e) e, where C depends on the
// principal stretch and its direction as the thesis and FORMAT.md describe. Because C varies with
// the strain, the stress is the true derivative of psi (it carries dC/de terms), which keeps the
// force conservative: energy tests, Newton line search and energy reports all stay meaningful.
#include <array>

#include <Eigen/Core>

namespace weft {

// One measured 4-vector as stored in the data files: (c11, c12, c22, c33) in N/m.
using StretchCoefficients = std::array<double, 4>;

struct MeasuredElasticity {
  StretchCoefficients zeroStrain{};                // row 0: the sample at zero strain
  std::array<StretchCoefficients, 5> directions{};  // rows 1-5: principal stretch at 0, 22.5, 45, 67.5, 90 deg from U
  double referenceStretch = 7.0 / 6.0;             // principal stretch lambda at which rows 1-5 were measured

  friend bool operator==(const MeasuredElasticity&, const MeasuredElasticity&) = default;
};

struct ElasticitySettings {
  enum class Model { Isotropic, Measured };
  Model model = Model::Isotropic;
  double youngModulus = 5000.0;  // isotropic membrane Young's modulus E*h (N/m)
  double poissonRatio = 0.3;     // isotropic Poisson ratio, in [0, 0.5)
  MeasuredElasticity measured;   // used when model == Measured
  double stiffnessScale = 1.0;   // multiplies every stiffness (a scene-side knob, like ARCSim's stretching_mult)

  // Compares every field, including those the chosen model does not use.
  friend bool operator==(const ElasticitySettings&, const ElasticitySettings&) = default;
};

struct ElasticityResponse {
  double energyDensity = 0.0;                     // psi (J/m^2)
  Eigen::Vector3d stress = Eigen::Vector3d::Zero();   // dpsi/de (N/m)
  Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();  // d^2 psi/de^2 (N/m), symmetric, may be indefinite
};

// The settings in the form every evaluation reads, prepared once for many strains (a cloth step
// evaluates thousands of triangles with the same settings): the measured samples clamped and
// limited (decision 2 in elasticity.cpp) with their direction mean, or the constant matrix E of
// Eq. 2.11. Evaluating with it gives the same numbers as evaluating with the settings.
struct PreparedElasticity {
  ElasticitySettings::Model model = ElasticitySettings::Model::Isotropic;
  double stiffnessScale = 1.0;
  double referenceStretch = 7.0 / 6.0;
  Eigen::Matrix3d isotropicMatrix = Eigen::Matrix3d::Zero();  // E of Eq. 2.11, stiffnessScale applied (N/m)
  // Usable measured samples (c11, c12, c22, c33) in N/m, before stiffnessScale.
  Eigen::Vector4d zeroStrain = Eigen::Vector4d::Zero();
  std::array<Eigen::Vector4d, 5> directions{};
  Eigen::Vector4d directionMean = Eigen::Vector4d::Zero();  // Lavg, the mean of L over [0, 90] deg
};

PreparedElasticity prepareElasticity(const ElasticitySettings& settings);

// Evaluates psi, its gradient and (when wantTangent) its Hessian at the strain e.
ElasticityResponse evaluateElasticity(const PreparedElasticity& law, const Eigen::Vector3d& strain, bool wantTangent);
ElasticityResponse evaluateElasticity(const ElasticitySettings& settings, const Eigen::Vector3d& strain,
                                      bool wantTangent);

// The matrix C(e) alone (3x3, acting on (e_uu, e_vv, gamma_uv), stiffnessScale applied), for plots and
// tests: the measured-data C at this strain, or the constant E of Eq. 2.11 for the isotropic model.
Eigen::Matrix3d elasticityMatrix(const ElasticitySettings& settings, const Eigen::Vector3d& strain);

}  // namespace weft
