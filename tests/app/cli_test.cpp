// The `weft` command line, run as a user would: the built binary (WEFT_BINARY) in a temporary
// working folder, checking exit codes, messages and the files it writes.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/shell_run.h"
#include "support/snapshot.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kPresetScenes = fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes";
const fs::path kHangingSheet = kPresetScenes / "hanging-sheet.json";

// A tiny version of the hanging sheet: 8 x 8 vertices, 5 frames.
const std::string kTiny = "--set 'cloths.0.mesh.grid.resolution=[8,8]' --frames 5";

using Result = weft::test::ShellResult;

// Each test gets its own working folder (`work/`), so that default output paths such as
// out/<scene> land there and nothing depends on where the test runner was started.
class WeftCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device seed;
    root_ = fs::temp_directory_path() / ("weft_cli_test_" + std::to_string(seed()));
    fs::create_directories(root_ / "work");
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }

  fs::path work() const { return root_ / "work"; }

  // `environment`: assignments put before the command, e.g. "PATH=/nonexistent", or a wrapper such
  // as `env -u DISPLAY` or `xvfb-run`. Pictures come from llvmpipe, as in the renderer's tests.
  Result weft(const std::string& arguments, const std::string& environment = "") const {
    const fs::path log = root_ / "output.txt";
    const std::string command = "cd '" + work().string() + "' && GALLIUM_DRIVER=llvmpipe WEFT_AUTOSAVE_DIR='" + (root_ / "autosave").string() + "' WEFT_CONFIG_DIR='" + (root_ / "config").string() + "' " + environment + " '" +
                                std::string(WEFT_BINARY) + "' " + arguments;
    return weft::test::runShell(command, log);
  }

  fs::path writeScene(const std::string& name, const json& scene) const {
    const fs::path file = root_ / name;
    std::ofstream(file) << scene.dump(2);
    return file;
  }

  static json readJson(const fs::path& file) {
    std::ifstream in(file);
    return json::parse(in);
  }

 private:
  fs::path root_;
};

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

json badScene() {
  return json::parse(R"({"name": "bad", "cloths": [{"mesh": {"grid": {}}, "material": "royal-target"}],
                         "solver": {"dt": -1}})");
}

