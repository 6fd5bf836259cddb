// Scene files: every preset loads, defaults and overrides land in the right field, and each kind
// of bad input is rejected with an InputError that names the file and the JSON path of the field.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_json.h"
#include "support/temp_dir.h"
#include "util/echo.h"
#include "util/input_error.h"

namespace weft {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kPresetScenes = fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes";

using test::TempDir;

// The smallest valid scene: one grid cloth of a preset material, everything else defaulted.
json minimalScene() {
  return json::parse(R"({"cloths": [{"mesh": {"grid": {}}, "material": "royal-target"}]})");
}

json isotropicMaterial() {
  return json::parse(R"({
    "area_density_kg_m2": 0.2,
    "elasticity": {"model": "isotropic", "young_modulus_n_per_m": 3000, "poisson_ratio": 0.3},
    "bending": {"model": "constant", "stiffness_n_m": 1e-4}
  })");
}

// A 2 x 2 quad in an OBJ file with UVs; `degenerate` collapses one triangle's UVs onto a line.
std::string squareObj(bool degenerate) {
  std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
  if (degenerate) obj += "vt 0.5 0.5\nf 1/1 2/2 3/3\nf 1/1 3/3 4/5\n";  // (0,0), (1,1), (0.5,0.5): collinear
  else obj += "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
  return obj;
}

TEST(SceneJson, EveryPresetSceneLoads) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kPresetScenes)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene scene = loadScene(entry.path());
    EXPECT_FALSE(scene.cloths.empty());
    EXPECT_EQ(scene.name, entry.path().stem().string()) << "a preset's name should match its file name";
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(SceneJson, HangingSheetIsTheDocumentedScene) {
  const Scene scene = loadScene(kPresetScenes / "hanging-sheet.json");
  ASSERT_EQ(scene.cloths.size(), 1u);
  const ClothSpec& sheet = scene.cloths[0];
  ASSERT_TRUE(sheet.grid.has_value());
  EXPECT_EQ(sheet.grid->resolutionX, 32);
  EXPECT_EQ(sheet.grid->resolutionY, 32);
  EXPECT_DOUBLE_EQ(sheet.grid->width, 1.0);
  EXPECT_EQ(sheet.materialName, "royal-target");
  EXPECT_EQ(sheet.material.name, "royal-target");
  ASSERT_EQ(sheet.pins.size(), 1u);
  EXPECT_EQ(sheet.pins[0].corners, (std::vector<std::string>{"top_left", "top_right"}));
  EXPECT_EQ(stepsPerFrame(scene), 2);
}

TEST(SceneJson, SheetMovedByPinsHasAnIncreasingScript) {
  const Scene scene = loadScene(kPresetScenes / "sheet-moved-by-pins.json");
  const PinGroup& pins = scene.cloths.at(0).pins.at(0);
  ASSERT_TRUE(pins.restBox.has_value());
  ASSERT_GE(pins.script.size(), 3u);
  for (std::size_t k = 1; k < pins.script.size(); ++k) EXPECT_GT(pins.script[k].time, pins.script[k - 1].time);
  EXPECT_DOUBLE_EQ(pins.script[1].offset.x(), 0.3);
}

TEST(SceneJson, ObjPathResolvesAgainstTheAssetsFolder) {
  const Scene scene = loadScene(kPresetScenes / "draped-obj-sheet.json");
  ASSERT_TRUE(scene.cloths.at(0).obj.has_value());
  EXPECT_TRUE(fs::is_regular_file(scene.cloths[0].obj->path)) << scene.cloths[0].obj->path;
  EXPECT_EQ(scene.cloths[0].obj->path.filename(), "square_sheet.obj");
}

