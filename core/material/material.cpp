// Weft's material JSON format (presets/materials/README.md): strict parsing, writing, and preset
// lookup. Every rejection names the file and the JSON pointer of the offending field.
#include "material/material.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <set>
#include <string_view>

#include <nlohmann/json.hpp>

#include "util/input_error.h"

namespace weft {
namespace {

using nlohmann::json;

// The fixed labels of the self-describing measured blocks; a file must repeat them exactly, so a
// file written for another layout cannot be read by accident.
constexpr std::array<const char*, 4> kCoefficientNames{"c11", "c12", "c22", "c33"};
constexpr std::array<double, 5> kDirectionsDeg{0, 22.5, 45, 67.5, 90};
constexpr std::array<double, 3> kBendingEdgeDirectionsDeg{0, 45, 90};
constexpr std::array<double, 5> kBendingCurvaturesPerM{0, 5, 10, 15, 20};

// Where a value sits: the file and its JSON pointer, for error messages.
struct Location {
  const std::string& file;
  std::string pointer;

  Location child(std::string_view key) const {
    std::string escaped;  // RFC 6901: '~' -> "~0", '/' -> "~1"
    for (char ch : key) {
      if (ch == '~') escaped += "~0";
      else if (ch == '/') escaped += "~1";
      else escaped += ch;
    }
    return {file, pointer + "/" + escaped};
  }
  Location child(size_t index) const { return {file, pointer + "/" + std::to_string(index)}; }

  [[noreturn]] void fail(const std::string& what) const { throw InputError(file, pointer, what); }
};

std::string describe(const json& value) {
  if (value.is_array()) return "an array of " + std::to_string(value.size());
  return std::string("a ") + value.type_name();
}

std::string joined(const auto& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + std::string(item);
  return out;
}

void requireObject(const json& value, const Location& at) {
  if (!value.is_object()) at.fail("expected a JSON object, got " + describe(value));
}

void rejectUnknownKeys(const json& object, const Location& at, std::initializer_list<const char*> allowed) {
  for (const auto& item : object.items()) {
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* key) { return item.key() == key; })) {
      at.child(item.key()).fail("unknown key '" + item.key() + "' (allowed here: " + joined(allowed) + ")");
    }
  }
}

const json& requiredField(const json& object, const Location& at, const char* key, const std::string& expected) {
  const auto it = object.find(key);
  if (it == object.end()) at.child(key).fail("missing required field '" + std::string(key) + "' (" + expected + ")");
  return *it;
}

double finiteNumber(const json& value, const Location& at, const std::string& expected) {
  if (!value.is_number()) at.fail("expected " + expected + ", got " + describe(value));
  const double x = value.get<double>();
  if (!std::isfinite(x)) at.fail("expected a finite number (" + expected + ")");
  return x;
}

double numberField(const json& object, const Location& at, const char* key, const std::string& expected) {
  return finiteNumber(requiredField(object, at, key, expected), at.child(key), expected);
}

double positiveNumberField(const json& object, const Location& at, const char* key, const std::string& expected) {
  const double x = numberField(object, at, key, expected);
  if (x <= 0.0) at.child(key).fail("must be > 0 (" + expected + "), got " + std::to_string(x));
  return x;
}

std::string stringField(const json& object, const Location& at, const char* key, const std::string& expected) {
  const json& value = requiredField(object, at, key, expected);
  if (!value.is_string() || value.get<std::string>().empty()) {
    at.child(key).fail("expected a non-empty string (" + expected + "), got " + describe(value));
  }
  return value.get<std::string>();
}

template <size_t N>
std::array<double, N> numberRow(const json& value, const Location& at, const std::string& expected) {
  if (!value.is_array() || value.size() != N) {
    at.fail("expected an array of " + std::to_string(N) + " numbers (" + expected + "), got " + describe(value));
  }
  std::array<double, N> row{};
  for (size_t i = 0; i < N; ++i) row[i] = finiteNumber(value[i], at.child(i), "a number (" + expected + ")");
  return row;
}

