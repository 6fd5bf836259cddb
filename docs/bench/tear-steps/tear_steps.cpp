// Scratch (issue 20, the default's flip): the process CPU time and wall clock of every step of a
// scene's first 180 steps, which steps tore, and the means and medians over the tearing steps and
// over all. `tear_steps SCENE [override ...]`, e.g.
//   tear_steps presets/scenes/ball-into-sheet-table4.1-cloth1.json 'cloths.0.mesh.grid.resolution=[64,64]' \
//     solver.linear_solver.preconditioner=lagged_cholesky      # and =amg
// Built by hand from the top of the worktree after building the core library:
//   g++ -O3 -DNDEBUG -std=c++20 -fopenmp -DEIGEN_DONT_PARALLELIZE -Icore -isystem /usr/include/eigen3 \
//     -I/usr/include/suitesparse docs/bench/tear-steps/tear_steps.cpp build/core/libweft_core.a \
//     -lcholmod -ltinyobjloader -lgmpxx -lgmp $(pkg-config --libs stb) -o tear_steps
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>
#include "scene/scene_json.h"
#include "sim/world.h"
using namespace weft;
static double cpu() { timespec t; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t); return 1e3 * t.tv_sec + 1e-6 * t.tv_nsec; }
static double wall() { timespec t; clock_gettime(CLOCK_MONOTONIC, &t); return 1e3 * t.tv_sec + 1e-6 * t.tv_nsec; }
static double median(std::vector<double> v) { std::sort(v.begin(), v.end()); return v.empty() ? 0 : v[v.size() / 2]; }
static double mean(const std::vector<double>& v) { double s = 0; for (double x : v) s += x; return v.empty() ? 0 : s / v.size(); }
int main(int argc, char** argv) {
  std::vector<std::string> overrides(argv + 2, argv + argc);
  const Scene scene = loadScene(argv[1], overrides);
  World world(scene);
  const int steps = 180;
  std::vector<double> tc, tw, all, allw;
  std::string tearSteps;
  for (int s = 0; s < steps; ++s) {
    const size_t before = world.tearLog().size();
    const double c0 = cpu(), w0 = wall();
    world.step();
    const double c = cpu() - c0, w = wall() - w0;
    all.push_back(c); allw.push_back(w);
    const size_t tore = world.tearLog().size() - before;
    if (tore > 0) { tc.push_back(c); tw.push_back(w); tearSteps += " " + std::to_string(s) + ":" + std::to_string(tore) + "@" + std::to_string(int(c)); }
  }
  std::printf("tearing steps %zu, tears %zu, state %016llx\n steps(tears@cpu ms):%s\n", tc.size(), world.tearLog().size(), (unsigned long long)world.stateHash(), tearSteps.c_str());
  std::printf("tearing steps: cpu mean %.2f median %.2f ms; wall mean %.2f median %.2f\n", mean(tc), median(tc), mean(tw), median(tw));
  std::printf("all %d steps: cpu mean %.2f median %.2f ms; wall mean %.2f median %.2f\n", steps, mean(all), median(all), mean(allw), median(allw));
}
