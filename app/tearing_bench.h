#pragma once
// `weft bench --tearing`: the tearing stage's cost in a sheet pulled apart until it tears, with the
// thesis' candidate lines and the dense ones, each with and without the bound that skips quiet
// vertices, against the whole step.
#include <string>
#include <vector>

namespace weft::app {

struct TearingBenchOptions {
  int resolution = 64;      // grid vertices per side
  int warmup = 335;         // untimed steps: the pull builds up stress until just before the
                            // first tear (1.40 s at 1/240 s at 64^2)
  int steps = 30;           // timed steps per repeat
  int repeats = 3;          // the median over every timed step of every repeat is reported
  int threads = 1;
  // The configurations timed, by name (thesis, thesis-unbounded, dense, dense-unbounded, propagate,
  // growth); empty: all of them.
  std::vector<std::string> rows;
  std::string csv = "out/bench/tearing.csv";
  // Where each timed step's own figures go (row, repeat, step, tears, stage and whole ms, the four
  // parts, lines evaluated); empty: not written. The medians hide where the stage's time goes: the
  // steps of an overload wave and those that tear cost several times a quiet step.
  std::string stepsCsv;
  // The growth row's tearing.initiation_every (new cracks looked for every this many steps); 0:
  // the scene's default.
  int initiationEvery = 0;
};

int runTearingBench(const TearingBenchOptions& options);

}  // namespace weft::app
