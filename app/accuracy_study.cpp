// The accuracy study. Each knob is varied alone against a reference that differs only in that
// knob, so the error printed is the error that knob causes:
//   time step        vs BDF2 solved by Newton to 1e-9 at dt/16 of the finest step studied (second
//                    order, so its own error is far below any row's; backward Euler there
//                    would be ~5% of the 1/240 s rows)
//   Newton iterations vs Newton converged to 1e-9 at the same dt
//   CG tolerance      vs the direct solver (CHOLMOD) at the same dt
//   resolution        vs a finer grid at the same dt, compared at the material points both grids share
// Error = largest distance between corresponding vertices after `duration` seconds (mm), and its
// RMS; cost = wall milliseconds per 1/60 s of simulated time (one run, so noisy: compare ratios).
#include "accuracy_study.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

#include "command.h"
#include "machine_info.h"
#include "scene/scene_json.h"
#include "sim/world.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;

struct Run {
  std::unique_ptr<World> world;
  double msPerSixtieth = 0.0;  // wall ms per 1/60 s simulated
};

Run simulate(const fs::path& sceneFile, std::vector<std::string> overrides, double duration) {
  Scene scene = loadScene(sceneFile, overrides);
  Run run;
  run.world = std::make_unique<World>(scene);
  const long long steps = std::llround(duration / scene.solver.dt);
  const auto start = std::chrono::steady_clock::now();
  for (long long s = 0; s < steps; ++s) run.world->step();
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  run.msPerSixtieth = ms / (duration * 60.0);
  return run;
}

struct Deviation {
  double maxMm = 0.0;
  double rmsMm = 0.0;
};

// Compares grid vertices at shared material points: vertex (ix, iy) of an n x n grid sits where
// vertex (ix * stride, iy * stride) of an N x N grid does, stride = (N - 1) / (n - 1).
Deviation deviation(const World& coarse, int coarseSize, const World& fine, int fineSize) {
  const int stride = (fineSize - 1) / (coarseSize - 1);
  Deviation d;
  double sum = 0.0;
  int count = 0;
  for (int iy = 0; iy < coarseSize; ++iy)
    for (int ix = 0; ix < coarseSize; ++ix) {
      const Vec3& a = coarse.cloth(0).x[iy * coarseSize + ix];
      const Vec3& b = fine.cloth(0).x[(iy * stride) * fineSize + ix * stride];
      const double distance = (a - b).norm() * 1000.0;
      d.maxMm = std::max(d.maxMm, distance);
      sum += distance * distance;
      ++count;
    }
  d.rmsMm = std::sqrt(sum / count);
  return d;
}

std::string grid(int n) { return "cloths.0.mesh.grid.resolution=[" + std::to_string(n) + "," + std::to_string(n) + "]"; }
std::string dtOverride(double dt) {
  std::ostringstream s;
  s.precision(17);
  s << "solver.dt=" << dt;
  return s.str();
}

const std::vector<std::string> kConverged = {"solver.integrator=newton", "solver.newton.tolerance=1e-9",
                                             "solver.newton.max_iterations=100", "solver.linear_solver.type=cholmod"};

// The time step's reference: second order, so at dt/16 its own error is negligible.
const std::vector<std::string> kConvergedBdf2 = {"solver.integrator=bdf2_newton", "solver.newton.tolerance=1e-9",
                                                 "solver.newton.max_iterations=100", "solver.linear_solver.type=cholmod"};

