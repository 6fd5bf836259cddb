// Weft's material JSON: strict parsing with errors that name file and field, preset lookup, and
// the round trip through materialToJson.
#include "material/material.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "util/input_error.h"

namespace weft {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kPresetDir = fs::path(WEFT_SOURCE_DIR) / "presets" / "materials";

class MaterialFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("weft_material_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static json preset(const std::string& name) {
    std::ifstream in(kPresetDir / (name + ".json"));
    return json::parse(in);
  }

  static json renamed(json j, const std::string& name) {
    j["name"] = name;
    return j;
  }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path file = dir_ / (name + ".json");
    std::ofstream(file) << text;
    return file;
  }
  fs::path write(const std::string& name, const json& j) const { return write(name, j.dump(2)); }

  // Loading `file` must throw an InputError naming the file and the field, both in the message.
  static void expectRejected(const fs::path& file, const std::string& field, const std::string& mentions = "") {
    expectInputError([&] { loadMaterialFile(file); }, file.string(), field, mentions);
  }

  static void expectInputError(const std::function<void()>& load, const std::string& file, const std::string& field,
                               const std::string& mentions) {
    try {
      load();
      ADD_FAILURE() << "no InputError for " << file << " " << field;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(e.file(), file) << message;
      EXPECT_EQ(e.field(), field) << message;
      EXPECT_NE(message.find(file), std::string::npos) << message;
      EXPECT_NE(message.find(field), std::string::npos) << message;
      EXPECT_NE(message.find(mentions), std::string::npos) << message;
    }
  }

  fs::path dir_;
};

TEST_F(MaterialFiles, ValidPresetCopyLoads) {
  const Material m = loadMaterialFile(write("royal-target", preset("royal-target")));
  EXPECT_EQ(m.name, "royal-target");
  EXPECT_EQ(m.areaDensity, 0.220);
  EXPECT_EQ(m.elasticity.model, ElasticitySettings::Model::Measured);
  EXPECT_EQ(m.elasticity.measured.zeroStrain[0], 2016.55456);
  EXPECT_EQ(m.elasticity.measured.directions[4][3], 39.885654);
  EXPECT_EQ(m.bending.measured[2][4], 227.861038e-6);
}

TEST_F(MaterialFiles, UnknownKeyIsRejected) {
  json j = preset("royal-target");
  j["colour"] = "blue";
  expectRejected(write("top", j), "/colour", "unknown key");
  j = preset("royal-target");
  j["elasticity"]["stretching_mult"] = 2;
  expectRejected(write("nested", j), "/elasticity/stretching_mult", "unknown key");
  j = preset("isotropic-cotton");
  j["bending"]["edge_direction_deg"] = json::array({0, 45, 90});  // a measured key in a constant model
  expectRejected(write("wrong-model-key", j), "/bending/edge_direction_deg", "unknown key");
}

TEST_F(MaterialFiles, MissingFieldIsRejected) {
  json j = preset("royal-target");
  j.erase("area_density_kg_m2");
  expectRejected(write("density", j), "/area_density_kg_m2", "missing");
  j = preset("royal-target");
  j.erase("source");
  expectRejected(write("source", j), "/source", "missing");
  j = preset("royal-target");
  j["elasticity"].erase("reference_stretch");
  expectRejected(write("stretch", j), "/elasticity/reference_stretch", "missing");
  j = preset("isotropic-cotton");
  j["elasticity"].erase("poisson_ratio");
  expectRejected(write("poisson", j), "/elasticity/poisson_ratio", "missing");
  j = preset("isotropic-cotton");
  j.erase("bending");
  expectRejected(write("bending", j), "/bending", "missing");
}

TEST_F(MaterialFiles, WrongTypeIsRejected) {
  json j = preset("royal-target");
  j["area_density_kg_m2"] = "heavy";
  expectRejected(write("string-density", j), "/area_density_kg_m2", "got a string");
  j = preset("royal-target");
  j["elasticity"]["zero_strain"][2] = nullptr;
  expectRejected(write("null-sample", j), "/elasticity/zero_strain/2", "got a null");
  j = preset("isotropic-cotton");
  j["elasticity"]["young_modulus_n_per_m"] = true;
  expectRejected(write("bool-modulus", j), "/elasticity/young_modulus_n_per_m", "got a boolean");
  j = preset("royal-target");
  j["name"] = 7;
  expectRejected(write("number-name", j), "/name", "string");
  j = preset("royal-target");
  j["elasticity"] = json::array();
  expectRejected(write("array-elasticity", j), "/elasticity", "object");
  j = preset("royal-target");
  j["elasticity"]["units"] = "kN/m";
  expectRejected(write("units", j), "/elasticity/units", "N/m");
  j = preset("royal-target");
  j["elasticity"]["model"] = "neo-hookean";
  expectRejected(write("model", j), "/elasticity/model", "unknown model");
}

