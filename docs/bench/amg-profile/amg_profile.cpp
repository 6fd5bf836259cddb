// Scratch (issue 20, round 3): the multigrid preconditioner's parts timed on the real 64² (and 32²)
// hanging-sheet system after 20 steps of its fall (the tests' movingSheetSystem): the CG's product
// (Eigen's and by blocks), the numeric refresh, one V-cycle in double and in float, and a PCG
// solve from zero (tolerance from $TOL, default 1e-6); medians of repeats in thread CPU time (a
// descheduled thread's wait does not count on the shared machine). `amg_profile 64 product`,
// `... cycle` and `... refresh` loop one part alone (for perf). The system comes from the tests'
// builder, tests/support/moving_sheet_system.{h,cpp}, compiled alongside. Built by hand from the
// top of the worktree after building the core library:
//   g++ -O3 -DNDEBUG -std=c++20 -fopenmp -DEIGEN_DONT_PARALLELIZE -DWEFT_SOURCE_DIR=\"$PWD\" -Icore -Itests \
//     -isystem /usr/include/eigen3 -I/usr/include/suitesparse docs/bench/amg-profile/amg_profile.cpp \
//     tests/support/moving_sheet_system.cpp \
//     build/core/libweft_core.a -lcholmod -ltinyobjloader -lgmpxx -lgmp $(pkg-config --libs stb) -o amg_profile
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "forces/elastic_forces.h"
#include "integrate/amg_preconditioner.h"
#include "integrate/lagged_cholesky_preconditioner.h"
#include "integrate/preconditioned_cg.h"
#include "scene/scene_json.h"
#include "sim/cloth.h"
#include "sim/world.h"
#include "support/moving_sheet_system.h"

using namespace weft;

// Thread CPU time: on the shared machine a descheduled thread's wait does not count.
static double now() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * t.tv_sec + 1e-6 * t.tv_nsec;
}

using test::ClothSystem;
using test::movingSheetSystem;

template <class F>
static double median(int repeats, F&& f) {
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const double t0 = now();
    f();
    t.push_back(now() - t0);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

int main(int argc, char** argv) {
  std::vector<int> sizes{32, 64};
  if (argc > 1) sizes = {std::stoi(argv[1])};
  if (argc > 2 && std::string(argv[2]) == "product") {  // `amg_profile 64 product`: only the CG's products, for perf stat
    const ClothSystem system = movingSheetSystem(sizes[0], 20);
    PreconditionedConjugateGradient cg(1e-6, 10);
    Eigen::VectorXd y;
    const double t0 = now();
    for (int k = 0; k < 3000; ++k) cg.multiply(system.A, system.b, y);
    std::printf("%.4f ms per product\n", (now() - t0) / 3000);
    return 0;
  }
  if (argc > 2 && std::string(argv[2]) == "cycle") {  // `amg_profile 64 cycle`: only V-cycles
    const ClothSystem system = movingSheetSystem(sizes[0], 20);
    AmgPreconditioner amg;
    amg.prepare(system.A);
    Eigen::VectorXd z;
    const double t0 = now();
    for (int k = 0; k < 3000; ++k) amg.apply(system.b, z);
    std::printf("%.4f ms per cycle\n", (now() - t0) / 3000);
    return 0;
  }
  if (argc > 2) {  // `amg_profile 64 refresh`: only numeric refreshes, for perf
    const ClothSystem system = movingSheetSystem(sizes[0], 20);
    AmgPreconditioner amg(AmgPreconditioner::Settings{});
    amg.prepare(system.A);
    const double t0 = now();
    for (int k = 0; k < 300; ++k) amg.prepare(system.A);
    std::printf("%.4f ms per refresh\n", (now() - t0) / 300);
    return 0;
  }
  for (int size : sizes) {
    const ClothSystem system = movingSheetSystem(size, 20);
    Eigen::VectorXd y;
    const double product = median(51, [&] { y.noalias() = system.A.matrix().transpose() * system.b; });
    PreconditionedConjugateGradient blockCg(1e-6, 10);
    const double blockProduct = median(51, [&] { blockCg.multiply(system.A, system.b, y); });
    std::printf("%d²: product Eigen %.4f ms, by blocks %.4f ms\n", size, product, blockProduct);
    for (int variant = 0; variant < 2; ++variant) {
      AmgPreconditioner::Settings settings = AmgPreconditioner::Settings{};
      settings.singlePrecisionCycle = variant == 1;
      AmgPreconditioner amg(settings);
      amg.prepare(system.A);
      const double build = median(3, [&] {
        AmgPreconditioner fresh(settings);
        fresh.prepare(system.A);
      });
      const double refresh = median(21, [&] { amg.prepare(system.A); });
      Eigen::VectorXd z, r = system.b;
      const double cycle = median(51, [&] { amg.apply(r, z); });
      int iterations = 0;
      double residual = 0;
      const double solve = median(7, [&] {
        PreconditionedConjugateGradient cg(std::getenv("TOL") ? std::atof(std::getenv("TOL")) : 1e-6, 2000);
        Eigen::VectorXd x = Eigen::VectorXd::Zero(system.b.size());
        const LinearSolveResult result = cg.solve(system.A, system.b, 0.0, amg, x);
        iterations = result.iterations;
        residual = (system.b - system.A.matrix() * x).norm() / system.b.norm();
      });
      const AmgHierarchy& h = amg.hierarchy();
      if (variant == 0) {
        std::printf("  levels %d (", h.levelCount());
        for (int l = 0; l < h.levelCount(); ++l) std::printf("%s%d", l ? " " : "", h.level(l).A.blockRows);
        std::printf(") complexity %.2f, finest blocks %d, P blocks %d\n", h.operatorComplexity(), h.level(0).A.blockCount(),
                    h.levelCount() > 1 ? h.level(0).P.blockCount() : 0);
      }
      std::printf("  %s cycle: build %.3f ms, refresh %.3f ms, cycle %.4f ms; solve from 0 to 1e-6 (with refresh) %.3f ms, "
                  "%d iterations (true residual %.2e), %.4f ms/iteration\n",
                  variant ? "float " : "double", build, refresh, cycle, solve, iterations, residual,
                  (solve - refresh) / std::max(iterations, 1));
    }
  }
}