template <size_t Rows, size_t Cols>
std::array<std::array<double, Cols>, Rows> numberTable(const json& value, const Location& at,
                                                       const std::string& expected) {
  if (!value.is_array() || value.size() != Rows) {
    at.fail("expected an array of " + std::to_string(Rows) + " rows of " + std::to_string(Cols) + " numbers (" +
            expected + "), got " + describe(value));
  }
  std::array<std::array<double, Cols>, Rows> table{};
  for (size_t i = 0; i < Rows; ++i) table[i] = numberRow<Cols>(value[i], at.child(i), expected);
  return table;
}

// A label field that must hold exactly the given value (units, coefficient names, sample axes).
void requireExactly(const json& object, const Location& at, const char* key, const json& expected) {
  const json& value = requiredField(object, at, key, "must be " + expected.dump());
  if (value != expected) at.child(key).fail("must be exactly " + expected.dump() + ", got " + value.dump());
}

double stiffnessScale(const json& object, const Location& at) {
  if (!object.contains("stiffness_scale")) return 1.0;
  return positiveNumberField(object, at, "stiffness_scale", "a multiplier of every stiffness, > 0");
}

std::string modelName(const json& object, const Location& at, std::initializer_list<const char*> models) {
  const std::string expected = "one of: " + joined(models);
  const std::string model = stringField(object, at, "model", expected);
  if (std::none_of(models.begin(), models.end(), [&](const char* m) { return model == m; })) {
    at.child("model").fail("unknown model '" + model + "' (expected " + expected + ")");
  }
  return model;
}

ElasticitySettings parseElasticity(const json& j, const Location& at) {
  requireObject(j, at);
  ElasticitySettings out;
  const std::string model = modelName(j, at, {"isotropic", "measured"});
  if (model == "isotropic") {
    rejectUnknownKeys(j, at, {"model", "young_modulus_n_per_m", "poisson_ratio", "stiffness_scale"});
    out.model = ElasticitySettings::Model::Isotropic;
    out.youngModulus = positiveNumberField(j, at, "young_modulus_n_per_m", "membrane Young's modulus E*h in N/m, > 0");
    out.poissonRatio = numberField(j, at, "poisson_ratio", "Poisson ratio in [0, 0.5)");
    if (out.poissonRatio < 0.0 || out.poissonRatio >= 0.5) {
      at.child("poisson_ratio").fail("must be in [0, 0.5), got " + std::to_string(out.poissonRatio));
    }
  } else {
    rejectUnknownKeys(j, at,
                      {"model", "units", "coefficients", "zero_strain", "direction_deg", "at_reference_stretch",
                       "reference_stretch", "stiffness_scale"});
    out.model = ElasticitySettings::Model::Measured;
    requireExactly(j, at, "units", "N/m");
    requireExactly(j, at, "coefficients", kCoefficientNames);
    requireExactly(j, at, "direction_deg", kDirectionsDeg);
    const std::string row = "c11, c12, c22, c33 in N/m";
    out.measured.zeroStrain = numberRow<4>(requiredField(j, at, "zero_strain", "4 numbers: " + row),
                                           at.child("zero_strain"), row);
    out.measured.directions = numberTable<5, 4>(
        requiredField(j, at, "at_reference_stretch", "5 rows (0, 22.5, 45, 67.5, 90 deg) of 4 numbers: " + row),
        at.child("at_reference_stretch"), row);
    out.measured.referenceStretch =
        numberField(j, at, "reference_stretch", "principal stretch of the direction rows, > 1");
    if (out.measured.referenceStretch <= 1.0) {
      at.child("reference_stretch").fail("must be > 1 (a stretch), got " + std::to_string(out.measured.referenceStretch));
    }
  }
  out.stiffnessScale = stiffnessScale(j, at);
  return out;
}

