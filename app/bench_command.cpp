// `weft bench`: time the hanging sheet over mesh sizes, integrators and linear solvers.
//
// Each configuration is run `repeats` times from a fresh World: warm-up steps first (the first
// steps allocate, factor and settle), then `steps` timed steps. The simulation is deterministic,
// so every repeat does the same work and the median time per step is a fair summary of the noise.
// Results go to a table on stdout and a CSV whose header names the machine, so results from
// different machines can be committed side by side.
#include <sys/utsname.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "accuracy_study.h"
#include "bench_stats.h"
#include "cli_checks.h"
#include "command.h"
#include "default_scene.h"
#include "contact_bench.h"
#include "solver_accuracy_bench.h"
#include "tearing_bench.h"
#include "machine_info.h"
#include "material/elasticity.h"
#include "metrics_writer.h"
#include "roofline.h"
#include "scene/scene_json.h"
#include "scene/scene_limits.h"
#include "sim/world.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;

struct BenchOptions {
  std::vector<int> sizes{32, 64, 128, 256};
  std::vector<std::string> integrators{"lbe", "newton", "symplectic"};
  std::vector<std::string> solvers{"cg", "cholmod"};
  int steps = 20;
  int warmup = 5;
  int repeats = 3;
  int threads = 1;
  int symplecticSubsteps = 0;  // 0: chosen from the mesh and material (see stableSymplecticSubsteps)
  std::string csv = "out/bench/bench.csv";
  std::string scene;  // default: presets/scenes/hanging-sheet.json of this source tree
  bool accuracy = false;  // run the accuracy study instead of the timing benchmark
  AccuracyOptions accuracyOptions;
  bool contact = false;   // time the collision stage instead
  ContactBenchOptions contactOptions;
  bool tearing = false;   // time the tearing stage instead
  TearingBenchOptions tearingOptions;
  bool solverAccuracy = false;  // compare the linear solvers' trajectories instead
  bool cpuTime = false;         // time steps by the process's CPU time instead of the wall clock
  SolverAccuracyOptions solverAccuracyOptions;
};

struct Configuration {
  int size = 0;
  std::string integrator;  // short name, as on the command line
  std::string solver;      // "none" for the explicit integrator
};

struct Result {
  Configuration config;
  int vertices = 0;
  int triangles = 0;
  double dt = 0.0;
  int substeps = 1;
  double medianMsPerStep = 0.0;
  double minMsPerStep = 0.0;
  double maxMsPerStep = 0.0;
  double linearIterationsPerStep = 0.0;
  double newtonIterationsPerStep = 0.0;
  bool finite = true;
  std::vector<std::pair<std::string, double>> stageShares;  // name, percent of the timed steps
};

std::string sceneIntegratorName(const std::string& shortName) {
  if (shortName == "lbe") return "linearized_backward_euler";
  if (shortName == "newton") return "newton";
  if (shortName == "bdf2") return "bdf2";
  if (shortName == "bdf2n") return "bdf2_newton";
  return "symplectic_euler";
}

// An explicit step is stable only below the period of the stiffest mode. For a mesh of edge
// length h, membrane waves travel at c = sqrt(k / rho) (k: largest membrane tangent stiffness,
// N/m; rho: area density) and the shortest period is about h / c; bending waves are dispersive
// and limit the step to about h^2 / sqrt(kb / rho). A factor 1/2 covers the triangle mesh not
// being a lattice. Returns substeps per scene step (dt).
int stableSymplecticSubsteps(const Scene& scene) {
  double stableDt = scene.solver.dt;
  for (const ClothSpec& cloth : scene.cloths) {
    if (!cloth.grid) continue;
    const GridSpec& g = *cloth.grid;
    const double h = std::min(g.width / (g.resolutionX - 1), g.height / (g.resolutionY - 1));
    double k = 0.0;
    for (const Eigen::Vector3d& strain :
         {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(0.1, 0.1, 0.1)}) {
      const Eigen::Matrix3d tangent = evaluateElasticity(cloth.material.elasticity, strain, true).tangent;
      k = std::max(k, tangent.cwiseAbs().rowwise().sum().maxCoeff());  // bounds the largest eigenvalue
    }
    double kb = cloth.material.bending.stiffness;
    if (cloth.material.bending.model == BendingSettings::Model::Measured) {
      for (const auto& row : cloth.material.bending.measured) kb = std::max(kb, *std::max_element(row.begin(), row.end()));
    }
    kb *= cloth.material.bending.stiffnessScale;
    const double rho = cloth.material.areaDensity;
    stableDt = std::min(stableDt, 0.5 * h / std::sqrt(k / rho));
    if (kb > 0.0) stableDt = std::min(stableDt, 0.5 * h * h / std::sqrt(kb / rho));
  }
  return std::max(1, static_cast<int>(std::ceil(scene.solver.dt / stableDt)));
}


