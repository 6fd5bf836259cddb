#pragma once
// `weft bench --accuracy`: what each accuracy knob costs and how much error it leaves.
#include <string>

namespace weft::app {

struct AccuracyOptions {
  std::string scene;        // default: presets/scenes/hanging-sheet.json (its first cloth must be a grid)
  double duration = 0.5;    // simulated seconds compared (s)
  int resolution = 17;      // grid vertices per side for the time-step, Newton and CG studies
  int threads = 1;
  std::string csv = "out/bench/accuracy.csv";
};

int runAccuracyStudy(const AccuracyOptions& options);

}  // namespace weft::app