TEST_F(WeftCli, ValidateAcceptsEveryPresetScene) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kPresetScenes)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const Result r = weft("validate " + quoted(entry.path()));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.rfind("ok: " + entry.path().stem().string() + ": 1 cloths, ", 0), 0u) << r.output;
    // A painted strength and a tear region are named with their images.
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.find("\"tear_strength_map\"") != std::string::npos) {
      EXPECT_NE(r.output.find("    strength map "), std::string::npos) << r.output;
    }
    if (text.find("\"tear_region\"") != std::string::npos) {
      EXPECT_NE(r.output.find("    tear region "), std::string::npos) << r.output;
    }
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST_F(WeftCli, ValidateRejectsABadSceneNamingTheField) {
  const Result r = weft("validate " + quoted(writeScene("bad.json", badScene())));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("/solver/dt"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bad.json"), std::string::npos) << r.output;
}

TEST_F(WeftCli, ValidateAppliesOverrides) {
  const Result r = weft("validate " + quoted(kHangingSheet) + " --set solver.integrator=leapfrog");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("/solver/integrator"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("leapfrog"), std::string::npos) << r.output;
}

TEST_F(WeftCli, RunWritesMetricsWithEveryDocumentedKey) {
  const Result r = weft("run " + quoted(kHangingSheet) + " " + kTiny + " --out result --obj");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const fs::path metricsFile = work() / "result" / "metrics.json";
  ASSERT_TRUE(fs::is_regular_file(metricsFile)) << r.output;
  const json m = readJson(metricsFile);
  for (const char* key : {"scene", "steps", "sim_time_s", "wall_s", "stages", "stage_ms", "vertices", "triangles",
                          "max_strain", "kinetic_energy", "elastic_energy", "gravity_energy", "finite", "solver",
                          "state_hash", "threads", "dt", "substeps"}) {
    EXPECT_TRUE(m.contains(key)) << "metrics.json lacks " << key;
  }
  for (const char* key : {"integrator", "linear_solver", "preconditioner", "linear_iterations", "last_linear_residual",
                          "max_linear_residual", "newton_iterations", "last_newton_residual", "linear_solve_failures",
                          "bdf2_restarts"}) {
    EXPECT_TRUE(m["solver"].contains(key)) << "metrics.json lacks solver." << key;
  }
  EXPECT_EQ(m["scene"], "hanging-sheet");
  EXPECT_EQ(m["finite"], true);
  EXPECT_EQ(m["vertices"], 64);
  EXPECT_EQ(m["steps"], 10);  // 5 frames at 30 fps, dt = 1/60
  EXPECT_NEAR(m["sim_time_s"].get<double>(), 10.0 / 60.0, 1e-9);
  EXPECT_EQ(m["state_hash"].get<std::string>().size(), 16u);
  EXPECT_FALSE(m["stages"].empty());
  EXPECT_FALSE(m["stage_ms"].empty());

  // --obj: frame 0 is the initial state, then one file per frame; nothing half-written remains.
  for (int frame = 0; frame <= 5; ++frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.obj", frame);
    EXPECT_TRUE(fs::is_regular_file(work() / "result" / "frames" / name)) << name;
  }
  for (const auto& entry : fs::recursive_directory_iterator(work() / "result")) {
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
  }
  std::ifstream obj(work() / "result" / "frames" / "frame_0005.obj");
  std::string text((std::istreambuf_iterator<char>(obj)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\nv "), std::string::npos);
  EXPECT_NE(text.find("\nvt "), std::string::npos);
  EXPECT_NE(text.find("\nf "), std::string::npos);
}

TEST_F(WeftCli, RunWritesToOutSceneNameByDefault) {
  const Result r = weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(work() / "out" / "hanging-sheet" / "metrics.json"));
  EXPECT_EQ(r.output, "") << "--quiet should print nothing on success";
}

TEST_F(WeftCli, RunPrintsStagesAndTheirShares) {
  const Result r = weft("run " + quoted(kHangingSheet) + " " + kTiny + " --out result");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("stages:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("membrane"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("%"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("metrics.json"), std::string::npos) << r.output;
}

TEST_F(WeftCli, BadSceneLeavesNoOutputFolder) {
  const fs::path scene = writeScene("bad.json", badScene());
  const Result r = weft("run " + quoted(scene) + " --out result");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(r.output.rfind("weft: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find("/solver/dt"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work() / "result"));

  const Result byDefault = weft("run " + quoted(scene));
  EXPECT_EQ(byDefault.exitCode, 2) << byDefault.output;
  EXPECT_FALSE(fs::exists(work() / "out"));
}

TEST_F(WeftCli, BadOverrideIsBadInput) {
  const Result r = weft("run " + quoted(kHangingSheet) + " --set solver.dt=NaN --out result");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("solver.dt=NaN"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work() / "result"));
}

TEST_F(WeftCli, RunTwiceGivesTheSameStateHash) {
  ASSERT_EQ(weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet --out a").exitCode, 0);
  ASSERT_EQ(weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet --out b").exitCode, 0);
  const json a = readJson(work() / "a" / "metrics.json");
  const json b = readJson(work() / "b" / "metrics.json");
  EXPECT_EQ(a["state_hash"], b["state_hash"]);
}

TEST_F(WeftCli, StateHashDoesNotDependOnThreads) {
  ASSERT_EQ(weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet --threads 1 --out one").exitCode, 0);
  ASSERT_EQ(weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet --threads 2 --out two").exitCode, 0);
  const json one = readJson(work() / "one" / "metrics.json");
  const json two = readJson(work() / "two" / "metrics.json");
  EXPECT_EQ(one["threads"], 1);
  EXPECT_EQ(two["threads"], 2);
  EXPECT_EQ(one["state_hash"], two["state_hash"]);
}

TEST_F(WeftCli, MoreThreadsThanTheMachineHasRunOnAsManyAsItHas) {
  // Oversubscribed threads only wait on each other (run_command.cpp): the run says so and uses the
  // machine's count, with the same results.
  const int machine = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (machine + 1 > 256) GTEST_SKIP() << "the machine has more hardware threads than --threads accepts";
  const Result many =
      weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet --threads " + std::to_string(machine + 1) + " --out many");
  ASSERT_EQ(many.exitCode, 0) << many.output;
  EXPECT_NE(many.output.find("using " + std::to_string(machine)), std::string::npos) << many.output;
  ASSERT_EQ(weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet --threads 1 --out one").exitCode, 0);
  const json manyMetrics = readJson(work() / "many" / "metrics.json");
  EXPECT_EQ(manyMetrics["threads"], machine);
  EXPECT_EQ(manyMetrics["state_hash"], readJson(work() / "one" / "metrics.json")["state_hash"]);
}

// Symplectic Euler at 60 Hz on a stiff woven fabric is far past its stability limit.
const std::string kUnstable =
    "--set 'cloths.0.mesh.grid.resolution=[8,8]' --set solver.integrator=symplectic_euler"
    " --set cloths.0.material=isotropic-stiff --frames 300 --quiet --out result";

TEST_F(WeftCli, UnhealthyRunStopsWhileFiniteAndExits3) {
  const Result r = weft("run " + quoted(kHangingSheet) + " " + kUnstable);
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_NE(r.output.find("unhealthy run at step "), std::string::npos) << r.output;
  ASSERT_TRUE(fs::is_regular_file(work() / "result" / "metrics.json")) << r.output;
  const json m = readJson(work() / "result" / "metrics.json");
  EXPECT_EQ(m["healthy"], false);
  EXPECT_EQ(m["finite"], true) << "stopped before the state turned NaN";
  EXPECT_TRUE(m["max_strain"].is_number()) << m.dump();
  EXPECT_LT(m["steps"].get<int>(), 600);
  EXPECT_EQ(m["health"]["first_failing_step"], m["steps"]);
  for (const char* key : {"time_s", "check", "stage", "value", "limit", "message"}) {
    EXPECT_TRUE(m["health"].contains(key)) << "health lacks " << key;
  }
}

TEST_F(WeftCli, NonFiniteRunStillWritesMetricsAndExits3) {
  // --keep-going runs past the health check's warning until the state is NaN.
  const Result r = weft("run " + quoted(kHangingSheet) + " " + kUnstable + " --keep-going");
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_NE(r.output.find("warning: unhealthy run"), std::string::npos) << r.output;
  ASSERT_TRUE(fs::is_regular_file(work() / "result" / "metrics.json")) << r.output;
  const json m = readJson(work() / "result" / "metrics.json");
  EXPECT_EQ(m["finite"], false);
  EXPECT_EQ(m["healthy"], false);
  // Never 0 or null for a state that has no strain: absent.
  EXPECT_FALSE(m.contains("max_strain")) << m.dump();
}

TEST_F(WeftCli, FailingLinearSolvesAreNotReportedAsAGoodRun) {
  const std::string failing =
      " " + kTiny + " --set solver.linear_solver.max_iterations=1 --set solver.linear_solver.tolerance=1e-14 --out result";
  const Result r = weft("run " + quoted(kHangingSheet) + failing);
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_NE(r.output.find("linear_solver.max_iterations"), std::string::npos) << "names the knob: " << r.output;
  const json m = readJson(work() / "result" / "metrics.json");
  EXPECT_EQ(m["healthy"], false);
  EXPECT_EQ(m["health"]["check"], "linear-solve");
  EXPECT_EQ(m["health"]["first_failing_step"], 3);
  EXPECT_EQ(m["steps"], 3);

  const Result going = weft("run " + quoted(kHangingSheet) + failing + " --keep-going --obj");
  EXPECT_EQ(going.exitCode, 3) << going.output;
  const json all = readJson(work() / "result" / "metrics.json");
  EXPECT_EQ(all["steps"], 10) << "--keep-going finishes the run";
  EXPECT_EQ(all["health"]["first_failing_step"], 3);
  EXPECT_TRUE(fs::is_regular_file(work() / "result" / "frames" / "frame_0005.obj"));

  const Result healthy = weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet --out fine");
  EXPECT_EQ(healthy.exitCode, 0) << healthy.output;
  const json fine = readJson(work() / "fine" / "metrics.json");
  EXPECT_EQ(fine["healthy"], true);
  EXPECT_FALSE(fine.contains("health"));
}

TEST_F(WeftCli, AKilledRerunLeavesThePreviousOutputAsItWas) {
  ASSERT_EQ(weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet --obj --out result").exitCode, 0);
  const json before = readJson(work() / "result" / "metrics.json");
  // A long rerun into the same folder, killed after a second: it must not leave its frames next
  // to the first run's metrics.json.
  const Result killed = weft("run " + quoted(kHangingSheet) +
                                 " --set 'cloths.0.mesh.grid.resolution=[24,24]' --frames 100000 --quiet --obj --out result",
                             "timeout -s KILL 1");
  EXPECT_NE(killed.exitCode, 0);
  EXPECT_EQ(readJson(work() / "result" / "metrics.json"), before);
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(work() / "result" / "frames")) frames += entry.path().extension() == ".obj";
  EXPECT_EQ(frames, 6) << "frames 0..5 of the first run, and no others";
  std::ifstream obj(work() / "result" / "frames" / "frame_0000.obj");
  std::string text((std::istreambuf_iterator<char>(obj)), std::istreambuf_iterator<char>());
  int vertices = 0;
  for (std::size_t at = text.find("\nv "); at != std::string::npos; at = text.find("\nv ", at + 1)) ++vertices;
  EXPECT_EQ(vertices, 64) << "frame 0 is still the 8 x 8 sheet of the first run";

  // The next complete run replaces everything and clears what the killed one staged.
  ASSERT_EQ(weft("run " + quoted(kHangingSheet) + " --set 'cloths.0.mesh.grid.resolution=[8,8]' --frames 2 --quiet --obj --out result").exitCode, 0);
  EXPECT_EQ(readJson(work() / "result" / "metrics.json")["steps"], 4);
  EXPECT_FALSE(fs::exists(work() / "result" / ".weft-partial"));
  EXPECT_FALSE(fs::exists(work() / "result" / "frames" / "frame_0003.obj"));
}

TEST_F(WeftCli, ALongRunSaysSoBeforeItStartsEvenWhenQuiet) {
  // A million frames of a 256 x 256 sheet: weeks of work. One line, then the run (killed here).
  const Result r = weft("run " + quoted(kHangingSheet) +
                            " --set 'cloths.0.mesh.grid.resolution=[256,256]' --frames 1000000 --quiet --out result",
                        "timeout -s KILL 2");
  EXPECT_EQ(r.output.rfind("weft: a long run: 1000000 frames x 2 steps x 1 substep(s) of 65536 cloth vertices, roughly ", 0),
            0u)
      << r.output;
  EXPECT_NE(r.output.find(" days"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work() / "result" / "metrics.json"));

  const Result small = weft("run " + quoted(kHangingSheet) + " " + kTiny + " --quiet --out small");
  EXPECT_EQ(small.output, "") << "a short run says nothing with --quiet";
}

TEST_F(WeftCli, HostileInputIsBadInputWithAShortMessage) {
  const auto expectShortBadInput = [&](const std::string& arguments, const std::string& phrase) {
    SCOPED_TRACE(arguments.substr(0, 120));
    const Result r = weft(arguments);
    EXPECT_EQ(r.exitCode, 2) << r.output.substr(0, 2000);
    EXPECT_NE(r.output.find(phrase), std::string::npos) << r.output.substr(0, 2000);
    EXPECT_LT(r.output.size(), 700u) << r.output.substr(0, 2000);
  };
  // Nested 100,000 deep: once a segfault in the JSON library's dump().
  const int depth = 100'000;
  std::ofstream(work() / "deep.json") << R"({"cloths": [{"mesh": {"grid": {}}, "material": "royal-target"}], "solver": {"dt": )"
                                      << std::string(depth, '[') << std::string(depth, ']') << "}}";
  expectShortBadInput("validate deep.json", "nested deeper than 64");
  std::ofstream(work() / "twice.json") << R"({"cloths": [{"mesh": {"grid": {}}, "material": "royal-target"}],
                                             "solver": {"dt": 0.01, "dt": 0.5}})";
  expectShortBadInput("run twice.json --out result", "duplicate key \"dt\"");
  EXPECT_FALSE(fs::exists(work() / "result"));
  // Once a segfault in the OpenMP runtime, and once "not in range" with a 309-digit bound.
  expectShortBadInput("run " + quoted(kHangingSheet) + " --threads 100000", "[1, 256]");
  expectShortBadInput("run " + quoted(kHangingSheet) + " --frames abc", "'abc' is not an integer in [0, 1000000]");
  // Once exit 1 (bad_alloc, "File name too long", json type_error 316).
  expectShortBadInput("validate " + quoted(kHangingSheet) + " --set 'cloths.0.mesh.grid.resolution=[1000000,1000000]'",
                      "/cloths/0/mesh/grid/resolution/0");
  expectShortBadInput("run " + quoted(kHangingSheet) + " --set contact.thickness=3.7 --out result", "(0, 0.1] m");
  EXPECT_FALSE(fs::exists(work() / "result"));
  expectShortBadInput("validate " + quoted(kHangingSheet) + " --set cloths.0.material=" + std::string(300, 'x'),
                      "at most 100 bytes");
  expectShortBadInput("validate " + quoted(kHangingSheet) + " --set $(printf 'name=\\377')", "not valid UTF-8");
  // Once a 1 MB echo of the name, and 355 KB of one line per vertex.
  expectShortBadInput("validate " + quoted(kHangingSheet) + " --set name=" + std::string(100'000, 'n'), "/name");
  expectShortBadInput("validate " + quoted(kHangingSheet) + " --set cloths.0.mesh.grid.width=1e308", "(0, 100] m");
}

TEST_F(WeftCli, ValidateShowsHowAnObjClothsVLinesBecameVertices) {
  std::ofstream(work() / "seam.obj") << "v 9 9 9\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0.5 0\n"
                                        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 2 0\nvt 2 1\nvt 3 0.5\n"
                                        "f 2/1 3/2 4/3\nf 2/1 4/3 5/4\nf 3/5 6/7 4/6\n";
  json scene = badScene();
  scene.erase("solver");
  scene["cloths"][0]["mesh"] = {{"obj", {{"path", (work() / "seam.obj").string()}}}};
  scene["cloths"][0]["pins"] = json::parse(R"([{"vertices": [2]}])");
  const fs::path file = writeScene("seam.json", scene);
  const Result summary = weft("validate " + quoted(file));
  EXPECT_EQ(summary.exitCode, 0) << summary.output;
  EXPECT_NE(summary.output.find("6 `v` lines of seam.obj"), std::string::npos) << summary.output;
  EXPECT_NE(summary.output.find("2 split on UV seams, 1 used by no face"), std::string::npos) << summary.output;
  const Result listed = weft("validate " + quoted(file) + " --vertex-map");
  EXPECT_NE(listed.output.find("v 0 -> (unused)"), std::string::npos) << listed.output;
  EXPECT_NE(listed.output.find("v 2 -> 1, 2"), std::string::npos) << listed.output;
  EXPECT_NE(listed.output.find("v 5 -> 6"), std::string::npos) << listed.output;
  const Result unused = weft("validate " + quoted(file) + " --set 'cloths.0.pins.0.vertices=[0]'");
  EXPECT_EQ(unused.exitCode, 2) << unused.output;
  EXPECT_NE(unused.output.find("which no face uses"), std::string::npos) << unused.output;
}

TEST_F(WeftCli, EditRejectsABadSceneBeforeOpeningAnything) {
  const Result r = weft("edit " + quoted(writeScene("bad.json", badScene())), "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("/solver/dt"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("cannot open a window"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work() / "out"));
}

TEST_F(WeftCli, UsageErrorsExit2) {
  EXPECT_EQ(weft("run").exitCode, 2);                                         // missing SCENE
  EXPECT_EQ(weft("run " + quoted(kHangingSheet) + " --frobnicate").exitCode, 2);  // unknown option
  EXPECT_EQ(weft("run " + quoted(kHangingSheet) + " --frames -3").exitCode, 2);
  EXPECT_EQ(weft("bench --integrators euler").exitCode, 2);
  EXPECT_EQ(weft("fly").exitCode, 2);
  EXPECT_EQ(weft("--help").exitCode, 0);
}

// CLI11's own number checks let "nan" through (every comparison with NaN is false): a NaN
// duration ran the accuracy study on it, and NaN seconds rendered study clips.
TEST_F(WeftCli, NumbersOnTheCommandLineMustBeFiniteAndInRange) {
  for (const std::string args : {"bench --accuracy --accuracy-duration nan --accuracy-csv acc.csv",
                                 "bench --accuracy --accuracy-duration 1e308 --accuracy-csv acc.csv",
                                 "bench --solver-accuracy --solver-accuracy-duration inf",
                                 "bench --contact --contact-warmup -1", "bench --sizes 6,abc",
                                 "study-videos --out clips --seconds-per-part nan",
                                 "study-videos --out clips --seconds-per-part 0.5s"}) {
    const Result r = weft(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    EXPECT_TRUE(r.output.find("is not a number in") != std::string::npos ||
                r.output.find("is outside") != std::string::npos ||
                r.output.find("is not an integer in") != std::string::npos)
        << args << "\n" << r.output;
    EXPECT_LT(r.output.size(), 400u) << args;
  }
  EXPECT_FALSE(fs::exists(work() / "acc.csv"));
  EXPECT_FALSE(fs::exists(work() / "clips"));
}

TEST_F(WeftCli, BenchWritesACsvNamingTheMachine) {
  const Result r = weft("bench --sizes 6 --integrators lbe,symplectic --solvers cg --steps 2 --warmup 1 --repeats 3 "
                        "--csv bench/out.csv");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream csv(work() / "bench" / "out.csv");
  std::vector<std::string> lines;
  for (std::string line; std::getline(csv, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 4u) << r.output;  // machine line, header, lbe+cg, symplectic
  EXPECT_EQ(lines[0].rfind("# weft bench; machine: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find("cores: "), std::string::npos) << lines[0];
  EXPECT_EQ(lines[1].rfind("size,vertices,", 0), 0u) << lines[1];
  EXPECT_EQ(lines[2].rfind("6,36,", 0), 0u) << lines[2];
  EXPECT_NE(lines[2].find("linearized_backward_euler,cg"), std::string::npos) << lines[2];
  EXPECT_NE(lines[3].find("symplectic_euler,none"), std::string::npos) << lines[3];
  EXPECT_NE(lines[3].find(",true,"), std::string::npos) << "the chosen substeps should keep it stable: " << lines[3];
}

// The tearing benchmark reports the steps that tore apart from the median step: they carry the
// surgery and the patched stress, so they are a live demo's slowest frames.
TEST_F(WeftCli, TearingBenchReportsTheStepsThatToreApart) {
  const Result r = weft("bench --tearing --tearing-resolution 16 --tearing-rows growth --steps 20 --repeats 2 "
                        "--tearing-csv tearing.csv");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream csv(work() / "tearing.csv");
  std::vector<std::string> lines;
  for (std::string line; std::getline(csv, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 3u) << r.output;  // machine line, header, the growth row
  std::vector<std::string> header, row;
  for (auto [line, fields] : {std::pair{&lines[1], &header}, std::pair{&lines[2], &row}}) {
    std::stringstream in(*line);
    for (std::string field; std::getline(in, field, ',');) fields->push_back(field);
  }
  ASSERT_EQ(header.size(), row.size()) << lines[1] << "\n" << lines[2];
  std::map<std::string, double> value;
  for (std::size_t k = 0; k < header.size(); ++k) {
    if (k >= 5) value[header[k]] = std::stod(row[k]);
  }
  ASSERT_TRUE(value.contains("tearing_steps_per_repeat")) << lines[1];
  // The window holds the pulled sheet's first tears at every resolution (docs/tearing.md, crack growth).
  EXPECT_GE(value["tearing_steps_per_repeat"], 1.0) << lines[2];
  EXPECT_LE(value["tearing_steps_per_repeat"], 20.0) << lines[2];
  EXPECT_GT(value["tears_per_repeat"], 0.0) << lines[2];
  EXPECT_GT(value["median_tearing_step_tearing_ms"], 0.0) << lines[2];
  EXPECT_GE(value["median_tearing_step_ms"], value["median_tearing_step_tearing_ms"]) << lines[2];
  EXPECT_GT(value["window_tearing_share"], 0.0) << lines[2];
  EXPECT_LT(value["window_tearing_share"], 1.0) << lines[2];
}

TEST_F(WeftCli, AccuracyStudyReportsErrorsThatShrinkWithEachKnob) {
  const Result r = weft("bench --accuracy --accuracy-resolution 5 --accuracy-duration 0.1 --accuracy-csv acc.csv");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream csv(work() / "acc.csv");
  std::map<std::string, std::vector<double>> errors;  // knob -> max errors in the order studied
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "knob,value,integrator,dt,max_error_mm,rms_error_mm,ms_per_sixtieth_s");
  while (std::getline(csv, line)) {
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    ASSERT_EQ(fields.size(), 7u) << line;
    errors[fields[0] + "/" + fields[2]].push_back(std::stod(fields[4]));
  }
  ASSERT_EQ(errors["newton_iterations/newton"].size(), 5u);
  ASSERT_EQ(errors["cg_tolerance/linearized_backward_euler"].size(), 5u);
  ASSERT_EQ(errors["time_step/newton"].size(), 4u);
  // More Newton iterations, a tighter CG tolerance and a smaller step each leave less error.
  EXPECT_LT(errors["newton_iterations/newton"].back(), errors["newton_iterations/newton"].front());
  EXPECT_LT(errors["cg_tolerance/linearized_backward_euler"].back(), errors["cg_tolerance/linearized_backward_euler"].front());
  EXPECT_LT(errors["time_step/newton"].back(), errors["time_step/newton"].front());
  EXPECT_LT(errors["time_step/linearized_backward_euler"].back(), errors["time_step/linearized_backward_euler"].front());
  // BDF2 has rows too, and is far more accurate than backward Euler at the same step.
  ASSERT_EQ(errors["time_step/bdf2"].size(), 4u);
  ASSERT_EQ(errors["time_step/bdf2_newton"].size(), 4u);
  EXPECT_LT(errors["time_step/bdf2"].back(), errors["time_step/bdf2"].front());
  EXPECT_LT(errors["time_step/bdf2"].back(), errors["time_step/linearized_backward_euler"].back());
  EXPECT_LT(errors["time_step/bdf2_newton"].back(), errors["time_step/newton"].back());
}

// BDF2 through `weft run` on a tearing scene: it tears, stays finite, and restarts its history
// (one backward Euler step) after the steps that tore.
TEST_F(WeftCli, RunTearsASheetWithBdf2) {
  const Result r = weft("run " + quoted(kPresetScenes / "sheet-pulled-apart.json") +
                        " --set solver.integrator=bdf2 --set 'cloths.0.mesh.grid.resolution=[16,16]' --out torn --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const json m = readJson(work() / "torn" / "metrics.json");
  EXPECT_EQ(m["finite"], true);
  EXPECT_EQ(m["solver"]["integrator"], "bdf2");
  EXPECT_GT(m["tears"].get<long long>(), 0);
  EXPECT_GT(m["solver"]["bdf2_restarts"].get<long long>(), 1);
  EXPECT_LT(m["solver"]["bdf2_restarts"].get<long long>(), m["steps"].get<long long>() / 2);
}

}  // namespace

// --png renders through EGL; where EGL cannot start the tests below that need pictures skip.
bool eglUnavailable(const Result& r) { return r.exitCode == 1 && r.output.find("cannot start headless OpenGL") != std::string::npos; }

TEST_F(WeftCli, RunPngWritesEveryNthFrameAndARenderBlock) {
  const Result r = weft("run " + quoted(kHangingSheet) + " " + kTiny + " --png --every 2 --size 64x48 --out result");
  if (eglUnavailable(r)) GTEST_SKIP() << "headless OpenGL cannot start here: " << r.output;
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const fs::path frames = work() / "result" / "frames";
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(frames)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frame_0000.png", "frame_0002.png", "frame_0004.png"}));
  std::ifstream png(frames / "frame_0000.png", std::ios::binary);
  char signature[8] = {};
  png.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  const json m = readJson(work() / "result" / "metrics.json");
  ASSERT_TRUE(m.contains("render")) << m.dump(2);
  EXPECT_FALSE(m["render"]["gl_renderer"].get<std::string>().empty());
  EXPECT_EQ(m["render"]["size"], json::array({64, 48}));
  EXPECT_EQ(m["render"]["frames"], 3);
  EXPECT_NE(r.output.find("PNG image(s)"), std::string::npos) << r.output;
}

TEST_F(WeftCli, PngWithoutEglFailsBeforeWritingAnything) {
  // glvnd finds no EGL vendor library: EGL cannot start.
  const Result r = weft("run " + quoted(kHangingSheet) + " " + kTiny + " --png --out result",
                        "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/egl_vendor.json");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("cannot start headless OpenGL"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work() / "result"));
}

TEST_F(WeftCli, VideoWithoutFfmpegSaysSoAndStillWritesFrames) {
  const Result r = weft("run " + quoted(kHangingSheet) + " " + kTiny + " --video --every 5 --size 32x32 --out result",
                        "PATH=/nonexistent");
  if (eglUnavailable(r)) GTEST_SKIP() << "headless OpenGL cannot start here: " << r.output;
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("ffmpeg is not installed"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(work() / "result" / "frames" / "frame_0005.png"));
  EXPECT_FALSE(fs::exists(work() / "result" / "frames.mp4"));
}

TEST_F(WeftCli, BadImageSizeIsBadInput) {
  const Result r = weft("run " + quoted(kHangingSheet) + " " + kTiny + " --png --size 64by48 --out result");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work() / "result"));
}

namespace {

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path != nullptr ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    if (!folder.empty() && ::access((fs::path(folder) / program).c_str(), X_OK) == 0) return true;
  }
  return false;
}

// `weft edit` in a window, on a virtual X display (Xvfb) with Mesa's software GL.
std::string virtualDisplay() { return "LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s '-screen 0 1440x900x24'"; }

// Pixels with colour in them: the background and the ground are grey, the cloth's weave is not.
long long colouredPixels(const weft::test::RgbaImage& image) {
  long long count = 0;
  for (std::size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
    const auto [lo, hi] = std::minmax({image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]});
    if (hi - lo > 40) ++count;
  }
  return count;
}

TEST_F(WeftCli, EditShowsTheSceneInAWindowAndTakesAScreenshot) {
  if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not on PATH (apt-get install xvfb xauth)";
  const Result r = weft("edit " + quoted(kHangingSheet) + " --frames 5 --screenshot shot.png", virtualDisplay());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("cannot open a window"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("wrote shot.png"), std::string::npos) << r.output;
  const weft::test::RgbaImage shot = weft::test::readPng(work() / "shot.png");
  EXPECT_EQ(shot.width, 1440);
  EXPECT_EQ(shot.height, 900);
  // The sheet fills a good part of the default framing.
  EXPECT_GT(colouredPixels(shot), shot.width * shot.height / 50) << "no cloth in the screenshot";
  EXPECT_FALSE(fs::exists(work() / "out")) << "a window run writes no headless frames";
}

TEST_F(WeftCli, EditInAWindowStopsOnANonFiniteStateWithoutCrashing) {
  if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not on PATH (apt-get install xvfb xauth)";
  // The unstable set-up of NonFiniteRunStillWritesMetricsAndExits3, watched in a window (it blows
  // up within a few frames; the window keeps showing the last state until --frames is reached).
  const Result r = weft("edit " + quoted(kHangingSheet) +
                            " --set 'cloths.0.mesh.grid.resolution=[8,8]' --set solver.integrator=symplectic_euler"
                            " --set cloths.0.material=isotropic-stiff --frames 60 --play",
                        virtualDisplay());
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_NE(r.output.find("became non-finite"), std::string::npos) << r.output;
}

// With no usable display `weft edit` says why and runs headless, writing PNG frames.
void expectHeadlessFallback(const Result& r, const fs::path& frames, int lastFrame,
                            const std::string& scene = "hanging-sheet") {
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("weft edit: cannot open a window ("), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("); running headless instead"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("PNG image(s)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("out/" + scene + "/frames"), std::string::npos) << "where the images are: " << r.output;
  for (int frame = 0; frame <= lastFrame; ++frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    EXPECT_TRUE(fs::is_regular_file(frames / name)) << name;
  }
}

TEST_F(WeftCli, EditWithoutADisplayRunsHeadless) {
  const Result r = weft("edit " + quoted(kHangingSheet) + " --frames 3 --screenshot last.png",
                        "env -u DISPLAY -u WAYLAND_DISPLAY");
  if (eglUnavailable(r)) GTEST_SKIP() << "headless OpenGL cannot start here: " << r.output;
  expectHeadlessFallback(r, work() / "out" / "hanging-sheet" / "frames", 3);
  EXPECT_NE(r.output.find("neither DISPLAY nor WAYLAND_DISPLAY is set"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work() / "out" / "hanging-sheet" / "frames" / "frame_0004.png"));
  EXPECT_EQ(weft::test::readPng(work() / "last.png").width, 960) << "the last headless frame, copied";
}

TEST_F(WeftCli, EditWithAnUnreachableDisplayRunsHeadless) {
  const Result r = weft("edit " + quoted(kHangingSheet) + " --frames 2", "env -u WAYLAND_DISPLAY DISPLAY=:987");
  if (eglUnavailable(r)) GTEST_SKIP() << "headless OpenGL cannot start here: " << r.output;
  expectHeadlessFallback(r, work() / "out" / "hanging-sheet" / "frames", 2);
  EXPECT_NE(r.output.find(":987"), std::string::npos) << "GLFW's reason names the display: " << r.output;
}

TEST_F(WeftCli, NoArgumentsEditsTheDefaultScene) {
  // The editor's default scene tears (a ball into denim, issue 21 item 8); it comes from
  // $WEFT_DATA_DIR when that has one: a 2-frame, 8 x 8 copy here.
  json scene = readJson(kPresetScenes / "ball-into-sheet-table4.1-cloth2.json");
  ASSERT_TRUE(scene["cloths"][0].contains("tear_table")) << "the default scene can tear";
  scene["output"]["frames"] = 2;
  scene["cloths"][0]["mesh"]["grid"]["resolution"] = json::array({8, 8});
  const fs::path data = work() / "data";
  fs::create_directories(data / "presets" / "scenes");
  std::ofstream(data / "presets" / "scenes" / "ball-into-sheet-table4.1-cloth2.json") << scene.dump(2);
  const Result r = weft("", "env -u DISPLAY -u WAYLAND_DISPLAY WEFT_DATA_DIR=" + quoted(data));
  if (eglUnavailable(r)) GTEST_SKIP() << "headless OpenGL cannot start here: " << r.output;
  const std::string name = scene["name"];
  expectHeadlessFallback(r, work() / "out" / name / "frames", 2, name);
}

}  // namespace