TEST_F(MaterialFiles, WrongArrayShapeIsRejected) {
  json j = preset("royal-target");
  j["elasticity"]["at_reference_stretch"].erase(4);
  expectRejected(write("four-rows", j), "/elasticity/at_reference_stretch", "5 rows");
  j = preset("royal-target");
  j["elasticity"]["at_reference_stretch"][1].erase(3);
  expectRejected(write("three-numbers", j), "/elasticity/at_reference_stretch/1", "4 numbers");
  j = preset("royal-target");
  j["elasticity"]["zero_strain"].push_back(1.0);
  expectRejected(write("five-numbers", j), "/elasticity/zero_strain", "4 numbers");
  j = preset("royal-target");
  j["bending"]["stiffness"][2].erase(0);
  expectRejected(write("bending-row", j), "/bending/stiffness/2", "5 numbers");
  j = preset("royal-target");
  j["elasticity"]["direction_deg"] = json::array({0, 30, 60, 90, 120});
  expectRejected(write("directions", j), "/elasticity/direction_deg", "exactly");
}

TEST_F(MaterialFiles, OutOfRangeValueIsRejected) {
  json j = preset("royal-target");
  j["area_density_kg_m2"] = -0.2;
  expectRejected(write("negative-density", j), "/area_density_kg_m2", "> 0");
  j["area_density_kg_m2"] = 0.0;
  expectRejected(write("zero-density", j), "/area_density_kg_m2", "> 0");
  j = preset("isotropic-cotton");
  j["elasticity"]["poisson_ratio"] = 0.5;
  expectRejected(write("poisson-half", j), "/elasticity/poisson_ratio", "[0, 0.5)");
  j["elasticity"]["poisson_ratio"] = -0.1;
  expectRejected(write("poisson-negative", j), "/elasticity/poisson_ratio", "[0, 0.5)");
  j = preset("isotropic-cotton");
  j["elasticity"]["young_modulus_n_per_m"] = 0;
  expectRejected(write("modulus", j), "/elasticity/young_modulus_n_per_m", "> 0");
  j = preset("isotropic-cotton");
  j["bending"]["stiffness_n_m"] = -1e-5;
  expectRejected(write("bending-constant", j), "/bending/stiffness_n_m", ">= 0");
  j = preset("royal-target");
  j["bending"]["stiffness"][1][2] = -1e-5;
  expectRejected(write("bending-measured", j), "/bending/stiffness/1/2", ">= 0");
  j = preset("royal-target");
  j["elasticity"]["reference_stretch"] = 1.0;
  expectRejected(write("reference", j), "/elasticity/reference_stretch", "> 1");
  j = preset("royal-target");
  j["bending"]["stiffness_scale"] = 0.0;
  expectRejected(write("scale", j), "/bending/stiffness_scale", "> 0");
  // Negative stretching samples are data, kept as they are (the model clamps them).
  j = preset("gray-interlock");
  EXPECT_EQ(loadMaterialFile(write("gray-interlock", j)).elasticity.measured.directions[3][3], -174.43853);
}

TEST_F(MaterialFiles, NonFiniteNumberIsRejected) {
  // JSON text cannot hold NaN, and nlohmann rejects 1e999 while parsing; a json built in code can.
  json j = preset("isotropic-cotton");
  j["elasticity"]["young_modulus_n_per_m"] = std::numeric_limits<double>::quiet_NaN();
  expectInputError([&] { parseMaterial(j, "scene.json", "/cloths/0/material"); }, "scene.json",
                   "/cloths/0/material/elasticity/young_modulus_n_per_m", "finite");
  j = preset("royal-target");
  j["elasticity"]["zero_strain"][0] = std::numeric_limits<double>::infinity();
  expectInputError([&] { parseMaterial(j, "scene.json", "/cloths/0/material"); }, "scene.json",
                   "/cloths/0/material/elasticity/zero_strain/0", "finite");
  expectRejected(write("overflow", std::string(R"({"name": "overflow", "area_density_kg_m2": 1e999})")),
                 "/area_density_kg_m2", "too large for a double");
}

