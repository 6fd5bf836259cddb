#include "scene_edits.h"

#include <algorithm>
#include <stdexcept>

#include "material/material.h"
#include "tearing/tear_table.h"

namespace weft::editor {

using nlohmann::json;

namespace {

json& clothJson(json& scene, int cloth) {
  json& cloths = scene.at("cloths");
  if (cloth < 0 || cloth >= static_cast<int>(cloths.size())) throw std::out_of_range("no cloth " + std::to_string(cloth));
  return cloths[static_cast<std::size_t>(cloth)];
}

const ClothSpec& clothSpec(const Scene& parsed, int cloth) {
  if (cloth < 0 || cloth >= static_cast<int>(parsed.cloths.size())) {
    throw std::out_of_range("no cloth " + std::to_string(cloth));
  }
  return parsed.cloths[static_cast<std::size_t>(cloth)];
}

// An edited copy no longer is the preset it came from: it loses the preset's name and says what
// it was made from, so a saved scene does not claim a preset's name for other numbers.
std::string editedSource(const std::string& name, const std::string& source) {
  if (name.empty()) return source;
  return "edited in Weft from " + name + (source.empty() ? std::string() : ": " + source);
}

TearTable currentTearTable(const Scene& parsed, int cloth, double defaultStrength) {
  const ClothSpec& spec = clothSpec(parsed, cloth);
  if (spec.material.tearTable) return *spec.material.tearTable;
  TearTable uniform;
  uniform.strength.assign(4, defaultStrength);
  uniform.unitNPerM = 30.0;  // the unit of the thesis' tables (presets/tear_tables/README.md)
  uniform.source = "uniform table made in Weft's editor";
  return uniform;
}

json inlineTable(TearTable table) {
  table.source = editedSource(table.name, table.source);
  table.name.clear();
  return tearTableToJson(table);
}

// The cloth's material inline, ready for one of its numbers to change.
json& inlineMaterial(json& scene, const Scene& parsed, int cloth) {
  json& c = clothJson(scene, cloth);
  if (!c.contains("material") || !c["material"].is_object()) {
    const ClothSpec& spec = clothSpec(parsed, cloth);
    Material material = spec.material;
    // The cloth's effective tear table stays where the scene can see it: on the cloth.
    if (material.tearTable && !c.contains("tear_table")) c["tear_table"] = tearTableToJson(*material.tearTable);
    material.tearTable.reset();
    material.source = editedSource(material.name, material.source);
    material.name = material.name.empty() ? "" : material.name + "-edited";
    c["material"] = materialToJson(material);
  }
  return c["material"];
}

}  // namespace

json withWeftAngle(const json& scene, int cloth, double degrees) {
  json out = scene;
  clothJson(out, cloth)["weft_angle_deg"] = degrees;
  return out;
}

json withInlineTearTable(const json& scene, const Scene& parsed, int cloth, double defaultStrength) {
  json out = scene;
  json& c = clothJson(out, cloth);
  if (!c.contains("tear_table") || !c["tear_table"].is_object()) {
    c["tear_table"] = inlineTable(currentTearTable(parsed, cloth, defaultStrength));
  }
  return out;
}

json withTearStrength(const json& scene, const Scene& parsed, int cloth, int k, double strength) {
  json out = withInlineTearTable(scene, parsed, cloth);
  json& values = clothJson(out, cloth)["tear_table"]["strength"];
  if (k < 0 || k >= static_cast<int>(values.size())) throw std::out_of_range("no tear table entry " + std::to_string(k));
  values[static_cast<std::size_t>(k)] = strength;
  return out;
}

json withTearDirections(const json& scene, const Scene& parsed, int cloth, int directions) {
  directions = std::max(directions, 1);
  const TearTable old = currentTearTable(parsed, cloth, 10.0);
  TearTable resampled = old;
  resampled.strength.clear();
  for (int k = 0; k < directions; ++k) {
    resampled.strength.push_back(requiredStrength(old, 180.0 * k / directions) / old.unitNPerM);
  }
  json out = scene;
  clothJson(out, cloth)["tear_table"] = inlineTable(resampled);
  return out;
}

json withTearTablePreset(const json& scene, int cloth, const std::string& name) {
  json out = scene;
  clothJson(out, cloth)["tear_table"] = name;
  return out;
}

json withoutTearTable(const json& scene, const Scene& parsed, int cloth) {
  json out = scene;
  json& c = clothJson(out, cloth);
  c.erase("tear_table");
  // A table that comes with the material must go too: the material is made inline without it.
  if (clothSpec(parsed, cloth).material.tearTable) {
    json& material = inlineMaterial(out, parsed, cloth);
    material.erase("tear_table");
    c.erase("tear_table");
  }
  return out;
}

json withMaterialPreset(const json& scene, int cloth, const std::string& name) {
  json out = scene;
  clothJson(out, cloth)["material"] = name;
  return out;
}

json withInlineMaterial(const json& scene, const Scene& parsed, int cloth) {
  json out = scene;
  inlineMaterial(out, parsed, cloth);
  return out;
}

json withAreaDensity(const json& scene, const Scene& parsed, int cloth, double kgPerM2) {
  json out = scene;
  inlineMaterial(out, parsed, cloth)["area_density_kg_m2"] = kgPerM2;
  return out;
}

json withBendingScale(const json& scene, const Scene& parsed, int cloth, double scale) {
  json out = scene;
  inlineMaterial(out, parsed, cloth)["bending"]["stiffness_scale"] = scale;
  return out;
}

json withStiffnessScale(const json& scene, const Scene& parsed, int cloth, double scale) {
  json out = scene;
  inlineMaterial(out, parsed, cloth)["elasticity"]["stiffness_scale"] = scale;
  return out;
}

json withElasticityCoefficient(const json& scene, const Scene& parsed, int cloth, int row, int column, double value) {
  json out = scene;
  json& elasticity = inlineMaterial(out, parsed, cloth)["elasticity"];
  if (elasticity.value("model", "") != "measured") throw std::logic_error("the material is not measured");
  if (column < 0 || column > 3) throw std::out_of_range("no coefficient column " + std::to_string(column));
  json& target = row < 0 ? elasticity["zero_strain"] : elasticity["at_reference_stretch"].at(static_cast<std::size_t>(row));
  target.at(static_cast<std::size_t>(column)) = value;
  return out;
}

json withBendingStiffness(const json& scene, const Scene& parsed, int cloth, int row, int column, double value) {
  json out = scene;
  json& bending = inlineMaterial(out, parsed, cloth)["bending"];
  const std::string model = bending.value("model", "constant");
  if (model == "measured") {
    bending.at("stiffness").at(static_cast<std::size_t>(row)).at(static_cast<std::size_t>(column)) = value;
  } else if (model == "constant") {
    bending["stiffness_n_m"] = value;
  } else {
    throw std::logic_error("the material has no bending to edit");
  }
  return out;
}

json withIsotropicElasticity(const json& scene, const Scene& parsed, int cloth, double youngModulus,
                             double poissonRatio) {
  json out = scene;
  json& material = inlineMaterial(out, parsed, cloth);
  const double scale = material["elasticity"].value("stiffness_scale", 1.0);
  material["elasticity"] = json{{"model", "isotropic"},
                                {"young_modulus_n_per_m", youngModulus},
                                {"poisson_ratio", poissonRatio},
                                {"stiffness_scale", scale}};
  return out;
}

namespace {

// `base`, or base2, base3... whichever no element of `array` is named yet.
std::string uniqueName(const json& array, const std::string& base) {
  auto taken = [&](const std::string& name) {
    for (const json& item : array) {
      if (item.value("name", "") == name) return true;
    }
    return false;
  };
  std::string name = base;
  for (int k = 2; taken(name); ++k) name = base + std::to_string(k);
  return name;
}

json vec3Json(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

}  // namespace

json withObstacleAdded(const json& scene, const std::string& shape, const Vec3& position, double size) {
  json out = scene;
  if (!out.contains("obstacles")) out["obstacles"] = json::array();
  json obstacle;
  obstacle["name"] = uniqueName(out["obstacles"], shape);
  if (shape == "sphere") {
    obstacle["shape"] = json{{"sphere", {{"radius", size}}}};
  } else if (shape == "box") {
    obstacle["shape"] = json{{"box", {{"half_extents", vec3Json(Vec3::Constant(size))}}}};
  } else {
    throw std::invalid_argument("cannot add a \"" + shape + "\" from the editor; expected sphere or box");
  }
  obstacle["placement"] = json{{"translate", vec3Json(position)}};
  out["obstacles"].push_back(obstacle);
  return out;
}

json withoutObstacle(const json& scene, int obstacle) {
  json out = scene;
  json& obstacles = out.at("obstacles");
  if (obstacle < 0 || obstacle >= static_cast<int>(obstacles.size())) throw std::out_of_range("no such obstacle");
  obstacles.erase(static_cast<std::size_t>(obstacle));
  if (obstacles.empty()) out.erase("obstacles");
  return out;
}

json withSharpTagsFile(const json& scene, int obstacle, const std::string& file) {
  json out = scene;
  json& obstacles = out.at("obstacles");
  if (obstacle < 0 || obstacle >= static_cast<int>(obstacles.size())) throw std::out_of_range("no such obstacle");
  json& mesh = obstacles[static_cast<std::size_t>(obstacle)].at("shape").at("mesh");
  mesh["sharp_tags"] = file;
  return out;
}

json withSharpTagsInline(const json& scene, int obstacle, const json& tags) {
  json out = scene;
  json& obstacles = out.at("obstacles");
  if (obstacle < 0 || obstacle >= static_cast<int>(obstacles.size())) throw std::out_of_range("no such obstacle");
  obstacles[static_cast<std::size_t>(obstacle)].at("shape").at("mesh")["sharp_tags"] = tags;
  return out;
}

json withClothDuplicated(const json& scene, int cloth, const Vec3& offset) {
  json out = scene;
  json copy = clothJson(out, cloth);
  copy["name"] = uniqueName(out["cloths"], copy.value("name", "cloth"));
  Vec3 translate = Vec3::Zero();
  if (copy.contains("placement") && copy["placement"].contains("translate")) {
    const json& t = copy["placement"]["translate"];
    translate = Vec3(t.at(0).get<double>(), t.at(1).get<double>(), t.at(2).get<double>());
  }
  copy["placement"]["translate"] = vec3Json(translate + offset);
  out["cloths"].push_back(copy);
  return out;
}

json withoutCloth(const json& scene, int cloth) {
  json out = scene;
  clothJson(out, cloth);  // range check
  if (out["cloths"].size() < 2) throw std::invalid_argument("a scene keeps at least one cloth");
  out["cloths"].erase(static_cast<std::size_t>(cloth));
  return out;
}

json withGravity(const json& scene, const Vec3& gravity) {
  json out = scene;
  out["forces"]["gravity"] = vec3Json(gravity);
  return out;
}

json withWind(const json& scene, const Vec3& velocity) {
  json out = scene;
  out["forces"]["wind"]["velocity"] = vec3Json(velocity);
  return out;
}

json withMassDamping(const json& scene, double perSecond) {
  json out = scene;
  out["forces"]["damping"]["mass"] = perSecond;
  return out;
}

json withTimeStep(const json& scene, double dt) {
  json out = scene;
  out["solver"]["dt"] = dt;
  return out;
}

json withSubsteps(const json& scene, int substeps) {
  json out = scene;
  out["solver"]["substeps"] = substeps;
  return out;
}

json withLinearTolerance(const json& scene, double tolerance) {
  json out = scene;
  out["solver"]["linear_solver"]["tolerance"] = tolerance;
  return out;
}

json withIntegrator(const json& scene, const std::string& name) {
  json out = scene;
  out["solver"]["integrator"] = name;
  return out;
}

json withLinearSolverType(const json& scene, const std::string& name) {
  json out = scene;
  out["solver"]["linear_solver"]["type"] = name;
  return out;
}

json withPreconditioner(const json& scene, const std::string& name) {
  json out = scene;
  out["solver"]["linear_solver"]["preconditioner"] = name;
  return out;
}

json withStage(const json& scene, const std::string& stage, bool runs) {
  json out = scene;
  out["stages"][stage] = runs;
  return out;
}

}  // namespace weft::editor
