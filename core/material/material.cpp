// Weft's material JSON format (presets/materials/README.md): strict parsing, writing, and preset
// lookup. Every rejection names the file and the JSON pointer of the offending field.
#include "material/material.h"

#include <algorithm>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "util/input_error.h"
#include "util/json_fields.h"
#include "util/json_text.h"

namespace weft {
namespace {

using nlohmann::json;

// The fixed labels of the self-describing measured blocks; a file must repeat them exactly, so a
// file written for another layout cannot be read by accident.
constexpr std::array<const char*, 4> kCoefficientNames{"c11", "c12", "c22", "c33"};
constexpr std::array<double, 5> kDirectionsDeg{0, 22.5, 45, 67.5, 90};
constexpr std::array<double, 3> kBendingEdgeDirectionsDeg{0, 45, 90};
constexpr std::array<double, 5> kBendingCurvaturesPerM{0, 5, 10, 15, 20};

// Material messages name the kind of a wrong value ("got a string"), as the format has always done.
constexpr GotStyle kGot = GotStyle::Kind;

double stiffnessScale(const FieldReader& r) {
  return r.number("stiffness_scale", 1.0, Bound::Positive, "the multiplier of every stiffness");
}

std::string modelName(const FieldReader& r, const std::vector<std::string>& models) {
  const std::string expected = "one of: " + joinNames(models);
  const std::string model = r.requiredString("model", "the model, " + expected);
  if (std::find(models.begin(), models.end(), model) == models.end()) {
    r.fail(r.pointer("model"), "unknown model \"" + model + "\"; expected " + expected);
  }
  return model;
}

ElasticitySettings parseElasticity(const json& j, const std::string& pointer, const std::string& file) {
  const FieldReader r(j, pointer, file, kGot);
  ElasticitySettings out;
  const std::string model = modelName(r, {"isotropic", "measured"});
  if (model == "isotropic") {
    r.allowOnly({"model", "young_modulus_n_per_m", "poisson_ratio", "stiffness_scale"});
    out.model = ElasticitySettings::Model::Isotropic;
    out.youngModulus =
        r.requiredNumber("young_modulus_n_per_m", Bound::Positive, "the membrane Young's modulus E*h in N/m");
    out.poissonRatio = r.requiredNumber("poisson_ratio", Bound::Finite, "the Poisson ratio");
    if (out.poissonRatio < 0.0 || out.poissonRatio >= 0.5) {
      r.fail(r.pointer("poisson_ratio"), "must be in [0, 0.5), " + got(json(out.poissonRatio)));
    }
  } else {
    r.allowOnly({"model", "units", "coefficients", "zero_strain", "direction_deg", "at_reference_stretch",
                 "reference_stretch", "stiffness_scale"});
    out.model = ElasticitySettings::Model::Measured;
    r.requireExactly("units", "N/m");
    r.requireExactly("coefficients", kCoefficientNames);
    r.requireExactly("direction_deg", kDirectionsDeg);
    const std::string row = "c11, c12, c22, c33 in N/m";
    out.measured.zeroStrain = r.numberRow<4>(r.required("zero_strain", "4 numbers: " + row), r.pointer("zero_strain"),
                                             "the zero-strain stiffness " + row);
    out.measured.directions = r.numberTable<5, 4>(
        r.required("at_reference_stretch", "5 rows (0, 22.5, 45, 67.5, 90 deg) of 4 numbers: " + row),
        r.pointer("at_reference_stretch"), "the stiffness at the reference stretch, " + row);
    out.measured.referenceStretch =
        r.requiredNumber("reference_stretch", Bound::Finite, "the principal stretch of the direction rows");
    if (out.measured.referenceStretch <= 1.0) {
      r.fail(r.pointer("reference_stretch"), "must be > 1 (a stretch), " + got(json(out.measured.referenceStretch)));
    }
  }
  out.stiffnessScale = stiffnessScale(r);
  return out;
}

BendingSettings parseBending(const json& j, const std::string& pointer, const std::string& file) {
  const FieldReader r(j, pointer, file, kGot);
  BendingSettings out;
  const std::string model = modelName(r, {"none", "constant", "measured"});
  if (model == "none") {
    r.allowOnly({"model"});
    out.model = BendingSettings::Model::None;
    return out;
  }
  if (model == "constant") {
    r.allowOnly({"model", "stiffness_n_m", "stiffness_scale"});
    out.model = BendingSettings::Model::Constant;
    out.stiffness = r.requiredNumber("stiffness_n_m", Bound::NonNegative, "the bending stiffness k_e in N*m");
  } else {
    r.allowOnly({"model", "units", "edge_direction_deg", "curvature_alpha_per_m", "stiffness", "stiffness_scale"});
    out.model = BendingSettings::Model::Measured;
    r.requireExactly("units", "N*m");
    r.requireExactly("edge_direction_deg", kBendingEdgeDirectionsDeg);
    r.requireExactly("curvature_alpha_per_m", kBendingCurvaturesPerM);
    const std::string what = "bending stiffness k_e in N*m at alpha = 0, 5, 10, 15, 20 1/m";
    const std::string table = r.pointer("stiffness");
    out.measured = r.numberTable<3, 5>(r.required("stiffness", "3 rows (edges at 0, 45, 90 deg) of 5 numbers: " + what),
                                       table, "the " + what);
    // Negative bending stiffness has no physical meaning, unlike negative stretching samples.
    for (size_t i = 0; i < 3; ++i) {
      for (size_t k = 0; k < 5; ++k) {
        if (out.measured[i][k] < 0.0) {
          r.fail(childPointer(childPointer(table, i), k),
                 "the " + what + " must be >= 0, " + got(json(out.measured[i][k])));
        }
      }
    }
  }
  out.stiffnessScale = stiffnessScale(r);
  return out;
}

json rowToJson(const auto& row) { return json(std::vector<double>(row.begin(), row.end())); }

json elasticityToJson(const ElasticitySettings& e) {
  json out;
  if (e.model == ElasticitySettings::Model::Isotropic) {
    out = {{"model", "isotropic"}, {"young_modulus_n_per_m", e.youngModulus}, {"poisson_ratio", e.poissonRatio}};
  } else {
    json rows = json::array();
    for (const auto& row : e.measured.directions) rows.push_back(rowToJson(row));
    out = {{"model", "measured"},
           {"units", "N/m"},
           {"coefficients", kCoefficientNames},
           {"zero_strain", rowToJson(e.measured.zeroStrain)},
           {"direction_deg", kDirectionsDeg},
           {"at_reference_stretch", rows},
           {"reference_stretch", e.measured.referenceStretch}};
  }
  if (e.stiffnessScale != 1.0) out["stiffness_scale"] = e.stiffnessScale;
  return out;
}

json bendingToJson(const BendingSettings& b) {
  json out;
  switch (b.model) {
    case BendingSettings::Model::None:
      return {{"model", "none"}};
    case BendingSettings::Model::Constant:
      out = {{"model", "constant"}, {"stiffness_n_m", b.stiffness}};
      break;
    case BendingSettings::Model::Measured: {
      json rows = json::array();
      for (const auto& row : b.measured) rows.push_back(rowToJson(row));
      out = {{"model", "measured"},
             {"units", "N*m"},
             {"edge_direction_deg", kBendingEdgeDirectionsDeg},
             {"curvature_alpha_per_m", kBendingCurvaturesPerM},
             {"stiffness", rows}};
      break;
    }
  }
  if (b.stiffnessScale != 1.0) out["stiffness_scale"] = b.stiffnessScale;
  return out;
}

std::vector<std::string> availablePresets(const std::vector<std::filesystem::path>& presetDirs) {
  std::set<std::string> names;
  for (const auto& dir : presetDirs) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      if (entry.path().extension() == ".json") names.insert(entry.path().stem().string());
    }
  }
  return {names.begin(), names.end()};
}

}  // namespace