TEST(SceneJson, DefaultsAreTheStructDefaults) {
  TempDir dir;
  const fs::path file = dir.write("my-scene.json", minimalScene().dump());
  const Scene scene = loadScene(file);
  const SolverSpec solver;
  const ForcesSpec forces;
  const OutputSpec output;
  const GridSpec grid;
  EXPECT_EQ(scene.name, "my-scene");  // the file's stem
  EXPECT_EQ(scene.description, "");
  EXPECT_DOUBLE_EQ(scene.solver.dt, solver.dt);
  EXPECT_EQ(scene.solver.substeps, solver.substeps);
  EXPECT_EQ(scene.solver.integrator, solver.integrator);
  EXPECT_EQ(scene.solver.linearSolver, solver.linearSolver);
  EXPECT_EQ(scene.solver.linearPreconditioner, solver.linearPreconditioner);
  EXPECT_EQ(scene.solver.newtonMaxIterations, solver.newtonMaxIterations);
  EXPECT_EQ(scene.solver.threads, solver.threads);
  EXPECT_EQ(scene.forces.gravity, forces.gravity);
  EXPECT_EQ(scene.forces.wind.velocity, forces.wind.velocity);
  EXPECT_DOUBLE_EQ(scene.forces.damping.mass, forces.damping.mass);
  EXPECT_TRUE(scene.stages.bending && scene.stages.wind && scene.stages.gravity);
  EXPECT_EQ(scene.output.frames, output.frames);
  EXPECT_DOUBLE_EQ(scene.output.fps, output.fps);
  const ClothSpec& cloth = scene.cloths.at(0);
  EXPECT_EQ(cloth.name, "cloth");
  EXPECT_EQ(cloth.grid->resolutionX, grid.resolutionX);
  EXPECT_DOUBLE_EQ(cloth.grid->height, grid.height);
  EXPECT_EQ(cloth.placement.translate, Vec3::Zero());
  EXPECT_DOUBLE_EQ(cloth.weftAngleDeg, 0.0);
  EXPECT_TRUE(cloth.pins.empty());
}

TEST(SceneJson, OverridesChangeTheNamedValue) {
  const Scene base = loadScene(kPresetScenes / "hanging-sheet.json");
  const Scene scene = loadScene(kPresetScenes / "hanging-sheet.json",
                                {"solver.dt=0.005", "cloths.0.weft_angle_deg=30", "solver.substeps=4",
                                 "cloths.0.material=tango-red-jet-set", "cloths.0.mesh.grid.resolution=[8, 9]"});
  EXPECT_DOUBLE_EQ(scene.solver.dt, 0.005);
  EXPECT_DOUBLE_EQ(scene.cloths[0].weftAngleDeg, 30.0);
  EXPECT_EQ(scene.solver.substeps, 4);
  EXPECT_EQ(scene.cloths[0].materialName, "tango-red-jet-set");  // not JSON: taken as a string
  EXPECT_EQ(scene.cloths[0].grid->resolutionX, 8);
  EXPECT_EQ(scene.cloths[0].grid->resolutionY, 9);
  // Untouched values stay as they were.
  EXPECT_EQ(scene.output.frames, base.output.frames);
  EXPECT_EQ(scene.solver.integrator, base.solver.integrator);
}

TEST(SceneJson, EveryIntegratorIsReadByName) {
  const std::pair<const char*, IntegratorKind> names[] = {
      {"linearized_backward_euler", IntegratorKind::LinearizedBackwardEuler},
      {"newton", IntegratorKind::Newton},
      {"symplectic_euler", IntegratorKind::SymplecticEuler},
      {"bdf2", IntegratorKind::Bdf2},
      {"bdf2_newton", IntegratorKind::Bdf2Newton}};
  for (const auto& [name, kind] : names) {
    const Scene scene = loadScene(kPresetScenes / "hanging-sheet.json", {std::string("solver.integrator=") + name});
    EXPECT_EQ(scene.solver.integrator, kind) << name;
  }
}

TEST(SceneJson, OverridesCanAddAKeyTheFileLeavesOut) {
  TempDir dir;
  const fs::path file = dir.write("s.json", minimalScene().dump());  // no solver section at all
  const Scene scene = loadScene(file, {"solver.substeps=3", "solver.newton.tolerance=1e-3", "forces.wind.velocity=[1,0,0]"});
  EXPECT_EQ(scene.solver.substeps, 3);
  EXPECT_DOUBLE_EQ(scene.solver.newtonTolerance, 1e-3);
  EXPECT_EQ(scene.forces.wind.velocity, Vec3(1, 0, 0));
}