TEST_F(MaterialFiles, MissingOrInvalidFileIsRejected) {
  expectRejected(dir_ / "does-not-exist.json", "", "cannot open");
  expectRejected(write("broken", std::string("{\n  \"name\": \"broken\",\n  \"source\": \"x\"\n  \"area\": 1\n}")),
                 "", "line 4");
  expectRejected(write("not-object", std::string("[1, 2]")), "", "object");
}

TEST_F(MaterialFiles, PresetLookupNamesTheReferenceAndListsPresets) {
  write("alpha", renamed(preset("isotropic-cotton"), "alpha"));
  write("beta", renamed(preset("isotropic-stiff"), "beta"));
  EXPECT_EQ(loadMaterialPreset("beta", {dir_ / "missing-dir", dir_}, "scene.json", "/cloths/0/material").name,
            "beta");
  for (const std::string bad : {"gamma", "../alpha", ""}) {
    SCOPED_TRACE("'" + bad + "'");
    expectInputError([&] { loadMaterialPreset(bad, {dir_}, "scenes/drape.json", "/cloths/1/material"); },
                     "scenes/drape.json", "/cloths/1/material", "available presets: alpha, beta");
  }
  // A preset whose name disagrees with its file name.
  write("delta", renamed(preset("isotropic-cotton"), "epsilon"));
  expectInputError([&] { loadMaterialPreset("delta", {dir_}, "scene.json", "/m"); }, (dir_ / "delta.json").string(),
                   "/name", "must match");
}

TEST_F(MaterialFiles, InlineMaterialNamesTheScenePath) {
  json j = preset("isotropic-cotton");
  j.erase("name");
  j.erase("source");
  const Material m = parseMaterial(j, "scene.json", "/cloths/0/material");  // name, source optional inline
  EXPECT_EQ(m.elasticity.youngModulus, 4000.0);
  j["elasticity"]["poisson_ratio"] = 0.7;
  expectInputError([&] { parseMaterial(j, "scene.json", "/cloths/0/material"); }, "scene.json",
                   "/cloths/0/material/elasticity/poisson_ratio", "[0, 0.5)");
  json slash = preset("isotropic-cotton");
  slash["a/b~c"] = 1;
  expectInputError([&] { parseMaterial(slash, "scene.json", "/m"); }, "scene.json", "/m/a~1b~0c", "unknown key");
}

std::vector<fs::path> presetFiles() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kPresetDir)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(MaterialPresets, EveryPresetParses) {
  const std::vector<fs::path> files = presetFiles();
  EXPECT_GE(files.size(), 12u);  // ten measured fabrics and the isotropic ones
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::string name = file.stem().string();
    const Material m = loadMaterialPreset(name, {kPresetDir}, "test", "/material");
    EXPECT_EQ(m.name, name);
    EXPECT_FALSE(m.source.empty());
    EXPECT_GT(m.areaDensity, 0.0);
  }
}

TEST(MaterialPresets, RoundTripThroughJson) {
  std::vector<Material> materials;
  for (const fs::path& file : presetFiles()) materials.push_back(loadMaterialFile(file));
  Material scaled = materials.front();
  scaled.elasticity.stiffnessScale = 2.5;
  scaled.bending.stiffnessScale = 0.5;
  materials.push_back(scaled);
  Material plain;  // defaults: isotropic, constant bending, no name or source
  materials.push_back(plain);
  plain.bending = BendingSettings{};
  plain.bending.model = BendingSettings::Model::None;
  materials.push_back(plain);
  for (const Material& m : materials) {
    SCOPED_TRACE(m.name);
    EXPECT_EQ(parseMaterial(materialToJson(m), "", ""), m);
    EXPECT_EQ(parseMaterial(json::parse(materialToJson(m).dump()), "", ""), m);  // through text as well
  }
  EXPECT_FALSE(parseMaterial(materialToJson(scaled), "", "") == materials.front());
}

}  // namespace
}  // namespace weft
