#pragma once
// The tearing part of a scene: how candidates are searched and chosen, and the guards of the mesh
// surgery. Which cloths can tear is the material's business (Material::tearTable); a cloth
// without a tear table never tears. Read by scene/tearing_json.cpp.
namespace weft {


struct TearingSpec {
  bool denseLines = true;        // true: the whole fan (any direction); false: the thesis' three lines per
                                 // incident triangle (its edges and bisector: the grid's directions)
  int denseDirections = 180;     // dense: samples per half turn (per fan for a border vertex)
  bool skipByBound = true;       // skip vertices whose separation-strength bound cannot reach the table
  // Crack growth within a step (tear_stage.h). true: a crack that tears runs on from its new tips
  // within the step, each tip running at most crackSpeed * dt per step,
  // so a crack's growth per second does not depend on the element size, and tips read the material ahead of them
  // (crackTipLength); false: the thesis' one pass per step (maxTearsPerStep lines), the next
  // step's dynamics relaxing the stress. The default (with stressLength 0.065 and incubation 0.06)
  // is the resolution-independent mode: the same crack growth at 32², 48², 64² (docs/tearing.md).
  bool propagate = true;
  double crackSpeed = 50.0;      // m/s (material space): with propagate, the fastest a crack tip runs
  int relaxRings = 2;            // vertices within this many edges of a new crack end are relaxed
  int relaxSweeps = 0;           // Gauss-Seidel sweeps of that relaxation (0: none)
  // m (material space), with propagate: a crack tip tears by the traction averaged over this much material ahead
  // of it (tearing/crack_tip_stress.h), and no new crack starts this close to a tip (the stress
  // there is the tip's); 0: a tip reads its own fan, like any vertex.
  double crackTipLength = 0.05;
  // m (material space): the stress a tear reads is each triangle's averaged over this radius of
  // cloth around it (tearing/nonlocal_stress.h), so a crack tip's or a clamp's singular stress is
  // read the same at any resolution; 0: each triangle's own (the thesis).
  double stressLength = 0.065;
  // s: a new crack starts only at a vertex whose omega has stayed above 1 this long (every step of
  // it), so a spike shorter than this (the ligament of a crack that is crossing the sheet, a strip
  // whipping into its clamp after it tore free) starts nothing; a crack's own tips run on at once.
  // 0: a crack starts as soon as omega > 1 (the thesis). tear_stage.h says why.
  double incubation = 0.06;
  // Steps: new cracks are looked for every this many steps (the step's count since the start, a
  // multiple of it); in between, only a torn cloth's crack tips are searched, so cracks run on
  // every step (no vertex is asked whether it starts a crack, and the incubation clocks wait for
  // the next sample). 1: every step (tear_stage.h says what it costs).
  int initiationEvery = 1;
  bool branchFromLips = false;   // a vertex on a crack's flank may start a new crack (shattering)
  int maxTearsPerStep = 1;       // per cloth per step: new cracks (with propagate) or lines (without);
                                 // the thesis tears one
  double minSpacing = 0.1;       // m (material space): a tear that starts a crack keeps this far from the
                                 // step's other tears (a crack's own tips run on regardless)
  // The guards of the mesh surgery (tearing/tear_guards.h says why these values).
  double minEdgeLength = 0.001;  // m (material space): no tear creates a shorter edge
  double minAngleDeg = 15.0;     // no tear creates a triangle with a smaller angle
  double snapAngleDeg = 5.0;     // a line this close to an existing edge follows the edge

  friend bool operator==(const TearingSpec&, const TearingSpec&) = default;
};

}  // namespace weft