std::vector<std::string> join(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

int runAccuracyStudy(const AccuracyOptions& options) {
  const fs::path sceneFile =
      options.scene.empty() ? fs::path(WEFT_SOURCE_DIR) / "presets/scenes/hanging-sheet.json" : fs::path(options.scene);
  const std::vector<std::string> base = {grid(options.resolution), "solver.substeps=1",
                                         "solver.threads=" + std::to_string(options.threads)};
  std::ostringstream csv;
  csv << "knob,value,integrator,dt,max_error_mm,rms_error_mm,ms_per_sixtieth_s\n";
  std::printf("%-18s %-10s %-26s %10s %12s %12s %14s\n", "knob", "value", "integrator", "dt", "max err mm",
              "rms err mm", "ms per 1/60 s");
  auto report = [&](const std::string& knob, const std::string& value, const std::string& integrator, double dt,
                    const Deviation& d, double ms) {
    std::printf("%-18s %-10s %-26s %10.5f %12.4f %12.4f %14.2f\n", knob.c_str(), value.c_str(), integrator.c_str(), dt,
                d.maxMm, d.rmsMm, ms);
    std::fflush(stdout);
    csv << knob << "," << value << "," << integrator << "," << dt << "," << d.maxMm << "," << d.rmsMm << "," << ms
        << "\n";
  };
  try {
    const int n = options.resolution;
    // Time step.
    const std::vector<double> steps = {1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240};
    const double referenceDt = steps.back() / 16;
    const Run reference =
        simulate(sceneFile, join(join(base, kConvergedBdf2), {dtOverride(referenceDt)}), options.duration);
    for (const char* integrator : {"linearized_backward_euler", "newton", "bdf2", "bdf2_newton"}) {
      for (double dt : steps) {
        const Run run = simulate(sceneFile,
                                 join(base, {std::string("solver.integrator=") + integrator, dtOverride(dt),
                                             "solver.linear_solver.type=cholmod"}),
                                 options.duration);
        report("time_step", "1/" + std::to_string(std::lround(1.0 / dt)), integrator, dt,
               deviation(*run.world, n, *reference.world, n), run.msPerSixtieth);
      }
    }
    // Newton iterations at 1/60 s, against converged Newton at the same step.
    const double dt = 1.0 / 60;
    const Run converged = simulate(sceneFile, join(join(base, kConverged), {dtOverride(dt)}), options.duration);
    for (int iterations : {1, 2, 3, 5, 10}) {
      const Run run = simulate(sceneFile,
                               join(base, {"solver.integrator=newton", dtOverride(dt), "solver.newton.tolerance=1e-12",
                                           "solver.newton.max_iterations=" + std::to_string(iterations),
                                           "solver.linear_solver.type=cholmod"}),
                               options.duration);
      report("newton_iterations", std::to_string(iterations), "newton", dt,
             deviation(*run.world, n, *converged.world, n), run.msPerSixtieth);
    }
    // CG tolerance at 1/60 s, against the direct solver.
    const Run direct = simulate(sceneFile, join(base, {dtOverride(dt), "solver.linear_solver.type=cholmod"}), options.duration);
    for (const char* tolerance : {"1e-1", "1e-2", "1e-3", "1e-4", "1e-6"}) {
      const Run run = simulate(sceneFile,
                               join(base, {dtOverride(dt), "solver.linear_solver.type=cg",
                                           std::string("solver.linear_solver.tolerance=") + tolerance,
                                           "solver.linear_solver.max_iterations=100000"}),
                               options.duration);
      report("cg_tolerance", tolerance, "linearized_backward_euler", dt, deviation(*run.world, n, *direct.world, n),
             run.msPerSixtieth);
    }
    // Resolution, at 1/120 s with the default integrator, against a 33 x 33 grid.
    const double fineDt = 1.0 / 120;
    const int finest = 33;
    auto atSize = [&](int size) {
      return join({grid(size), "solver.threads=" + std::to_string(options.threads)},
                  {dtOverride(fineDt), "solver.linear_solver.type=cholmod"});
    };
    const Run fine = simulate(sceneFile, atSize(finest), options.duration);
    for (int size : {5, 9, 17}) {
      const Run run = simulate(sceneFile, atSize(size), options.duration);
      report("resolution", std::to_string(size) + "x" + std::to_string(size), "linearized_backward_euler", fineDt,
             deviation(*run.world, size, *fine.world, finest), run.msPerSixtieth);
    }
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }
  return writeBenchCsv(options.csv, csv.str()) ? kExitOk : kExitFailure;
}

}  // namespace weft::app