Material parseMaterial(const nlohmann::json& j, const std::string& file, const std::string& path) {
  const FieldReader r(j, path, file, {"name", "source", "area_density_kg_m2", "elasticity", "bending", "tear_table"},
                      kGot);
  Material m;
  // name and source are optional inline (a scene's own material); preset files require them.
  if (r.has("name")) m.name = r.requiredString("name", "the material's name");
  if (r.has("source")) m.source = r.requiredString("source", "where the numbers come from");
  m.areaDensity = r.requiredNumber("area_density_kg_m2", Bound::Positive, "the area density in kg/m^2");
  m.elasticity = parseElasticity(r.required("elasticity", "the membrane model, an object"), r.pointer("elasticity"), file);
  m.bending = parseBending(r.required("bending", "the bending model, an object"), r.pointer("bending"), file);
  if (r.has("tear_table")) m.tearTable = parseTearTable(r.at("tear_table"), file, r.pointer("tear_table"));
  return m;
}

nlohmann::json materialToJson(const Material& m) {
  json out;
  if (!m.name.empty()) out["name"] = m.name;
  if (!m.source.empty()) out["source"] = m.source;
  out["area_density_kg_m2"] = m.areaDensity;
  out["elasticity"] = elasticityToJson(m.elasticity);
  out["bending"] = bendingToJson(m.bending);
  if (m.tearTable) out["tear_table"] = tearTableToJson(*m.tearTable);
  return out;
}

Material loadMaterialFile(const std::filesystem::path& file) {
  const std::string fileName = file.string();
  const json j = readJsonFile(file, "the material file");
  // A material file is a preset: it must say what it is and where its numbers come from.
  const FieldReader r(j, "", fileName, kGot);
  r.requiredString("name", "the preset's name");
  r.requiredString("source", "where the numbers come from (paper, data set)");
  return parseMaterial(j, fileName, "");
}

Material loadMaterialPreset(const std::string& name, const std::vector<std::filesystem::path>& presetDirs,
                            const std::string& referencingFile, const std::string& referencingField,
                            std::filesystem::path* found) {
  const std::vector<std::string> available = availablePresets(presetDirs);
  const bool plainName = !name.empty() && name.find_first_of("/\\") == std::string::npos && name != "." && name != "..";
  if (plainName) {
    for (const auto& dir : presetDirs) {
      const std::filesystem::path file = dir / (name + ".json");
      std::error_code error;  // a name too long for the file system is simply not there
      if (!std::filesystem::is_regular_file(file, error)) continue;
      Material m = loadMaterialFile(file);
      if (m.name != name) {
        throw InputError(file.string(), "/name",
                         "is '" + echo(m.name) + "' but the preset is looked up as '" + echo(name) + "'; they must match");
      }
      if (found != nullptr) *found = file;
      return m;
    }
  }
  std::vector<std::string> dirs;
  for (const auto& dir : presetDirs) dirs.push_back(dir.string());
  throw InputError(referencingFile, referencingField,
                   "unknown material preset '" + echo(name) + "'; available presets: " +
                       (available.empty() ? std::string("none") : joinNames(available)) +
                       " (searched: " + joinNames(dirs) + ")");
}

}  // namespace weft