TEST(SceneJson, PreconditionerIsReadByName) {
  TempDir dir;
  const fs::path file = dir.write("s.json", minimalScene().dump());
  const std::pair<const char*, PreconditionerKind> names[] = {
      {"lagged_cholesky", PreconditionerKind::LaggedCholesky},
      {"lagged_exact_cholesky", PreconditionerKind::LaggedExactCholesky},
      {"block_jacobi", PreconditionerKind::BlockJacobi},
      {"amg", PreconditionerKind::Amg}};
  for (const auto& [name, kind] : names) {
    const Scene scene = loadScene(file, {std::string("solver.linear_solver.preconditioner=") + name});
    EXPECT_EQ(scene.solver.linearPreconditioner, kind) << name;
  }
}

TEST(SceneJson, ApplyOverridesEditsTheJson) {
  json j = minimalScene();
  applyOverrides(j, {"cloths.0.weft_angle_deg=45", "name=\"quoted\"", "stages.wind=false"}, "f.json");
  EXPECT_EQ(j["cloths"][0]["weft_angle_deg"], 45);
  EXPECT_EQ(j["name"], "quoted");
  EXPECT_EQ(j["stages"]["wind"], false);
}

TEST(SceneJson, MalformedOverridesNameTheOverride) {
  json j = minimalScene();
  for (const std::string bad : {"solver.dt", "solver..dt=1", "cloths.3.name=x", "cloths.x.name=y",
                                "cloths.0.material.x=1"}) {
    SCOPED_TRACE(bad);
    try {
      applyOverrides(j, {bad}, "f.json");
      ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("f.json"), std::string::npos) << e.what();
    }
  }
}

TEST(SceneJson, MaterialPresetsAreFoundBesideTheScenesFolder) {
  TempDir dir;
  json material = isotropicMaterial();
  material["name"] = "my-fabric";
  material["source"] = "a test";
  dir.write("materials/my-fabric.json", material.dump());
  json scene = minimalScene();
  scene["cloths"][0]["material"] = "my-fabric";
  const Scene loaded = loadScene(dir.write("scenes/s.json", scene.dump()));
  EXPECT_EQ(loaded.cloths[0].materialName, "my-fabric");
  EXPECT_DOUBLE_EQ(loaded.cloths[0].material.areaDensity, 0.2);
}

TEST(SceneJson, InlineMaterialAndObjBesideTheScene) {
  TempDir dir;
  dir.write("quad.obj", squareObj(false));
  json scene = minimalScene();
  scene["cloths"][0]["material"] = isotropicMaterial();
  scene["cloths"][0]["mesh"] = {{"obj", {{"path", "quad.obj"}}}};
  scene["cloths"][0]["pins"] = json::parse(R"([{"vertices": [0, 1]}])");
  const Scene loaded = loadScene(dir.write("s.json", scene.dump()));
  EXPECT_EQ(loaded.cloths[0].materialName, "inline");
  EXPECT_EQ(loaded.cloths[0].material.elasticity.model, ElasticitySettings::Model::Isotropic);
  EXPECT_TRUE(fs::equivalent(loaded.cloths[0].obj->path, dir.path() / "quad.obj"));
}

