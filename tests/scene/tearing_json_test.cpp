// The tearing parts of a scene: a cloth's "tear_table" (a preset name or an inline table, in the
// material or on the cloth) and the "tearing" section. Read as documented; bad input rejected
// naming the file and the field.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_json.h"
#include "support/temp_dir.h"
#include "util/input_error.h"

namespace weft {
namespace {

using nlohmann::json;
using test::TempDir;

json sheet() { return json::parse(R"({"cloths": [{"mesh": {"grid": {}}, "material": "11oz-black-denim"}]})"); }

TEST(TearingJson, APresetTableAnInlineTableAndTheSectionAreRead) {
  TempDir dir;
  json scene = sheet();
  scene["cloths"][0]["tear_table"] = "karaoz2015-table4.1-cloth3";
  scene["tearing"] = json::parse(R"({"candidates": "dense", "dense_directions": 90, "tears_per_step": 3,
      "min_spacing_m": 0.2, "min_angle_deg": 10, "skip_by_bound": false, "incubation_s": 0.03,
      "initiation_every": 4})");
  Scene s = loadScene(dir.write("t.json", scene.dump()));
  ASSERT_TRUE(s.cloths[0].material.tearTable.has_value());
  EXPECT_EQ(s.cloths[0].material.tearTable->name, "karaoz2015-table4.1-cloth3");
  EXPECT_EQ(s.cloths[0].material.tearTable->strength, (std::vector<double>{12.0, 25.0, 35.0, 25.0}));
  EXPECT_TRUE(s.tearing.denseLines);
  EXPECT_EQ(s.tearing.denseDirections, 90);
  EXPECT_EQ(s.tearing.maxTearsPerStep, 3);
  EXPECT_DOUBLE_EQ(s.tearing.minSpacing, 0.2);
  EXPECT_DOUBLE_EQ(s.tearing.minAngleDeg, 10.0);
  EXPECT_FALSE(s.tearing.skipByBound);
  EXPECT_DOUBLE_EQ(s.tearing.incubation, 0.03);
  EXPECT_EQ(s.tearing.initiationEvery, 4);

  // Inline in the material, then replaced by the cloth's own.
  scene = sheet();
  json material = json::parse(R"({"area_density_kg_m2": 0.3, "elasticity": {"model": "isotropic",
      "young_modulus_n_per_m": 1000, "poisson_ratio": 0.3}, "bending": {"model": "none"},
      "tear_table": {"strength": [7], "unit_n_per_m": 2}})");
  scene["cloths"][0]["material"] = material;
  s = loadScene(dir.write("t2.json", scene.dump()));
  ASSERT_TRUE(s.cloths[0].material.tearTable.has_value());
  EXPECT_DOUBLE_EQ(weakestStrength(*s.cloths[0].material.tearTable), 14.0);
  scene["cloths"][0]["tear_table"] = json::parse(R"({"strength": [3, 4]})");
  s = loadScene(dir.write("t3.json", scene.dump()));
  EXPECT_EQ(s.cloths[0].material.tearTable->strength, (std::vector<double>{3.0, 4.0}));
  // No table: never tears.
  EXPECT_FALSE(loadScene(dir.write("t4.json", sheet().dump())).cloths[0].material.tearTable.has_value());
}

// The default is the resolution-independent mode; the one-pass mode (the thesis', the default
// before issue 17) stays selectable, and a scene that states it reads back as written.
TEST(TearingJson, TheDefaultIsTheResolutionIndependentModeAndTheOnePassModeIsSelectable) {
  TempDir dir;
  const Scene plain = loadScene(dir.write("plain.json", sheet().dump()));
  EXPECT_TRUE(plain.tearing.propagate);
  EXPECT_DOUBLE_EQ(plain.tearing.stressLength, 0.065);
  EXPECT_DOUBLE_EQ(plain.tearing.incubation, 0.06);
  json scene = sheet();
  scene["tearing"] = json::parse(R"({"propagate": false, "stress_length_m": 0, "incubation_s": 0})");
  const std::string text = scene.dump(2);
  const Scene onePass = loadScene(dir.write("one-pass.json", text));
  EXPECT_FALSE(onePass.tearing.propagate);
  EXPECT_EQ(onePass.tearing.stressLength, 0.0);
  EXPECT_EQ(onePass.tearing.incubation, 0.0);
  // Saved again (the editor writes the document it read) and read back: the same mode.
  EXPECT_EQ(loadScene(dir.write("saved.json", json::parse(text).dump(2))).tearing, onePass.tearing);
}

