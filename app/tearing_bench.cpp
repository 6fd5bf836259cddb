// The tearing stage's time per step on the sheet-pulled-apart preset at a chosen resolution, once
// the pull has built up stress and tears run across the sheet: every timed step is one sample,
// and the median over all repeats is reported beside the whole step's, so the stage's share of a
// step can be read off.
#include "tearing_bench.h"
#include "bench_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>
#include <vector>

#include "command.h"
#include "machine_info.h"
#include "scene/scene_json.h"
#include "sim/world.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;


struct TearingBenchRow {
  std::string lines;
  bool bound = true;
  bool propagate = false;
  bool growthMode = false;  // the resolution-independent mode: averaged stress and incubation too
  int vertices = 0;  // at the end of the last repeat
  double medianTearingMs = 0.0;
  double medianStepMs = 0.0;
  // The stage's parts, each a median over the timed steps: averaged stress, line search, surgery,
  // stress after each tear (they need not add up to the stage's median).
  double medianStressMs = 0.0, medianSearchMs = 0.0, medianSurgeryMs = 0.0, medianRelaxMs = 0.0;
  double tearsPerRepeat = 0.0;
  double skippedShare = 0.0;  // of the vertices looked at
  double linesPerStep = 0.0;
  // The steps that tore (the same steps in every repeat) carry the surgery and the stress patched
  // after each tear on top of a quiet step's work, so a live demo feels them as its slowest frames:
  // their own medians, and the stage's share of the whole timed window (sum over sum).
  int tearingSteps = 0;  // per repeat
  double medianTearingStepTearingMs = 0.0, medianTearingStepMs = 0.0;
  double windowShare = 0.0;
};

// The mode whose crack growth does not depend on the resolution (docs/tearing.md, point 9).
constexpr double kGrowthStressLength = 0.065;  // m
constexpr double kGrowthIncubation = 0.06;     // s