TEST(SceneJson, AppearanceIsReadWithItsUnits) {
  TempDir dir;
  json scene = minimalScene();
  scene["cloths"][0]["appearance"] =
      json::parse(R"({"color": [0.1, 0.2, 0.3], "pattern": "plain", "thread_pitch_mm": 2, "threads_per_band": 4})");
  const Scene s = loadScene(dir.write("scene.json", scene.dump()));
  const ClothAppearance& look = s.cloths[0].appearance;
  ASSERT_TRUE(look.color.has_value());
  EXPECT_EQ(*look.color, Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(look.pattern, WeavePattern::Plain);
  EXPECT_DOUBLE_EQ(look.threadPitch, 0.002);
  EXPECT_EQ(look.threadsPerBand, 4);
  const Scene plain = loadScene(dir.write("plain.json", minimalScene().dump()));
  EXPECT_FALSE(plain.cloths[0].appearance.color.has_value());
  EXPECT_EQ(plain.cloths[0].appearance.pattern, WeavePattern::Gingham);
}

TEST(SceneJson, StepsPerFrameRoundsAndNeverReturnsZero) {
  Scene scene;
  scene.output.fps = 30;
  scene.solver.dt = 0.016666;
  EXPECT_EQ(stepsPerFrame(scene), 2);
  scene.solver.dt = 0.001;
  EXPECT_EQ(stepsPerFrame(scene), 33);
  scene.solver.dt = 0.1;
  EXPECT_EQ(stepsPerFrame(scene), 1);
}

// ---------------------------------------------------------------------------------------------
// Bad input: each case edits the minimal scene (or supplies an override) and names the field
// that the message must point at.

struct BadCase {
  std::string name;
  std::string patch;                   // JSON merge patch applied to the minimal scene
  std::vector<std::string> overrides;
  std::string field;                   // expected InputError::field() (a prefix, for material errors)
  std::string mentions;                // a word the message must contain
};

std::ostream& operator<<(std::ostream& out, const BadCase& c) { return out << c.name; }

class SceneJsonRejects : public ::testing::TestWithParam<BadCase> {};

TEST_P(SceneJsonRejects, NamingTheFileAndTheField) {
  const BadCase& c = GetParam();
  TempDir dir;
  dir.write("degenerate.obj", squareObj(true));
  json scene = minimalScene();
  if (!c.patch.empty()) scene.merge_patch(json::parse(c.patch));
  const fs::path file = dir.write("bad-scene.json", scene.dump(2));
  try {
    (void)loadScene(file, c.overrides);
    FAIL() << "loaded without an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad-scene.json"), std::string::npos) << what;
    EXPECT_EQ(e.field().rfind(c.field, 0), 0u) << "field " << e.field() << ", expected " << c.field << "; " << what;
    EXPECT_NE(what.find(c.field), std::string::npos) << what;
    EXPECT_NE(what.find(c.mentions), std::string::npos) << "expected '" << c.mentions << "' in: " << what;
  }
}

const char* const kGridCloth = R"("mesh": {"grid": {}}, "material": "royal-target")";

