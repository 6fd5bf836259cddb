#include "scene/tearing_json.h"

#include <nlohmann/json.hpp>

#include "util/json_fields.h"

namespace weft {

TearingSpec parseTearing(const nlohmann::json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file,
                      {"candidates", "dense_directions", "skip_by_bound", "propagate", "crack_speed_m_per_s", "relax_rings",
                       "relax_sweeps", "crack_tip_length_m", "stress_length_m", "incubation_s", "initiation_every", "branch_from_lips", "tears_per_step", "min_spacing_m", "min_edge_length_m", "min_angle_deg",
                       "snap_angle_deg"});
  TearingSpec tearing;
  const std::string lines = r.string("candidates", "dense");
  if (lines != "thesis" && lines != "dense") {
    r.fail(r.pointer("candidates"), "must be \"thesis\" (three lines per incident triangle) or \"dense\" (the whole "
                                    "fan), got \"" + lines + "\"");
  }
  tearing.denseLines = lines == "dense";
  tearing.denseDirections = r.integer("dense_directions", tearing.denseDirections, 4);
  tearing.skipByBound = r.boolean("skip_by_bound", tearing.skipByBound);
  tearing.propagate = r.boolean("propagate", tearing.propagate);
  tearing.crackSpeed = r.number("crack_speed_m_per_s", tearing.crackSpeed, Bound::Positive,
                                "the fastest a crack tip runs in m/s");
  tearing.relaxRings = r.integer("relax_rings", tearing.relaxRings, 0);
  if (tearing.relaxRings > 8) r.fail(r.pointer("relax_rings"), "must be at most 8 (the relaxed patch grows as its square)");
  tearing.relaxSweeps = r.integer("relax_sweeps", tearing.relaxSweeps, 0);
  if (tearing.relaxSweeps > 100) r.fail(r.pointer("relax_sweeps"), "must be at most 100");
  tearing.crackTipLength = r.number("crack_tip_length_m", tearing.crackTipLength, Bound::NonNegative,
                                    "the length of material a crack tip reads ahead of it in m");
  if (tearing.crackTipLength > 1.0) r.fail(r.pointer("crack_tip_length_m"), "must be at most 1 m");
  tearing.stressLength = r.number("stress_length_m", tearing.stressLength, Bound::NonNegative,
                                  "the radius over which a tear averages the stress in m");
  if (tearing.stressLength > 1.0) r.fail(r.pointer("stress_length_m"), "must be at most 1 m");
  tearing.incubation = r.number("incubation_s", tearing.incubation, Bound::NonNegative,
                                "how long a stress must exceed the strength before a crack starts, in s");
  if (tearing.incubation > 10.0) r.fail(r.pointer("incubation_s"), "must be at most 10 s");
  tearing.initiationEvery = r.integer("initiation_every", tearing.initiationEvery, 1, 1000);
  tearing.branchFromLips = r.boolean("branch_from_lips", tearing.branchFromLips);
  tearing.maxTearsPerStep = r.integer("tears_per_step", tearing.maxTearsPerStep, 1);
  tearing.minSpacing = r.number("min_spacing_m", tearing.minSpacing, Bound::NonNegative,
                                "the spacing of several tears in one step in m");
  tearing.minEdgeLength = r.number("min_edge_length_m", tearing.minEdgeLength, Bound::Positive,
                                   "the shortest edge a tear may create in m");
  tearing.minAngleDeg = r.number("min_angle_deg", tearing.minAngleDeg, Bound::Positive,
                                 "the smallest triangle angle a tear may create in degrees");
  if (!(tearing.minAngleDeg < 30.0)) r.fail(r.pointer("min_angle_deg"), "must be below 30 degrees");
  tearing.snapAngleDeg = r.number("snap_angle_deg", tearing.snapAngleDeg, Bound::NonNegative,
                                  "the angle within which a line follows an existing edge in degrees");
  if (!(tearing.snapAngleDeg < 30.0)) r.fail(r.pointer("snap_angle_deg"), "must be below 30 degrees");
  return tearing;
}

}  // namespace weft