// One CSV line per timed step (TearingBenchOptions::stepsCsv), appended to `steps`.
TearingBenchRow measure(const TearingBenchOptions& options, const std::string& name, const std::string& lines,
                        bool bound, bool propagate, bool growthMode, std::ostringstream& steps) {
  const fs::path scene = fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sheet-pulled-apart.json";
  const int n = options.resolution;
  std::vector<std::string> overrides{
      "cloths.0.mesh.grid.resolution=[" + std::to_string(n) + "," + std::to_string(n) + "]",
      "tearing.candidates=\"" + lines + "\"", std::string("tearing.skip_by_bound=") + (bound ? "true" : "false"),
      std::string("tearing.propagate=") + (propagate ? "true" : "false"),
      "solver.threads=" + std::to_string(options.threads)};
  // Every row states its mode in full, so the rows keep measuring the same modes whatever the
  // scene's defaults are (the growth mode is the default since issue 17).
  overrides.push_back("tearing.stress_length_m=" + std::to_string(growthMode ? kGrowthStressLength : 0.0));
  overrides.push_back("tearing.incubation_s=" + std::to_string(growthMode ? kGrowthIncubation : 0.0));
  if (growthMode && options.initiationEvery > 0) {
    overrides.push_back("tearing.initiation_every=" + std::to_string(options.initiationEvery));
  }
  TearingBenchRow row;
  row.lines = lines;
  row.bound = bound;
  row.propagate = propagate;
  row.growthMode = growthMode;
  std::vector<double> tearingSamples, stepSamples;
  std::vector<double> tearingStepTearingSamples, tearingStepSamples;
  const char* const parts[] = {"tear_stress", "tear_search", "tear_surgery", "tear_relax"};
  std::vector<double> partSamples[4];
  long long tears = 0, looked = 0, skipped = 0, evaluated = 0;
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    World world(loadScene(scene, overrides));
    // The incubation delays the first tear by that many steps: warm up that much longer, so the
    // same first tears are timed.
    const int delay = growthMode ? static_cast<int>(std::ceil(kGrowthIncubation / world.scene().solver.dt)) : 0;
    for (int s = 0; s < options.warmup + delay; ++s) world.step();
    const TearStats before = world.tearStats();
    for (int s = 0; s < options.steps; ++s) {
      const double tearingBefore = world.profile().totalWithPrefix("tear_");
      const double totalBefore = world.profile().total();
      double partBefore[4];
      for (int k = 0; k < 4; ++k) partBefore[k] = world.profile().totalWithPrefix(parts[k]);
      const long long tearsBefore = world.tearStats().tears;
      const long long linesBefore = world.tearStats().search.linesEvaluated;
      world.step();
      if (world.tearStats().tears > tearsBefore) {
        tearingStepTearingSamples.push_back(world.profile().totalWithPrefix("tear_") - tearingBefore);
        tearingStepSamples.push_back(world.profile().total() - totalBefore);
      }
      for (int k = 0; k < 4; ++k) partSamples[k].push_back(world.profile().totalWithPrefix(parts[k]) - partBefore[k]);
      tearingSamples.push_back(world.profile().totalWithPrefix("tear_") - tearingBefore);
      stepSamples.push_back(world.profile().total() - totalBefore);
      steps << name << "," << repeat << "," << s << "," << world.tearStats().tears - tearsBefore << ","
            << tearingSamples.back() << "," << stepSamples.back();
      for (int k = 0; k < 4; ++k) steps << "," << partSamples[k].back();
      steps << "," << world.tearStats().search.linesEvaluated - linesBefore << "\n";
    }
    const TearStats& after = world.tearStats();
    tears += after.tears - before.tears;
    looked += after.search.vertices - before.search.vertices;
    skipped += after.search.skipped - before.search.skipped;
    evaluated += after.search.linesEvaluated - before.search.linesEvaluated;
    row.vertices = world.cloth(0).vertexCount();
  }
  row.medianTearingMs = median(tearingSamples);
  row.tearingSteps = static_cast<int>(tearingStepSamples.size()) / std::max(1, options.repeats);
  row.medianTearingStepTearingMs = median(tearingStepTearingSamples);
  row.medianTearingStepMs = median(tearingStepSamples);
  double tearingSum = 0.0, stepSum = 0.0;
  for (double ms : tearingSamples) tearingSum += ms;
  for (double ms : stepSamples) stepSum += ms;
  row.windowShare = stepSum > 0.0 ? tearingSum / stepSum : 0.0;
  row.medianStepMs = median(stepSamples);
  row.medianStressMs = median(partSamples[0]);
  row.medianSearchMs = median(partSamples[1]);
  row.medianSurgeryMs = median(partSamples[2]);
  row.medianRelaxMs = median(partSamples[3]);
  row.tearsPerRepeat = static_cast<double>(tears) / options.repeats;
  row.skippedShare = looked > 0 ? static_cast<double>(skipped) / looked : 0.0;
  row.linesPerStep = static_cast<double>(evaluated) / (static_cast<double>(options.steps) * options.repeats);
  return row;
}

}  // namespace