std::vector<std::string> overridesFor(const Configuration& config, const BenchOptions& options) {
  std::vector<std::string> overrides{
      "cloths.0.mesh.grid.resolution=[" + std::to_string(config.size) + "," + std::to_string(config.size) + "]",
      "solver.integrator=" + sceneIntegratorName(config.integrator),
      "solver.threads=" + std::to_string(options.threads),
  };
  // "amg" is the CG with the multigrid preconditioner; "cg" is the CG with the lagged
  // Cholesky, named explicitly so that it does not follow the default.
  if (config.solver == "amg" || config.solver == "cg") {
    overrides.push_back("solver.linear_solver.type=cg");
    overrides.push_back(config.solver == "amg" ? "solver.linear_solver.preconditioner=amg"
                                               : "solver.linear_solver.preconditioner=lagged_cholesky");
  } else if (config.solver != "none") {
    overrides.push_back("solver.linear_solver.type=" + config.solver);
  }
  return overrides;
}

// The CPU time of the whole process (all its threads), ms. On a shared machine it leaves out the
// time the process waits for a core, which the wall clock counts; with one thread it is that
// thread's time.
double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

Result runConfiguration(const Configuration& config, const BenchOptions& options, const fs::path& sceneFile) {
  Scene scene = loadScene(sceneFile, overridesFor(config, options));
  if (config.integrator == "symplectic") {
    // Reported per 1/60 s step, split into as many substeps as stability needs, so that its time
    // per step compares with the implicit integrators' at the same simulated time.
    scene.solver.dt = 1.0 / 60.0;
    scene.solver.substeps =
        options.symplecticSubsteps > 0 ? options.symplecticSubsteps : stableSymplecticSubsteps(scene);
  }

  Result result;
  result.config = config;
  result.dt = scene.solver.dt;
  result.substeps = scene.solver.substeps;
  std::vector<double> msPerStep;
  std::map<std::string, double> stageMs;
  std::vector<std::string> stageOrder;
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    World world(scene);
    for (int s = 0; s < options.warmup; ++s) world.step();
    const StageProfile before = world.profile();
    const SolverStats statsBefore = world.solverStats();

    const double start = options.cpuTime ? processCpuMs() : 0.0;
    const auto wallStart = std::chrono::steady_clock::now();
    for (int s = 0; s < options.steps; ++s) world.step();
    const double ms = options.cpuTime
                          ? processCpuMs() - start
                          : std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wallStart).count();
    msPerStep.push_back(ms / options.steps);

    const StageProfile& after = world.profile();
    for (std::size_t k = 0; k < after.names.size(); ++k) {
      const auto it = std::find(before.names.begin(), before.names.end(), after.names[k]);
      const double earlier = it == before.names.end() ? 0.0 : before.totalMs[static_cast<std::size_t>(it - before.names.begin())];
      if (!stageMs.count(after.names[k])) stageOrder.push_back(after.names[k]);
      stageMs[after.names[k]] += after.totalMs[k] - earlier;
    }
    const SolverStats& stats = world.solverStats();
    result.linearIterationsPerStep = double(stats.linearIterations - statsBefore.linearIterations) / options.steps;
    result.newtonIterationsPerStep = double(stats.newtonIterations - statsBefore.newtonIterations) / options.steps;
    result.finite = result.finite && world.metrics().finite;
    result.vertices = 0;
    result.triangles = 0;
    for (int i = 0; i < world.clothCount(); ++i) {
      result.vertices += world.cloth(i).vertexCount();
      result.triangles += world.cloth(i).triangleCount();
    }
  }
  result.medianMsPerStep = median(msPerStep);
  result.minMsPerStep = *std::min_element(msPerStep.begin(), msPerStep.end());
  result.maxMsPerStep = *std::max_element(msPerStep.begin(), msPerStep.end());
  double total = 0.0;
  for (const auto& [name, ms] : stageMs) total += ms;
  for (const auto& name : stageOrder) result.stageShares.emplace_back(name, total > 0 ? 100.0 * stageMs[name] / total : 0.0);
  return result;
}

