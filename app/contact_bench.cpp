// The collision stage's time per step, measured on the sheet-on-sphere preset at a chosen
// resolution once the sheet lies on the ball: every timed step is one sample, and the median over
// all repeats is reported with the pass counts, so a slow step can be traced to its pass.
#include "contact_bench.h"
#include "bench_stats.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "command.h"
#include "machine_info.h"
#include "scene/scene_json.h"
#include "sim/stage_profile.h"
#include "sim/world.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;


struct ContactBenchRow {
  bool self = false;
  bool reusePairs = true;
  int vertices = 0;
  double medianContactMs = 0.0;
  double maxContactMs = 0.0;
  double medianStepMs = 0.0;
  // The median of each contact stage alone (their sum need not be the median of the total).
  double medianStartPairsMs = 0.0, medianHeldMs = 0.0, medianCcdMs = 0.0;
  double proximityImpulsesPerStep = 0.0;
  double ccdIterationsPerStep = 0.0;
  double ccdCollisionsPerStep = 0.0;
  double impactZoneStepShare = 0.0;
  bool clean = true;  // no step left collisions unresolved
};

ContactBenchRow measure(const ContactBenchOptions& options, bool self, bool reusePairs) {
  const fs::path scene = fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sheet-on-sphere.json";
  const int n = options.resolution;
  const std::vector<std::string> overrides{
      "cloths.0.mesh.grid.resolution=[" + std::to_string(n) + "," + std::to_string(n) + "]",
      std::string("contact.self=") + (self ? "true" : "false"),
      std::string("contact.reuse_pairs=") + (reusePairs ? "true" : "false"),
      "solver.threads=" + std::to_string(options.threads)};
  ContactBenchRow row;
  row.self = self;
  row.reusePairs = reusePairs;
  std::vector<double> contactSamples, stepSamples, startPairsSamples, heldSamples, ccdSamples;
  ContactStats totals;
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    World world(loadScene(scene, overrides));
    for (int s = 0; s < options.warmup; ++s) world.step();
    const ContactStats before = world.contactStats();
    for (int s = 0; s < options.steps; ++s) {
      const StageProfile before = world.profile();
      world.step();
      const StageProfile& after = world.profile();
      auto took = [&](const char* prefix) { return after.totalWithPrefix(prefix) - before.totalWithPrefix(prefix); };
      contactSamples.push_back(took("contact_"));
      startPairsSamples.push_back(took("contact_start_pairs"));
      heldSamples.push_back(took("contact_held"));
      ccdSamples.push_back(took("contact_ccd"));
      stepSamples.push_back(after.total() - before.total());
    }
    const ContactStats& after = world.contactStats();
    totals.proximityImpulses += after.proximityImpulses - before.proximityImpulses;
    totals.ccdIterations += after.ccdIterations - before.ccdIterations;
    totals.ccdCollisions += after.ccdCollisions - before.ccdCollisions;
    totals.impactZoneSteps += after.impactZoneSteps - before.impactZoneSteps;
    totals.unresolvedSteps += after.unresolvedSteps - before.unresolvedSteps;
    row.vertices = world.cloth(0).vertexCount();
  }
  const double samples = static_cast<double>(options.steps) * options.repeats;
  row.medianContactMs = median(contactSamples);
  row.maxContactMs = *std::max_element(contactSamples.begin(), contactSamples.end());
  row.medianStepMs = median(stepSamples);
  row.medianStartPairsMs = median(startPairsSamples);
  row.medianHeldMs = median(heldSamples);
  row.medianCcdMs = median(ccdSamples);
  row.proximityImpulsesPerStep = totals.proximityImpulses / samples;
  row.ccdIterationsPerStep = totals.ccdIterations / samples;
  row.ccdCollisionsPerStep = totals.ccdCollisions / samples;
  row.impactZoneStepShare = totals.impactZoneSteps / samples;
  row.clean = totals.unresolvedSteps == 0;
  return row;
}

}  // namespace

int runContactBench(const ContactBenchOptions& options) {
  std::vector<ContactBenchRow> rows;
  try {
    std::printf("%-6s %-7s %8s %16s %14s %8s %8s %8s %14s %12s %10s %10s %10s\n", "self", "reuse", "vertices",
                "contact ms/step", "max ms/step", "start", "held", "ccd", "whole ms/step", "prox imp/st", "ccd it/st", "ccd col/st", "zones/st");
    // Each case with the pair cache and without it, one after the other: the ratio is what to
    // read on a machine whose speed drifts.
    for (const auto& [self, reusePairs] : {std::pair{false, true}, {false, false}, {true, true}, {true, false}}) {
      const ContactBenchRow r = measure(options, self, reusePairs);
      std::printf("%-6s %-7s %8d %16.3f %14.3f %8.3f %8.3f %8.3f %14.3f %12.1f %10.2f %10.2f %10.2f%s\n",
                  r.self ? "on" : "off", r.reusePairs ? "on" : "off", r.vertices, r.medianContactMs, r.maxContactMs,
                  r.medianStartPairsMs, r.medianHeldMs, r.medianCcdMs, r.medianStepMs, r.proximityImpulsesPerStep, r.ccdIterationsPerStep,
                  r.ccdCollisionsPerStep, r.impactZoneStepShare, r.clean ? "" : "  (unresolved steps!)");
      std::fflush(stdout);
      rows.push_back(r);
    }
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }
  std::ostringstream csv;
  csv << benchCsvMachineLine("weft bench --contact", options.threads,
                             "sheet-on-sphere, " + std::to_string(options.resolution) + "^2, " +
                                 std::to_string(options.warmup) + " warm-up steps, " + std::to_string(options.steps) +
                                 " timed steps x " + std::to_string(options.repeats) + " repeats");
  csv << "self_collision,reuse_pairs,vertices,median_contact_ms_per_step,max_contact_ms_per_step,"
         "median_start_pairs_ms,median_held_ms,median_ccd_ms,median_step_ms,"
         "proximity_impulses_per_step,ccd_iterations_per_step,ccd_collisions_per_step,impact_zone_steps_per_step,"
         "resolved\n";
  for (const auto& r : rows) {
    csv << (r.self ? "on" : "off") << "," << (r.reusePairs ? "on" : "off") << "," << r.vertices << "," << r.medianContactMs << "," << r.maxContactMs << ","
        << r.medianStartPairsMs << "," << r.medianHeldMs << "," << r.medianCcdMs << ","
        << r.medianStepMs << "," << r.proximityImpulsesPerStep << "," << r.ccdIterationsPerStep << ","
        << r.ccdCollisionsPerStep << "," << r.impactZoneStepShare << "," << (r.clean ? "true" : "false") << "\n";
  }
  return writeBenchCsv(options.csv, csv.str()) ? kExitOk : kExitFailure;
}

}  // namespace weft::app
