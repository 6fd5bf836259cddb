#pragma once
// Small scenes and materials built in code for the core tests.
#include <string>

#include "material/material.h"
#include "scene/scene.h"

namespace weft::test {

inline std::string presetPath(const std::string& name) {
  return std::string(WEFT_SOURCE_DIR) + "/presets/materials/" + name + ".json";
}

inline Material isotropicMaterial(double youngModulus = 2000.0, double poisson = 0.3, double bending = 1e-5) {
  Material m;
  m.name = "test-isotropic";
  m.areaDensity = 0.2;
  m.elasticity.model = ElasticitySettings::Model::Isotropic;
  m.elasticity.youngModulus = youngModulus;
  m.elasticity.poissonRatio = poisson;
  m.bending.model = bending > 0 ? BendingSettings::Model::Constant : BendingSettings::Model::None;
  m.bending.stiffness = bending;
  return m;
}

// A square sheet hanging from its two top corners, in the world x-y plane.
inline Scene hangingSheet(const Material& material, int resolution, double dt) {
  Scene scene;
  scene.name = "test-hanging-sheet";
  ClothSpec cloth;
  cloth.name = "sheet";
  GridSpec grid;
  grid.width = 1.0;
  grid.height = 1.0;
  grid.resolutionX = resolution;
  grid.resolutionY = resolution;
  cloth.grid = grid;
  cloth.material = material;
  cloth.materialName = material.name;
  PinGroup corners;
  corners.corners = {"top_left", "top_right"};
  cloth.pins.push_back(corners);
  scene.cloths.push_back(cloth);
  scene.solver.dt = dt;
  return scene;
}

}  // namespace weft::test
