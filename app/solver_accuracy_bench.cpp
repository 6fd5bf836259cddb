#include "solver_accuracy_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "command.h"
#include "default_scene.h"
#include "machine_info.h"
#include "scene/scene_json.h"
#include "sim/world.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> overridesFor(int size, const std::string& solver, int threads) {
  std::vector<std::string> overrides{
      "cloths.0.mesh.grid.resolution=[" + std::to_string(size) + "," + std::to_string(size) + "]",
      "solver.threads=" + std::to_string(threads)};
  // "cg" is the CG with the lagged Cholesky, named explicitly so that it does not follow the default.
  if (solver == "amg" || solver == "cg") {
    overrides.push_back("solver.linear_solver.type=cg");
    overrides.push_back(solver == "amg" ? "solver.linear_solver.preconditioner=amg"
                                        : "solver.linear_solver.preconditioner=lagged_cholesky");
  } else {
    overrides.push_back("solver.linear_solver.type=" + solver);
  }
  return overrides;
}

struct Run {
  std::vector<Vec3> positions;  // of every cloth, in order
  SolverStats stats;
  int steps = 0;
  double msPerStep = 0.0;
  bool finite = true;
};

Run simulate(const fs::path& sceneFile, int size, const std::string& solver, const SolverAccuracyOptions& options) {
  const Scene scene = loadScene(sceneFile, overridesFor(size, solver, options.threads));
  World world(scene);
  Run run;
  run.steps = static_cast<int>(std::lround(options.duration / (scene.solver.dt * scene.solver.substeps)));
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < run.steps; ++s) world.step();
  run.msPerStep = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() /
                  std::max(1, run.steps);
  for (int c = 0; c < world.clothCount(); ++c)
    run.positions.insert(run.positions.end(), world.cloth(c).x.begin(), world.cloth(c).x.end());
  run.stats = world.solverStats();
  run.finite = world.metrics().finite;
  return run;
}

}  // namespace

int runSolverAccuracyBench(const SolverAccuracyOptions& options) {
  const fs::path sceneFile = options.scene.empty() ? defaultScenePath() : fs::path(options.scene);
  std::ostringstream csv;
  csv << benchCsvMachineLine("weft bench --solver-accuracy", options.threads, sceneFile.string());
  csv << "size,solver,reference,duration_s,steps,max_distance_to_reference_m,linear_iterations_per_step,"
         "max_linear_residual,last_linear_residual,linear_solve_failures,ms_per_step,finite\n";
  std::printf("%6s %-8s %-9s %16s %10s %12s %12s %9s %10s\n", "size", "solver", "reference", "max dist (mm)",
              "lin it/st", "max resid", "last resid", "failures", "ms/step");
  bool allFinite = true;
  try {
    for (int size : options.sizes) {
      Run reference;
      for (size_t k = 0; k < options.solvers.size(); ++k) {
        const std::string& solver = options.solvers[k];
        Run run = simulate(sceneFile, size, solver, options);
        if (k == 0) reference = run;
        double distance = 0.0;
        for (size_t i = 0; i < run.positions.size() && i < reference.positions.size(); ++i)
          distance = std::max(distance, (run.positions[i] - reference.positions[i]).norm());
        const double iterations = double(run.stats.linearIterations) / std::max(1, run.steps);
        std::printf("%6d %-8s %-9s %16.6f %10.1f %12.3g %12.3g %9d %10.3f\n", size, solver.c_str(),
                    options.solvers[0].c_str(), 1000.0 * distance, iterations, run.stats.maxLinearResidual,
                    run.stats.lastLinearResidual, static_cast<int>(run.stats.linearSolveFailures), run.msPerStep);
        std::fflush(stdout);
        char line[512];
        std::snprintf(line, sizeof line, "%d,%s,%s,%.6g,%d,%.6e,%.2f,%.3e,%.3e,%d,%.4f,%s\n", size, solver.c_str(),
                      options.solvers[0].c_str(), options.duration, run.steps, distance, iterations,
                      run.stats.maxLinearResidual, run.stats.lastLinearResidual, static_cast<int>(run.stats.linearSolveFailures),
                      run.msPerStep, run.finite ? "true" : "false");
        csv << line;
        allFinite = allFinite && run.finite;
      }
    }
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }
  if (!writeBenchCsv(options.csv, csv.str())) return kExitFailure;
  return allFinite ? kExitOk : kExitNonFinite;
}

}  // namespace weft::app
