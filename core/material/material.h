#pragma once
// A cloth material: area density, membrane elasticity and bending. Loaded from a preset in
// presets/materials/ (Weft's JSON format) or given inline in a scene.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "material/elasticity.h"
#include "tearing/tear_table.h"

namespace weft {

struct BendingSettings {
  enum class Model { None, Constant, Measured };
  Model model = Model::Constant;
  double stiffness = 1e-5;  // constant bending stiffness k_e (N*m)
  // Measured stiffness k_e (N*m) by edge direction in material space (rows: 0, 45, 90 deg from U)
  // and by curvature (columns: alpha = 0, 5, 10, 15, 20 1/m), as FORMAT.md describes.
  std::array<std::array<double, 5>, 3> measured{};
  double stiffnessScale = 1.0;  // multiplies every bending stiffness

  // Compares every field, including those the chosen model does not use.
  friend bool operator==(const BendingSettings&, const BendingSettings&) = default;
};

struct Material {
  std::string name;            // preset name, e.g. "royal-target"
  std::string source;          // where the numbers come from (paper, data set)
  double areaDensity = 0.2;    // kg/m^2
  ElasticitySettings elasticity;
  BendingSettings bending;
  std::optional<TearTable> tearTable;  // none: the cloth never tears

  friend bool operator==(const Material&, const Material&) = default;
};

// Parses a material object. `file` and `path` name where it came from in error messages
// (e.g. "presets/materials/denim.json", "/cloths/0/material"). Throws InputError.
Material parseMaterial(const nlohmann::json& j, const std::string& file, const std::string& path);
nlohmann::json materialToJson(const Material& m);

// Loads presets/materials/<name>.json, searching `presetDirs` in order; `found`, when given, is
// set to the file read. Throws InputError.
Material loadMaterialPreset(const std::string& name, const std::vector<std::filesystem::path>& presetDirs,
                            const std::string& referencingFile, const std::string& referencingField,
                            std::filesystem::path* found = nullptr);
Material loadMaterialFile(const std::filesystem::path& file);

}  // namespace weft
