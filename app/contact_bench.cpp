// The collision stage's time per step, measured on the sheet-on-sphere preset at a chosen
// resolution once the sheet lies on the ball: every timed step is one sample, and the median over
// all repeats is reported with the pass counts, so a slow step can be traced to its pass.
#include "contact_bench.h"
#include "bench_stats.h"

#include <algorithm>
#include <array>
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

// One case's samples, gathered step by step.
struct CaseSamples {
  std::vector<double> contact, step, startPairs, held, ccd;
  ContactStats totals;
  int vertices = 0;
};

World makeWorld(const ContactBenchOptions& options, bool self, bool reusePairs) {
  const fs::path scene = fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "sheet-on-sphere.json";
  const int n = options.resolution;
  const std::vector<std::string> overrides{
      "cloths.0.mesh.grid.resolution=[" + std::to_string(n) + "," + std::to_string(n) + "]",
      std::string("contact.self=") + (self ? "true" : "false"),
      std::string("contact.reuse_pairs=") + (reusePairs ? "true" : "false"),
      "solver.threads=" + std::to_string(options.threads)};
  return World(loadScene(scene, overrides));
}

// Steps the world once, adding the step's stage times to `samples`.
void timedStep(World& world, CaseSamples& samples) {
  const StageProfile before = world.profile();
  world.step();
  const StageProfile& after = world.profile();
  auto took = [&](const char* prefix) { return after.totalWithPrefix(prefix) - before.totalWithPrefix(prefix); };
  samples.contact.push_back(took("contact_"));
  samples.startPairs.push_back(took("contact_start_pairs"));
  samples.held.push_back(took("contact_held"));
  samples.ccd.push_back(took("contact_ccd"));
  samples.step.push_back(after.total() - before.total());
}

void addCounts(const ContactStats& before, const ContactStats& after, ContactStats& totals) {
  totals.proximityImpulses += after.proximityImpulses - before.proximityImpulses;
  totals.ccdIterations += after.ccdIterations - before.ccdIterations;
  totals.ccdCollisions += after.ccdCollisions - before.ccdCollisions;
  totals.impactZoneSteps += after.impactZoneSteps - before.impactZoneSteps;
  totals.unresolvedSteps += after.unresolvedSteps - before.unresolvedSteps;
}

ContactBenchRow summarise(const ContactBenchOptions& options, bool self, bool reusePairs, const CaseSamples& s) {
  ContactBenchRow row;
  row.self = self;
  row.reusePairs = reusePairs;
  row.vertices = s.vertices;
  const double samples = static_cast<double>(options.steps) * options.repeats;
  row.medianContactMs = median(s.contact);
  row.maxContactMs = *std::max_element(s.contact.begin(), s.contact.end());
  row.medianStepMs = median(s.step);
  row.medianStartPairsMs = median(s.startPairs);
  row.medianHeldMs = median(s.held);
  row.medianCcdMs = median(s.ccd);
  row.proximityImpulsesPerStep = s.totals.proximityImpulses / samples;
  row.ccdIterationsPerStep = s.totals.ccdIterations / samples;
  row.ccdCollisionsPerStep = s.totals.ccdCollisions / samples;
  row.impactZoneStepShare = s.totals.impactZoneSteps / samples;
  row.clean = s.totals.unresolvedSteps == 0;
  return row;
}

// A case with the pair cache and without it, the two worlds stepped in turn, so that both rows
// see the same machine: its speed drifts by tens of percent within minutes, which made the ratio
// of two cases timed one after the other unreliable.
std::array<ContactBenchRow, 2> measure(const ContactBenchOptions& options, bool self) {
  std::array<CaseSamples, 2> samples;  // [0] with the cache, [1] without
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    std::array<World, 2> worlds{makeWorld(options, self, true), makeWorld(options, self, false)};
    for (int s = 0; s < options.warmup; ++s) {
      for (World& world : worlds) world.step();
    }
    const std::array<ContactStats, 2> before{worlds[0].contactStats(), worlds[1].contactStats()};
    for (int s = 0; s < options.steps; ++s) {
      for (int k = 0; k < 2; ++k) timedStep(worlds[k], samples[k]);
    }
    for (int k = 0; k < 2; ++k) {
      addCounts(before[k], worlds[k].contactStats(), samples[k].totals);
      samples[k].vertices = worlds[k].cloth(0).vertexCount();
    }
  }
  return {summarise(options, self, true, samples[0]), summarise(options, self, false, samples[1])};
}

}  // namespace

int runContactBench(const ContactBenchOptions& options) {
  std::vector<ContactBenchRow> rows;
  try {
    std::printf("%-6s %-7s %8s %16s %14s %8s %8s %8s %14s %12s %10s %10s %10s\n", "self", "reuse", "vertices",
                "contact ms/step", "max ms/step", "start", "held", "ccd", "whole ms/step", "prox imp/st", "ccd it/st", "ccd col/st", "zones/st");
    // Each case with the pair cache and without it, stepped in turn: the ratio is what to read on
    // a machine whose speed drifts.
    for (const bool self : {false, true}) {
      for (const ContactBenchRow& r : measure(options, self)) {
        std::printf("%-6s %-7s %8d %16.3f %14.3f %8.3f %8.3f %8.3f %14.3f %12.1f %10.2f %10.2f %10.2f%s\n",
                    r.self ? "on" : "off", r.reusePairs ? "on" : "off", r.vertices, r.medianContactMs, r.maxContactMs,
                    r.medianStartPairsMs, r.medianHeldMs, r.medianCcdMs, r.medianStepMs, r.proximityImpulsesPerStep,
                    r.ccdIterationsPerStep, r.ccdCollisionsPerStep, r.impactZoneStepShare,
                    r.clean ? "" : "  (unresolved steps!)");
        std::fflush(stdout);
        rows.push_back(r);
      }
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
