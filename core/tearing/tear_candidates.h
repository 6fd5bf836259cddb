#pragma once
// The candidate search (thesis §3.1-3.2): at every vertex, the fracture line with the highest
// ratio omega = zeta / R(alpha) of separation strength to the strength the tear table requires in
// its direction.
//
// Two ways to choose the lines tried at a vertex:
// - Thesis: three per incident triangle (Figure 2.8), along its two edges at the vertex and along
//   its corner's bisector (through the triangle's interior).
// - Dense: the whole fan, sampled at evenly spaced directions (as ARCSim does with 200) and the
//   best sample refined by a golden-section search between its neighbours; the line may then
//   leave the vertex through any triangle.
// A vertex whose bound on zeta (separation_strength.h) is below the tear table's weakest strength
// cannot reach omega = 1 in any direction and is skipped (optional; the result is the same).
#include <vector>

#include "mesh/cloth_mesh.h"
#include "tearing/separation_strength.h"
#include "tearing/strength_map.h"
#include "tearing/tear_record.h"
#include "tearing/tear_table.h"
#include "util/types.h"

namespace weft {

enum class CandidateLines { Thesis, Dense };

// No limit on how far a ray may turn from the middle of its open fan.
inline constexpr double kNoTurnLimit = 4.0;  // rad, beyond any half fan

struct TearSearchSettings {
  CandidateLines lines = CandidateLines::Dense;
  int denseDirections = 180;  // samples over a line's half turn (over the fan for a ray)
  bool skipByBound = true;    // skip vertices whose zeta bound is below the weakest strength
  bool branchFromLips = false;  // a vertex on a crack's flank may start a new crack (tear_search.h)
  // > 0: a crack tip reads the traction averaged over this much material ahead of it (m), not its
  // fan (crack_tip_stress.h); 0: its fan, like any other vertex.
  double tipLength = 0.0;
  int tipDirections = 72;     // rays sampled over a tip's open fan
  // The sharpest turn a crack takes at its tip (rad from straight on, the middle of its open fan);
  // rays further back run beside the crack's own lips.
  double maxKinkRad = kNoTurnLimit;
  // > 0: a vertex within this distance (m, material space) of a crack starts no new crack; it may
  // still tear as a crack's tip. Set by the tear stage (twice a tip's reach, tear_stage.cpp).
  double startClearance = 0.0;
  bool onlyTheBest = false;   // with skipByBound: return only the best vertex's line (one tear per
                              // step), skipping every vertex whose bound cannot beat the best so far
  // A closed fan reads its sectors' mean stress (weighted by their angles) as one stress at its
  // vertex (tear_search.h says when and why).
  bool closedFanAsOne = false;
};

struct TearCandidate {
  int vertex = kNone;
  Vec2 restPosition = Vec2::Zero();  // the vertex in material space (m)
  double angle = 0.0;       // direction of the line (or ray) in material space (rad)
  bool ray = false;         // the vertex is on a border or a tear: only the ray at `angle` opens
  bool crackTip = false;    // the vertex is where a crack ends (the tear continues it)
  double separation = 0.0;  // zeta (N/m)
  double required = 0.0;    // R(alpha) (N/m)
  double alphaDeg = 0.0;    // angle from the warp direction V, Eq. 3.1-3.3, in [0, 180)
  double ratio = 0.0;       // omega = zeta / R (Eq. 3.4)
};

// The best line of one vertex's fan (a full TearCandidate but for its vertex, position and ray
// flag), with the table's strengths scaled by `strengthScale` (a crack tip's propagation factor,
// times a painted strength map's mean along each line: strength_map.h).
TearCandidate bestLineAt(const StressFan& fan, const TearTable& table, double weftAngleRad,
                         const TearSearchSettings& settings, const StrengthScale& strengthScale, TearSearchCounts& counts,
                         double maxTurnRad = kNoTurnLimit);

// A bound on omega over every line (or ray) of the fan, sharper than the fan's bound over its
// weakest strength: the fan's lines in 5 degree pieces, each bounded from its middle line's sides
// (separationBoundNear) over the weakest strength within the piece's directions. Costs 36 lines.
double omegaBoundAt(const StressFan& fan, const TearTable& table, double weftAngleRad,
                    const StrengthScale& strengthScale, TearSearchCounts& counts);

// Whether some line (or ray) of the fan has omega > 1 as a crack start, answered as early as
// possible: the line at `hintAngle` first, then a branch and bound over pieces of the fan's lines
// that splits only the pieces whose bound exceeds 1. `angle` gets the line found. For the
// incubation of new cracks, which needs only whether a vertex is overloaded, not its best line.
bool anyLineAboveOneAt(const StressFan& fan, const TearTable& table, double weftAngleRad, double hintAngle,
                       double& angle, TearSearchCounts& counts, const StrengthScale& scale = 1.0);

// The other ways a vertex could open, when its best line is refused by the mesh: every line with
// omega > 1, best first (the thesis' lines; for dense lines, the local maxima of the sampling).
std::vector<TearCandidate> linesAboveOneAt(const StressFan& fan, const TearTable& table, double weftAngleRad,
                                           const TearSearchSettings& settings,
                                           const StrengthScale& strengthScale, double maxTurnRad = kNoTurnLimit);

// The best line of every vertex whose best omega exceeds 1, in vertex order (with onlyTheBest,
// just the one selectTears would choose first).
// `corners` is triangleCorners(mesh), kept up to date (separation_strength.h). With a strength
// map (prepared for this mesh's material bounds), each line's strength is scaled by the map's mean
// along it, and with a tear region (prepared likewise) blended with the region's table, as the tear
// stage's search does.
void findTearCandidates(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                        const std::vector<Mat2>& triangleStress, const TearTable& table,
                        double weftAngleRad, const TearSearchSettings& settings, std::vector<TearCandidate>& out,
                        TearSearchCounts& counts, const TearStrengthMap* strengthMap = nullptr,
                        const TearRegion* region = nullptr);

}  // namespace weft