std::string cloth(const std::string& extra) {
  return std::string(R"({"cloths": [{)") + kGridCloth + (extra.empty() ? "" : ", " + extra) + "}]}";
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, SceneJsonRejects,
    ::testing::Values(
        BadCase{"MissingCloths", R"({"cloths": null})", {}, "/cloths", "missing"},
        BadCase{"EmptyCloths", R"({"cloths": []})", {}, "/cloths", "at least one"},
        BadCase{"MissingMesh", R"({"cloths": [{"material": "royal-target"}]})", {}, "/cloths/0/mesh", "missing"},
        BadCase{"MissingMaterial", R"({"cloths": [{"mesh": {"grid": {}}}]})", {}, "/cloths/0/material", "missing"},
        BadCase{"WrongType", R"({"solver": {"dt": "fast"}})", {}, "/solver/dt", "got string"},
        BadCase{"UnknownKey", R"({"solver": {"dtt": 0.01}})", {}, "/solver/dtt", "allowed keys"},
        BadCase{"UnknownTopLevelKey", R"({"colths": []})", {}, "/colths", "unknown key"},
        BadCase{"NegativeDt", R"({"solver": {"dt": -1}})", {}, "/solver/dt", "got -1"},
        BadCase{"NaNByOverride", "", {"solver.dt=NaN"}, "/solver/dt", "solver.dt=NaN"},
        BadCase{"UnknownKeyByOverride", "", {"solver.foo=1"}, "/solver/foo", "solver.foo=1"},
        BadCase{"MalformedOverride", "", {"solver.dt"}, "override", "solver.dt"},
        // Once std::out_of_range from std::stoul: "internal error", exit 1.
        BadCase{"IndexPastSizeTByOverride", "", {"cloths.99999999999999999999999.name=x"}, "override",
                "is not an index of the array there"},
        BadCase{"ZeroSubsteps", R"({"solver": {"substeps": 0}})", {}, "/solver/substeps", "[1, 1000]"},
        BadCase{"FractionalSubsteps", R"({"solver": {"substeps": 1.5}})", {}, "/solver/substeps", "integer"},
        BadCase{"ZeroThreads", R"({"solver": {"threads": 0}})", {}, "/solver/threads", "[1, 256]"},
        BadCase{"NegativeTolerance", R"({"solver": {"linear_solver": {"tolerance": -1e-6}}})", {},
                "/solver/linear_solver/tolerance", ">= 0"},
        BadCase{"UnknownIntegrator", R"({"solver": {"integrator": "verlet"}})", {}, "/solver/integrator", "verlet"},
        BadCase{"UnknownLinearSolver", R"({"solver": {"linear_solver": {"type": "lu"}}})", {},
                "/solver/linear_solver/type", "cholmod"},
        BadCase{"UnknownPreconditioner", R"({"solver": {"linear_solver": {"preconditioner": "ilu"}}})", {},
                "/solver/linear_solver/preconditioner", "lagged_cholesky"},
        BadCase{"NegativeFrames", R"({"output": {"frames": -1}})", {}, "/output/frames", "[0, 1000000]"},
        BadCase{"ZeroFps", R"({"output": {"fps": 0}})", {}, "/output/fps", "(0, 10000]"},
        // Values outside physical sense (scene_limits.h): each once crashed, ran out of memory or
        // ran for hours.
        BadCase{"TooManyThreads", "", {"solver.threads=100000"}, "/solver/threads", "[1, 256]"},
        BadCase{"HugeResolution", "", {"cloths.0.mesh.grid.resolution=[1000000,1000000]"},
                "/cloths/0/mesh/grid/resolution/0", "[2, 4096]"},
        BadCase{"IntMaxResolution", "", {"cloths.0.mesh.grid.resolution=[2147483647,2]"},
                "/cloths/0/mesh/grid/resolution/0", "[2, 4096]"},
        BadCase{"TooManyGridVertices", "", {"cloths.0.mesh.grid.resolution=[4096,4096]"},
                "/cloths/0/mesh/grid/resolution", "at most 1048576"},
        BadCase{"HugeUvScale", "", {R"(cloths.0.mesh={"obj": {"path": "degenerate.obj", "uv_scale": 1e300}})"},
                "/cloths/0/mesh/obj/uv_scale", "(0, 1000] m per UV unit"},
        BadCase{"HugeGridWidth", "", {"cloths.0.mesh.grid.width=1e308"}, "/cloths/0/mesh/grid/width", "(0, 100] m"},
        BadCase{"ThickContact", R"({"contact": {"thickness": 3.7}})", {}, "/contact/thickness", "(0, 0.1] m"},
        BadCase{"TinyDt", "", {"solver.dt=1e-12"}, "/solver/dt", "[1e-06, 1] s"},
        BadCase{"HugeDt", R"({"solver": {"dt": 1e5}})", {}, "/solver/dt", "[1e-06, 1] s"},
        BadCase{"IntMaxSubsteps", "", {"solver.substeps=2147483647"}, "/solver/substeps", "[1, 1000]"},
        BadCase{"HugeGravity", "", {"forces.gravity=[0,-1e12,0]"}, "/forces/gravity", "at most 1000 m/s^2"},
        BadCase{"HugeWind", R"({"forces": {"wind": {"velocity": [1e5, 0, 0]}}})", {}, "/forces/wind/velocity",
                "at most 340 m/s"},
        BadCase{"MillionsOfStepsPerFrame", R"({"solver": {"dt": 1e-6}, "output": {"fps": 0.001}})", {}, "/output/fps",
                "steps per frame"},
        BadCase{"HugeNumberByOverride", "", {"solver.dt=1e999"}, "override", "too large"},
        BadCase{"LongPresetName", "", {"cloths.0.material=" + std::string(300, 'a')}, "/cloths/0/material",
                "at most 100 bytes"},
        BadCase{"LongTearTableName", "", {"cloths.0.tear_table=" + std::string(300, 'a')}, "/cloths/0/tear_table",
                "at most 100 bytes"},
        BadCase{"NulInObjPath", "", {R"(cloths.0.mesh={"obj": {"path": "a\u0000b.obj"}})"}, "override", "\\u0000"},
        BadCase{"GustOutOfRange", R"({"forces": {"wind": {"gust_amplitude": 2}}})", {},
                "/forces/wind/gust_amplitude", "[0, 1]"},
        BadCase{"ColourOutOfRange", cloth(R"("appearance": {"color": [0.2, 1.5, 0.1]})"), {},
                "/cloths/0/appearance/color", "[0, 1]"},
        BadCase{"UnknownPattern", cloth(R"("appearance": {"pattern": "tartan"})"), {}, "/cloths/0/appearance/pattern",
                "gingham or plain"},
        BadCase{"ZeroThreadPitch", cloth(R"("appearance": {"thread_pitch_mm": 0})"), {},
                "/cloths/0/appearance/thread_pitch_mm", "positive"},
        BadCase{"GravityNotAVector", R"({"forces": {"gravity": [0, -9.81]}})", {}, "/forces/gravity", "3 finite"},
        BadCase{"StageNotBool", R"({"stages": {"wind": 1}})", {}, "/stages/wind", "true or false"},
        BadCase{"ResolutionTooSmall", R"({"cloths": [{"mesh": {"grid": {"resolution": [1, 8]}}, "material": "royal-target"}]})",
                {}, "/cloths/0/mesh/grid/resolution/0", "[2, 4096]"},
        BadCase{"GridAndObj", R"({"cloths": [{"mesh": {"grid": {}, "obj": {"path": "degenerate.obj"}}, "material": "royal-target"}]})",
                {}, "/cloths/0/mesh", "exactly one"},
        BadCase{"MissingObjFile", R"({"cloths": [{"mesh": {"obj": {"path": "nowhere.obj"}}, "material": "royal-target"}]})",
                {}, "/cloths/0/mesh/obj/path", "nowhere.obj"},
        BadCase{"DegenerateObjTriangle", R"({"cloths": [{"mesh": {"obj": {"path": "degenerate.obj"}}, "material": "royal-target"}]})",
                {}, "/cloths/0/mesh/obj/path", "degenerate.obj"},
        BadCase{"UnknownPreset", R"({"cloths": [{"mesh": {"grid": {}}, "material": "no-such-fabric"}]})", {},
                "/cloths/0/material", "royal-target"},
        BadCase{"NegativeDensityInline",
                R"({"cloths": [{"mesh": {"grid": {}}, "material": {"area_density_kg_m2": -1,
                    "elasticity": {"model": "isotropic", "young_modulus_n_per_m": 3000, "poisson_ratio": 0.3},
                    "bending": {"model": "constant", "stiffness_n_m": 1e-4}}}]})",
                {}, "/cloths/0/material", "area_density"},
        BadCase{"WrongShapedElasticityTable",
                R"({"cloths": [{"mesh": {"grid": {}}, "material": {"area_density_kg_m2": 0.2,
                    "elasticity": {"model": "measured", "units": "N/m", "coefficients": ["c11", "c12", "c22", "c33"],
                                   "direction_deg": [0, 22.5, 45, 67.5, 90], "reference_stretch": 1.1666666666666667,
                                   "zero_strain": [1, 0, 1, 1],
                                   "at_reference_stretch": [[1, 0, 1, 1], [1, 0, 1, 1], [1, 0, 1, 1], [1, 0, 1, 1]]},
                    "bending": {"model": "constant", "stiffness_n_m": 1e-4}}}]})",
                {}, "/cloths/0/material/elasticity", "at_reference_stretch"},
        BadCase{"UnknownCorner", cloth(R"("pins": [{"corners": ["top_middle"]}])"), {}, "/cloths/0/pins/0/corners/0",
                "top_left"},
        BadCase{"TwoPinSelectors", cloth(R"("pins": [{"corners": ["top_left"], "vertices": [0]}])"), {},
                "/cloths/0/pins/0", "exactly one"},
        BadCase{"NoPinSelector", cloth(R"("pins": [{"script": []}])"), {}, "/cloths/0/pins/0", "exactly one"},
        BadCase{"RestBoxMinAboveMax", cloth(R"("pins": [{"rest_box": {"min": [0, 1], "max": [1, 0.9]}}])"), {},
                "/cloths/0/pins/0/rest_box", "min"},
        BadCase{"RestBoxMissesTheCloth", cloth(R"("pins": [{"rest_box": {"min": [5, 5], "max": [6, 6]}}])"), {},
                "/cloths/0/pins/0/rest_box", "no vertex"},
        BadCase{"VertexOutOfRange", cloth(R"("pins": [{"vertices": [0, 5000]}])"), {},
                "/cloths/0/pins/0/vertices/1", "out of range"},
        BadCase{"ScriptNotIncreasing",
                cloth(R"("pins": [{"corners": ["top_left"], "script": [{"t": 1, "offset": [0,0,0]}, {"t": 1, "offset": [1,0,0]}]}])"),
                {}, "/cloths/0/pins/0/script/1/t", "increasing"},
        BadCase{"UnsafeSceneName", R"({"name": "../escape"})", {}, "/name", "letters"},
        BadCase{"DuplicateClothNames",
                std::string(R"({"cloths": [{"name": "a", )") + kGridCloth + R"(}, {"name": "a", )" + kGridCloth + "}]}",
                {}, "/cloths/1/name", "unique"}),
    [](const ::testing::TestParamInfo<BadCase>& info) { return info.param.name; });