int runTearingBench(const TearingBenchOptions& options) {
  std::vector<TearingBenchRow> rows;
  std::ostringstream steps;
  try {
    std::printf("%-7s %-6s %-9s %8s %16s %14s %8s %10s %12s %12s   %-30s   %-40s   %s\n", "lines", "bound", "propagate", "vertices",
                "tearing ms/step", "whole ms/step", "share", "tears", "skipped", "lines/step",
                "stress/search/surgery/relax ms", "tearing steps: n, stage/whole ms, share", "window share");
    struct Config {
      const char* name;
      const char* lines;
      bool bound, propagate, growthMode;
    };
    const Config configs[] = {{"thesis", "thesis", true, false, false},  {"thesis-unbounded", "thesis", false, false, false},
                              {"dense", "dense", true, false, false},    {"dense-unbounded", "dense", false, false, false},
                              {"propagate", "dense", true, true, false}, {"growth", "dense", true, true, true}};
    for (const Config& c : configs) {
      if (!options.rows.empty() && std::find(options.rows.begin(), options.rows.end(), c.name) == options.rows.end()) {
        continue;
      }
      {
        const TearingBenchRow r = measure(options, c.name, c.lines, c.bound, c.propagate, c.growthMode, steps);
        char parts[64], tearingSteps[64];
        std::snprintf(parts, sizeof parts, "%.2f/%.2f/%.2f/%.2f", r.medianStressMs, r.medianSearchMs, r.medianSurgeryMs,
                      r.medianRelaxMs);
        std::snprintf(tearingSteps, sizeof tearingSteps, "%d, %.2f/%.2f, %.1f%%", r.tearingSteps,
                      r.medianTearingStepTearingMs, r.medianTearingStepMs,
                      r.medianTearingStepMs > 0.0 ? 100.0 * r.medianTearingStepTearingMs / r.medianTearingStepMs : 0.0);
        std::printf("%-7s %-6s %-9s %8d %16.3f %14.3f %7.1f%% %10.1f %11.1f%% %12.0f   %-30s   %-40s   %.1f%%\n",
                    r.lines.c_str(), r.bound ? "on" : "off", r.growthMode ? "growth" : r.propagate ? "on" : "off",
                    r.vertices, r.medianTearingMs, r.medianStepMs, 100.0 * r.medianTearingMs / r.medianStepMs,
                    r.tearsPerRepeat, 100.0 * r.skippedShare, r.linesPerStep, parts, tearingSteps, 100.0 * r.windowShare);
        std::fflush(stdout);
        rows.push_back(r);
      }
    }
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }
  std::ostringstream csv;
  csv << benchCsvMachineLine("weft bench --tearing", options.threads,
                             "sheet-pulled-apart, " + std::to_string(options.resolution) + "^2, " +
                                 std::to_string(options.warmup) + " warm-up steps, " + std::to_string(options.steps) +
                                 " timed steps x " + std::to_string(options.repeats) + " repeats");
  csv << "lines,skip_by_bound,propagate,stress_length_m,incubation_s,vertices,median_tearing_ms_per_step,median_step_ms,tearing_share,tears_per_repeat,"
         "skipped_vertex_share,lines_evaluated_per_step,median_stress_ms,median_search_ms,median_surgery_ms,"
         "median_relax_ms,tearing_steps_per_repeat,median_tearing_step_tearing_ms,median_tearing_step_ms,window_tearing_share\n";
  for (const auto& r : rows) {
    csv << r.lines << "," << (r.bound ? "true" : "false") << "," << (r.propagate ? "true" : "false") << ","
        << (r.growthMode ? kGrowthStressLength : 0.0) << "," << (r.growthMode ? kGrowthIncubation : 0.0) << "," << r.vertices << "," << r.medianTearingMs << ","
        << r.medianStepMs << "," << r.medianTearingMs / r.medianStepMs << "," << r.tearsPerRepeat << ","
        << r.skippedShare << "," << r.linesPerStep << "," << r.medianStressMs << "," << r.medianSearchMs << ","
        << r.medianSurgeryMs << "," << r.medianRelaxMs << "," << r.tearingSteps << "," << r.medianTearingStepTearingMs
        << "," << r.medianTearingStepMs << "," << r.windowShare << "\n";
  }
  if (!writeBenchCsv(options.csv, csv.str())) return kExitFailure;
  if (!options.stepsCsv.empty()) {
    std::ostringstream stepsText;
    stepsText << benchCsvMachineLine("weft bench --tearing (per timed step)", options.threads,
                                     "sheet-pulled-apart, " + std::to_string(options.resolution) + "^2");
    stepsText << "row,repeat,step,tears,tearing_ms,step_ms,stress_ms,search_ms,surgery_ms,relax_ms,lines_evaluated\n"
              << steps.str();
    if (!writeBenchCsv(options.stepsCsv, stepsText.str())) return kExitFailure;
  }
  return kExitOk;
}

}  // namespace weft::app
