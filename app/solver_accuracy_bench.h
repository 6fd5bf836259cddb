#pragma once
// `weft bench --solver-accuracy`: how far a linear solver's trajectory ends from the reference
// solver's (the first named, by default today's lagged-Cholesky CG) after the same simulated time,
// and the CG residuals it reached. The accuracy line of a faster solver: it may replace the
// default only if the sheet ends within 1 mm of where the default puts it.
#include <string>
#include <vector>

namespace weft::app {

struct SolverAccuracyOptions {
  std::vector<int> sizes{32, 64};
  std::vector<std::string> solvers{"cg", "amg", "cholmod"};  // the first is the reference
  double duration = 1.0;  // simulated seconds
  int threads = 1;
  std::string scene;      // default: presets/scenes/hanging-sheet.json
  std::string csv = "out/bench/solver-accuracy.csv";
};

int runSolverAccuracyBench(const SolverAccuracyOptions& options);

}  // namespace weft::app