TEST(SceneJson, InvalidJsonNamesTheFile) {
  TempDir dir;
  const fs::path file = dir.write("broken.json", R"({"cloths": [)");
  try {
    (void)loadScene(file);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos) << e.what();
  }
}

// Runs `load` and returns the InputError it throws (failing the test when there is none).
template <typename Load>
InputError inputErrorOf(Load&& load) {
  try {
    load();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", "", "");
}

TEST(SceneJson, DuplicateKeysAreRefusedNamingTheKey) {
  TempDir dir;
  // nlohmann::json keeps the last of two equal keys without a word: dt would silently be 0.5.
  const fs::path file = dir.write(
      "twice.json", R"({"cloths": [{"mesh": {"grid": {}}, "material": "royal-target"}],
                        "solver": {"dt": 0.01, "substeps": 2, "dt": 0.5}})");
  const InputError e = inputErrorOf([&] { (void)loadScene(file); });
  EXPECT_EQ(e.file(), file.string());
  EXPECT_EQ(e.field(), "/solver/dt");
  EXPECT_NE(std::string(e.what()).find("duplicate key \"dt\""), std::string::npos) << e.what();

  const InputError byOverride =
      inputErrorOf([&] { (void)loadScene(kPresetScenes / "hanging-sheet.json", {R"(solver={"dt": 0.01, "dt": 0.02})"}); });
  EXPECT_NE(std::string(byOverride.what()).find("duplicate key \"dt\""), std::string::npos) << byOverride.what();
  EXPECT_NE(byOverride.field().find("override"), std::string::npos) << byOverride.what();
}