BendingSettings parseBending(const json& j, const Location& at) {
  requireObject(j, at);
  BendingSettings out;
  const std::string model = modelName(j, at, {"none", "constant", "measured"});
  if (model == "none") {
    rejectUnknownKeys(j, at, {"model"});
    out.model = BendingSettings::Model::None;
    return out;
  }
  if (model == "constant") {
    rejectUnknownKeys(j, at, {"model", "stiffness_n_m", "stiffness_scale"});
    out.model = BendingSettings::Model::Constant;
    out.stiffness = numberField(j, at, "stiffness_n_m", "bending stiffness k_e in N*m, >= 0");
    if (out.stiffness < 0.0) at.child("stiffness_n_m").fail("must be >= 0, got " + std::to_string(out.stiffness));
  } else {
    rejectUnknownKeys(j, at,
                      {"model", "units", "edge_direction_deg", "curvature_alpha_per_m", "stiffness", "stiffness_scale"});
    out.model = BendingSettings::Model::Measured;
    requireExactly(j, at, "units", "N*m");
    requireExactly(j, at, "edge_direction_deg", kBendingEdgeDirectionsDeg);
    requireExactly(j, at, "curvature_alpha_per_m", kBendingCurvaturesPerM);
    const std::string what = "bending stiffness k_e in N*m at alpha = 0, 5, 10, 15, 20 1/m";
    const Location table = at.child("stiffness");
    out.measured = numberTable<3, 5>(
        requiredField(j, at, "stiffness", "3 rows (edges at 0, 45, 90 deg) of 5 numbers: " + what), table, what);
    for (size_t i = 0; i < 3; ++i) {
      for (size_t k = 0; k < 5; ++k) {
        if (out.measured[i][k] < 0.0) {
          table.child(i).child(k).fail("must be >= 0 (" + what + "), got " + std::to_string(out.measured[i][k]));
        }
      }
    }
  }
  out.stiffnessScale = stiffnessScale(j, at);
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
  const Location at{file, path};
  requireObject(j, at);
  rejectUnknownKeys(j, at, {"name", "source", "area_density_kg_m2", "elasticity", "bending"});
  Material m;
  // name and source are optional inline (a scene's own material); preset files require them.
  if (j.contains("name")) m.name = stringField(j, at, "name", "the material's name");
  if (j.contains("source")) m.source = stringField(j, at, "source", "where the numbers come from");
  m.areaDensity = positiveNumberField(j, at, "area_density_kg_m2", "area density in kg/m^2, > 0");
  m.elasticity = parseElasticity(requiredField(j, at, "elasticity", "the membrane model, an object"),
                                 at.child("elasticity"));
  m.bending = parseBending(requiredField(j, at, "bending", "the bending model, an object"), at.child("bending"));
  return m;
}

nlohmann::json materialToJson(const Material& m) {
  json out;
  if (!m.name.empty()) out["name"] = m.name;
  if (!m.source.empty()) out["source"] = m.source;
  out["area_density_kg_m2"] = m.areaDensity;
  out["elasticity"] = elasticityToJson(m.elasticity);
  out["bending"] = bendingToJson(m.bending);
  return out;
}

Material loadMaterialFile(const std::filesystem::path& file) {
  const std::string fileName = file.string();
  std::ifstream in(file);
  if (!in) throw InputError(fileName, "", "cannot open the material file");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {  // a syntax error (with its position) or a number overflow
    throw InputError(fileName, "", std::string("invalid JSON: ") + e.what());
  }
  const Location at{fileName, ""};
  requireObject(j, at);
  // A material file is a preset: it must say what it is and where its numbers come from.
  stringField(j, at, "name", "the preset's name");
  stringField(j, at, "source", "where the numbers come from (paper, data set)");
  return parseMaterial(j, fileName, "");
}

Material loadMaterialPreset(const std::string& name, const std::vector<std::filesystem::path>& presetDirs,
                            const std::string& referencingFile, const std::string& referencingField) {
  const std::vector<std::string> available = availablePresets(presetDirs);
  const bool plainName = !name.empty() && name.find_first_of("/\\") == std::string::npos && name != "." && name != "..";
  if (plainName) {
    for (const auto& dir : presetDirs) {
      const std::filesystem::path file = dir / (name + ".json");
      if (!std::filesystem::is_regular_file(file)) continue;
      Material m = loadMaterialFile(file);
      if (m.name != name) {
        throw InputError(file.string(), "/name",
                         "is '" + m.name + "' but the preset is looked up as '" + name + "'; they must match");
      }
      return m;
    }
  }
  std::vector<std::string> dirs;
  for (const auto& dir : presetDirs) dirs.push_back(dir.string());
  throw InputError(referencingFile, referencingField,
                   "unknown material preset '" + name + "'; available presets: " +
                       (available.empty() ? std::string("none") : joined(available)) +
                       " (searched: " + joined(dirs) + ")");
}

}  // namespace weft