struct BadTearing {
  std::string name;
  std::string patch;   // merged into the sheet scene
  std::string field;   // expected InputError::field()
  std::string mentions;
};
std::ostream& operator<<(std::ostream& out, const BadTearing& c) { return out << c.name; }

class TearingJsonRejects : public ::testing::TestWithParam<BadTearing> {};

TEST_P(TearingJsonRejects, NamingTheFileAndTheField) {
  const BadTearing& c = GetParam();
  TempDir dir;
  json scene = sheet();
  scene.merge_patch(json::parse(c.patch));
  if (!scene["cloths"][0].contains("mesh")) scene["cloths"][0] = sheet()["cloths"][0];
  try {
    loadScene(dir.write("bad-tearing.json", scene.dump(2)));
    FAIL() << "accepted without an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad-tearing.json"), std::string::npos) << what;
    EXPECT_EQ(e.field(), c.field) << what;
    EXPECT_NE(what.find(c.mentions), std::string::npos) << "expected '" << c.mentions << "' in: " << what;
  }
}

json clothWith(const std::string& key, const std::string& value) {
  json cloth = sheet()["cloths"][0];
  cloth[key] = json::parse(value);
  return cloth;
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, TearingJsonRejects,
    ::testing::Values(
        BadTearing{"UnknownPreset", json({{"cloths", {clothWith("tear_table", R"("no-such-table")")}}}).dump(),
                   "/cloths/0/tear_table", "karaoz2015-table4.1-cloth1"},
        BadTearing{"NotATable", json({{"cloths", {clothWith("tear_table", "5")}}}).dump(), "/cloths/0/tear_table",
                   "tear table"},
        BadTearing{"NegativeStrength",
                   json({{"cloths", {clothWith("tear_table", R"({"strength": [5, -2]})")}}}).dump(),
                   "/cloths/0/tear_table/strength/1", "strength"},
        BadTearing{"UnevenDirections",
                   json({{"cloths", {clothWith("tear_table", R"({"strength": [5, 6], "directions_deg": [0, 60]})")}}})
                       .dump(),
                   "/cloths/0/tear_table/directions_deg/1", "evenly spaced"},
        BadTearing{"UnknownCandidates", R"({"tearing": {"candidates": "all"}})", "/tearing/candidates", "thesis"},
        BadTearing{"ZeroTearsPerStep", R"({"tearing": {"tears_per_step": 0}})", "/tearing/tears_per_step", ""},
        BadTearing{"WideAngleGuard", R"({"tearing": {"min_angle_deg": 45}})", "/tearing/min_angle_deg", "30"},
        BadTearing{"NegativeIncubation", R"({"tearing": {"incubation_s": -0.01}})", "/tearing/incubation_s", ""},
        BadTearing{"HugeIncubation", R"({"tearing": {"incubation_s": 1e300}})", "/tearing/incubation_s", "10 s"},
        BadTearing{"ZeroInitiationEvery", R"({"tearing": {"initiation_every": 0}})", "/tearing/initiation_every",
                   ""},
        BadTearing{"FractionalInitiationEvery", R"({"tearing": {"initiation_every": 2.5}})",
                   "/tearing/initiation_every", ""},
        BadTearing{"HugeInitiationEvery", R"({"tearing": {"initiation_every": 1e9}})", "/tearing/initiation_every",
                   "1000"},
        BadTearing{"UnknownKey", R"({"tearing": {"speed": 1}})", "/tearing/speed", "speed"}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace weft