TEST(SceneJson, DeepNestingIsRefusedWithoutCrashing) {
  // 100,000 levels once overflowed the stack in dump() while the error message was being built.
  const int depth = 100'000;
  const std::string deep = std::string(depth, '[') + std::string(depth, ']');
  TempDir dir;
  const fs::path file =
      dir.write("deep.json", R"({"cloths": [{"mesh": {"grid": {}}, "material": "royal-target"}], "solver": {"dt": )" +
                                 deep + "}}");
  const InputError e = inputErrorOf([&] { (void)loadScene(file); });
  EXPECT_EQ(e.field().rfind("/solver/dt/0/0/0", 0), 0u) << e.what();
  EXPECT_NE(std::string(e.what()).find("nested deeper than 64"), std::string::npos) << e.what();
  EXPECT_LT(std::string(e.what()).size(), 500u);

  const InputError byOverride =
      inputErrorOf([&] { (void)loadScene(kPresetScenes / "hanging-sheet.json", {"solver.dt=" + deep}); });
  EXPECT_NE(std::string(byOverride.what()).find("nested deeper than 64"), std::string::npos) << byOverride.what();
  EXPECT_LT(std::string(byOverride.what()).size(), 800u);
}

TEST(SceneJson, OverrideThatIsNotUtf8IsRefused) {
  // Before, the bytes became a JSON string and dump() threw type_error 316: "internal error", exit 1.
  const InputError e =
      inputErrorOf([&] { (void)loadScene(kPresetScenes / "hanging-sheet.json", {"name=\xff\xfe"}); });
  EXPECT_NE(std::string(e.what()).find("not valid UTF-8"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("\\xFF\\xFE"), std::string::npos) << "bytes shown escaped: " << e.what();
}

TEST(SceneJson, EchoedValuesAreShortAndOnOneLine) {
  const std::string huge(100'000, 'a');
  const InputError name = inputErrorOf([&] { (void)loadScene(kPresetScenes / "hanging-sheet.json", {"name=" + huge}); });
  const std::string what = name.what();
  EXPECT_EQ(name.field(), "/name");
  EXPECT_LT(what.size(), 600u) << "a 100 KB name once came back in full";
  EXPECT_NE(what.find("…"), std::string::npos) << what;
  EXPECT_NE(what.find("100000 bytes"), std::string::npos) << what;

  // "\u0000" once cut the message short; a control character is shown escaped instead.
  TempDir dir;
  const fs::path file = dir.write(
      "nul.json", R"({"cloths": [{"mesh": {"grid": {}}, "material": "royal-target"}], "name": "a\u0000b"})");
  const InputError nul = inputErrorOf([&] { (void)loadScene(file); });
  EXPECT_EQ(nul.field(), "/name");
  EXPECT_NE(std::string(nul.what()).find("\\u0000"), std::string::npos) << nul.what();
  const InputError tab = inputErrorOf([&] { (void)loadScene(kPresetScenes / "hanging-sheet.json", {"name=\"a\\tb\""}); });
  EXPECT_EQ(std::string(tab.what()).find('\t'), std::string::npos) << tab.what();
  EXPECT_NE(std::string(tab.what()).find("a\\tb"), std::string::npos) << tab.what();
}

// Echoes are capped in bytes: a name of 100,000 four-byte characters gives a message no longer
// than one of 100,000 ASCII letters (a cap in characters let it through at four times the size),
// and the cut never leaves half a character behind.
TEST(SceneJson, EchoedMultiByteValuesAreCappedInBytes) {
  const fs::path scene = kPresetScenes / "hanging-sheet.json";
  const std::string ascii = inputErrorOf([&] { (void)loadScene(scene, {"name=" + std::string(100'000, 'n')}); }).what();
  for (const std::string character : {"é", "繊", "\xF0\x9F\xA7\xB5"}) {
    std::string wide;
    for (int i = 0; i < 100'000; ++i) wide += character;
    for (const std::string& override : {"name=" + wide, "cloths.0.material=" + wide}) {
      const InputError e = inputErrorOf([&] { (void)loadScene(scene, {override}); });
      const std::string what = e.what();
      EXPECT_TRUE(isValidUtf8(what)) << what;
      EXPECT_NE(what.find("…"), std::string::npos) << what;
      EXPECT_LE(what.size(), ascii.size() + 40) << what;  // the byte counts differ by a digit or two
    }
  }
}

TEST(SceneJson, AnObjClothIsPinnedByItsVLines) {
  // v lines in an order no face follows: face 1 first uses v 4, then v 3, then v 1.
  TempDir dir;
  dir.write("shuffled.obj",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            "f 4/4 3/3 1/1\nf 3/3 2/2 1/1\n");
  json scene = minimalScene();
  scene["cloths"][0]["mesh"] = json::parse(R"({"obj": {"path": "shuffled.obj"}})");
  scene["cloths"][0]["pins"] = json::parse(R"([{"vertices": [3]}])");
  const fs::path file = dir.write("pinned.json", scene.dump());
  EXPECT_NO_THROW((void)loadScene(file));
  // Only 4 v lines: id 4 is out of range, and the message says ids count v lines.
  const InputError e = inputErrorOf([&] { (void)loadScene(file, {"cloths.0.pins.0.vertices=[4]"}); });
  EXPECT_EQ(e.field(), "/cloths/0/pins/0/vertices/0");
  EXPECT_NE(std::string(e.what()).find("`v` lines"), std::string::npos) << e.what();
}

TEST(SceneJson, MissingFileIsAnInputError) {
  EXPECT_THROW((void)loadScene("/nonexistent/scene.json"), InputError);
}

}  // namespace
}  // namespace weft