// ---------------------------------------------------------------------------------------------
std::string sharesText(const Result& r, const char* separator, int limit) {
  std::vector<std::pair<std::string, double>> shares = r.stageShares;
  if (limit > 0) {
    std::stable_sort(shares.begin(), shares.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    if (static_cast<int>(shares.size()) > limit) shares.resize(static_cast<std::size_t>(limit));
  }
  std::string out;
  char item[96];
  for (const auto& [name, percent] : shares) {
    std::snprintf(item, sizeof item, "%s%s %.1f%%", out.empty() ? "" : separator, name.c_str(), percent);
    out += item;
  }
  return out;
}

std::string csvText(const std::vector<Result>& results, const BenchOptions& options, const fs::path& sceneFile) {
  std::ostringstream csv;
  csv << benchCsvMachineLine(options.cpuTime ? "weft bench --cpu-time" : "weft bench", options.threads, sceneFile.string());
  csv << "size,vertices,triangles,integrator,linear_solver,dt,substeps,warmup,steps,repeats,"
         "median_ms_per_step,min_ms_per_step,max_ms_per_step,ms_per_step_per_1000_vertices,"
         "linear_iterations_per_step,newton_iterations_per_step,finite,stage_shares\n";
  char line[512];
  for (const Result& r : results) {
    std::snprintf(line, sizeof line, "%d,%d,%d,%s,%s,%.9g,%d,%d,%d,%d,%.4f,%.4f,%.4f,%.4f,%.2f,%.2f,%s,", r.config.size,
                  r.vertices, r.triangles, sceneIntegratorName(r.config.integrator).c_str(), r.config.solver.c_str(),
                  r.dt, r.substeps, options.warmup, options.steps, options.repeats, r.medianMsPerStep, r.minMsPerStep,
                  r.maxMsPerStep, 1000.0 * r.medianMsPerStep / std::max(1, r.vertices), r.linearIterationsPerStep,
                  r.newtonIterationsPerStep, r.finite ? "true" : "false");
    csv << line << '"' << sharesText(r, ";", 0) << "\"\n";
  }
  return csv.str();
}

int runBench(const BenchOptions& options) {
  const fs::path sceneFile = options.scene.empty() ? defaultScenePath() : fs::path(options.scene);

  std::vector<Configuration> configs;
  for (int size : options.sizes) {
    for (const auto& integrator : options.integrators) {
      if (integrator == "symplectic") {
        configs.push_back({size, integrator, "none"});  // no linear solve: one run is enough
        continue;
      }
      for (const auto& solver : options.solvers) configs.push_back({size, integrator, solver});
    }
  }

  // Every configuration is loaded once before anything is timed, so a bad scene or size fails
  // in a second rather than after an hour of benchmarking.
  try {
    for (const auto& config : configs) (void)loadScene(sceneFile, overridesFor(config, options));
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }

  std::printf("%6s %8s %-11s %-8s %6s %12s %14s %10s %6s  %s\n", "size", "vertices", "integrator", "solver",
              "subst", options.cpuTime ? "cpu ms/step" : "ms/step", "ms/step/1k v", "lin it/st", "finite", "top stages");
  std::vector<Result> results;
  for (const auto& config : configs) {
    Result r;
    try {
      r = runConfiguration(config, options, sceneFile);
    } catch (const InputError& e) {
      std::cerr << "weft: " << e.what() << "\n";
      return kExitBadInput;
    }
    std::printf("%6d %8d %-11s %-8s %6d %12.3f %14.4f %10.1f %6s  %s\n", config.size, r.vertices,
                config.integrator.c_str(), config.solver.c_str(), r.substeps, r.medianMsPerStep,
                1000.0 * r.medianMsPerStep / std::max(1, r.vertices), r.linearIterationsPerStep,
                r.finite ? "yes" : "NO", sharesText(r, ", ", 3).c_str());
    std::fflush(stdout);
    results.push_back(std::move(r));
  }

  if (!writeBenchCsv(options.csv, csvText(results, options, sceneFile))) return kExitFailure;

  // The roofline (roofline.h): per size, the CG's product with the system matrix against the
  // machine's triad bandwidth, from memory and at the product's own footprint (a 64² matrix fits
  // the caches). Measured after the cases so that their times are not disturbed.
  const double triad = measureTriadBandwidth();
  std::printf("\nmatrix-vector product of the CG (one thread) against the triad bandwidth (from memory: %.2f GB/s):\n", triad);
  std::printf("%6s %12s %12s %10s %9s %18s %9s\n", "size", "MB/product", "ms/product", "GB/s", "of triad",
              "triad same MB GB/s", "of that");
  for (int size : options.sizes) {
    const Scene scene = loadScene(sceneFile, overridesFor({size, "lbe", "cg"}, options));
    const ProductBandwidth product = measureProductBandwidth(scene, sceneFile);
    const double cachedTriad = measureTriadBandwidth(static_cast<long>(product.megabytes * 1e6 / 24.0), 50);
    std::printf("%6d %12.3f %12.4f %10.2f %8.0f%% %18.2f %8.0f%%\n", size, product.megabytes, product.ms,
                product.gigabytesPerSecond(), 100.0 * product.gigabytesPerSecond() / triad, cachedTriad,
                100.0 * product.gigabytesPerSecond() / cachedTriad);
  }
  const bool allFinite = std::all_of(results.begin(), results.end(), [](const Result& r) { return r.finite; });
  return allFinite ? kExitOk : kExitNonFinite;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* cli = app.add_subcommand("bench", "Time the hanging sheet over sizes, integrators and linear solvers");
  cli->add_option("--sizes", options->sizes, "Grid resolutions (vertices per side), comma-separated")
      ->delimiter(',')
      ->check(integerIn(2, 4096))
      ->capture_default_str();
  cli->add_option("--integrators", options->integrators,
                  "Any of lbe, newton, symplectic, bdf2, bdf2n (BDF2 solved by Newton), comma-separated")
      ->delimiter(',')
      ->check(CLI::IsMember({"lbe", "newton", "symplectic", "bdf2", "bdf2n"}))
      ->capture_default_str();
  cli->add_option("--solvers", options->solvers,
                  "Linear solvers for the implicit integrators: cg (lagged Cholesky), amg (CG with multigrid), cholmod, "
                  "comma-separated")
      ->delimiter(',')
      ->check(CLI::IsMember({"cg", "amg", "cholmod"}))
      ->capture_default_str();
  cli->add_option("--steps", options->steps, "Timed steps per repeat")->check(integerIn(1, 1'000'000))->capture_default_str();
  cli->add_option("--warmup", options->warmup, "Untimed steps before timing")
      ->check(integerIn(0, 1'000'000))
      ->capture_default_str();
  cli->add_option("--repeats", options->repeats, "Repeats (the median is reported)")
      ->check(integerIn(1, 1000))
      ->capture_default_str();
  cli->add_option("--threads", options->threads, "Worker threads")->check(integerIn(1, limits::kMaxThreads))->capture_default_str();
  cli->add_option("--symplectic-substeps", options->symplecticSubsteps,
                  "Substeps per 1/60 s step for symplectic Euler (default: estimated for stability)")
      ->check(integerIn(1, limits::kMaxSubsteps));
  cli->add_option("--csv", options->csv, "CSV output file")->capture_default_str();
  cli->add_flag("--cpu-time", options->cpuTime,
                "Time the steps by the process's CPU time instead of the wall clock (on a shared, oversubscribed machine "
                "the wall clock also counts the waits for a core; with several threads this sums their times)");
  cli->add_option("--scene", options->scene, "Scene to benchmark (its first cloth must be a grid)");
  cli->add_flag("--accuracy", options->accuracy,
                "Instead of timing sizes, measure the error each accuracy knob leaves (time step, Newton iterations, "
                "CG tolerance, resolution) and its cost");
  cli->add_option("--accuracy-duration", options->accuracyOptions.duration, "Accuracy study: simulated seconds compared")
      ->check(numberIn(0.001, 60.0))
      ->capture_default_str();
  cli->add_option("--accuracy-resolution", options->accuracyOptions.resolution,
                  "Accuracy study: grid vertices per side (2^k + 1 keeps the resolution study's points shared)")
      ->check(integerIn(3, 257))
      ->capture_default_str();
  cli->add_option("--accuracy-csv", options->accuracyOptions.csv, "Accuracy study: CSV output file")->capture_default_str();
  cli->add_flag("--contact", options->contact,
                "Instead of timing sizes, time the collision stage of a sheet draped on a sphere, with and without "
                "self-collision");
  cli->add_option("--contact-resolution", options->contactOptions.resolution, "Contact benchmark: grid vertices per side")
      ->check(integerIn(4, 1024))
      ->capture_default_str();
  cli->add_option("--contact-warmup", options->contactOptions.warmup,
                  "Contact benchmark: untimed steps before timing (90: the sheet has just draped and still slides; "
                  "600: ten seconds in, folded at its hem)")
      ->check(integerIn(0, 1'000'000))
      ->capture_default_str();
  cli->add_option("--contact-csv", options->contactOptions.csv, "Contact benchmark: CSV output file")->capture_default_str();
  cli->add_flag("--tearing", options->tearing,
                "Instead of timing sizes, time the tearing stage of a sheet pulled apart, for the thesis' and the dense "
                "candidate lines, with and without the bound that skips quiet vertices");
  cli->add_option("--tearing-resolution", options->tearingOptions.resolution, "Tearing benchmark: grid vertices per side")
      ->check(integerIn(4, 1024))
      ->capture_default_str();
  cli->add_option("--tearing-rows", options->tearingOptions.rows,
                  "Tearing benchmark: the configurations timed (thesis, thesis-unbounded, dense, dense-unbounded, "
                  "propagate, growth), comma-separated; default all")
      ->delimiter(',')
      ->check(CLI::IsMember({"thesis", "thesis-unbounded", "dense", "dense-unbounded", "propagate", "growth"}));
  cli->add_option("--tearing-csv", options->tearingOptions.csv, "Tearing benchmark: CSV output file")->capture_default_str();
  cli->add_option("--tearing-steps-csv", options->tearingOptions.stepsCsv,
                  "Tearing benchmark: also write every timed step's figures (tears, stage and whole ms, the stage's "
                  "parts, lines evaluated) to this CSV");
  cli->add_option("--tearing-initiation-every", options->tearingOptions.initiationEvery,
                  "Tearing benchmark: the growth row's tearing.initiation_every (new cracks looked for every this "
                  "many steps); 0: the scene's default")
      ->check(integerIn(0, 1000))
      ->capture_default_str();
  cli->add_flag("--solver-accuracy", options->solverAccuracy,
                "Instead of timing, run the scene for --solver-accuracy-duration seconds at each of --sizes with "
                "each of --solvers and report the largest vertex distance to the first solver's run and the CG "
                "residuals reached");
  cli->add_option("--solver-accuracy-duration", options->solverAccuracyOptions.duration,
                  "Solver accuracy: simulated seconds")
      ->check(numberIn(0.001, 60.0))
      ->capture_default_str();
  cli->add_option("--solver-accuracy-csv", options->solverAccuracyOptions.csv, "Solver accuracy: CSV output file")
      ->capture_default_str();
  return {cli, [options] {
            if (options->solverAccuracy) {
              SolverAccuracyOptions accuracy = options->solverAccuracyOptions;
              accuracy.sizes = options->sizes;
              accuracy.solvers = options->solvers;
              accuracy.scene = options->scene;
              accuracy.threads = options->threads;
              return runSolverAccuracyBench(accuracy);
            }
            if (options->tearing) {
              TearingBenchOptions tearing = options->tearingOptions;
              tearing.steps = options->steps;
              tearing.repeats = options->repeats;
              tearing.threads = options->threads;
              return runTearingBench(tearing);
            }
            if (options->contact) {
              ContactBenchOptions contact = options->contactOptions;
              contact.steps = options->steps;
              contact.repeats = options->repeats;
              contact.threads = options->threads;
              return runContactBench(contact);
            }
            if (!options->accuracy) return runBench(*options);
            AccuracyOptions accuracy = options->accuracyOptions;
            accuracy.scene = options->scene;
            accuracy.threads = options->threads;
            return runAccuracyStudy(accuracy);
          }};
}

}  // namespace weft::app
