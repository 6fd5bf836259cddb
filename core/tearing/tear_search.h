#pragma once
// The candidate search of one cloth within one step, kept up to date across the step's tears.
//
// A step may tear many times (a crack runs on while its tip's omega stays above 1), and each tear
// changes the stress only around the crack. So the search is kept: every vertex's bound on omega
// (separation_strength.h) is computed once per step, then only the vertices around a tear are
// looked at again; the best line is found by branch and bound over the bounds (a vertex whose
// bound cannot beat the best line found is never evaluated), and an evaluated vertex's best line
// is kept until its stress changes. The result is the line findTearCandidates would choose, found
// at the cost of the vertices near the crack.
//
// Cracks grow at their tips: a crack tip (where a slit ends) needs only the table's propagation
// factor times its strength (tear_table.h); a vertex on a crack's flank (a lip) starts no new crack
// unless branching is asked for (TearSearchSettings::branchFromLips). Right after a crack opens,
// its lips still carry the stress the crack released until the cloth has moved: read as a fresh
// load, it would start cracks beside and across the first one at every step (measured: a uniaxial
// pull then shreds the sheet into strips one element wide).
//
// With averaged stress (TearSearchSettings::closedFanAsOne, the tear stage's default) a closed fan
// reads its sectors' mean stress S, weighted by their angles, as one stress at its vertex: a line's
// zeta is then |S n|, the traction across it (separation_strength.h), and no line of the fan has
// more than S's largest principal stress, a bound that is exact and needs no fan (the screen at the
// start of a step reads it from the rows). Why: each sector's stress is already an average over a
// disc several elements wide, so the sectors of one fan differ only by the shift between their
// discs' centres, a fraction of an element; reading them one by one cost the search most of its
// time (a loaded sheet's thousands of incubation questions a step, each a branch and bound over
// its sectors) for a difference of that order. Open fans (a border, a crack's tip or lips) still
// read sector by sector: a tip's sectors ahead carry the load its lips beside it do not, which
// steers the crack. Measured and compared with the sector reading in docs/tearing.md.
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "mesh/cloth_mesh.h"
#include "tearing/separation_strength.h"
#include "tearing/strength_map.h"
#include "tearing/tear_region.h"
#include "tearing/tear_candidates.h"
#include "tearing/tear_table.h"

namespace weft {

// Where a vertex stands on the cloth's cracks.
enum class CrackPlace { None, Tip, Lip };

class TearSearch {
 public:
  std::size_t heapBytes() const;  // util/heap_bytes.h (defined in sim/world_memory.cpp)
  // The cloth's painted strength (strength_map.h), or none; read by every later call, bounds
  // included. Set before start.
  void setStrengthMap(const TearStrengthMap* map) { map_ = map; }
  // The cloth's tear region (tear_region.h), or none; read as the map is.
  void setTearRegion(const TearRegion* region) { region_ = region; }
  // Every vertex looked at afresh (the start of a step). The triangles around each vertex are
  // kept from the last start when nothing has changed the mesh since: no refresh (no tear) and
  // the same vertex and triangle counts. A caller that searches another mesh with the same object
  // calls forgetMesh first.
  // `tipsOnly`: this step offers only the tips of cracks (no vertex starts a crack, none is asked
  // whether it could): the vertices off the cloth's borders, where no crack is, are not looked at.
  void start(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners, const std::vector<Mat2>& stress,
             const TearTable& table, double weftAngleRad, const TearSearchSettings& settings, TearSearchCounts& counts,
             bool tipsOnly = false);
  void forgetMesh() { rowsValid_ = false; }
  // The vertices of these triangles (changed by a tear, or with a new stress), and `vertices`
  // (those whose fans a tear opened without changing a triangle), looked at again; new vertices
  // are added. `corners` and `stress` must already be up to date for them.
  void refresh(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners, const std::vector<Mat2>& stress,
               const std::vector<int>& triangles, const std::vector<int>& vertices, TearSearchCounts& counts);
  // The best line with omega > 1 among the vertices not excluded (ties to the lower vertex id).
  std::optional<TearCandidate> best(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                                    const std::vector<Mat2>& stress, TearSearchCounts& counts);
  // Every line with omega > 1 at a vertex, best first (the fallbacks when the best is refused).
  std::vector<TearCandidate> linesAt(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                                     const std::vector<Mat2>& stress, int vertex);
  // The best line at a crack tip, whatever its omega (vertex kNone when the vertex is not a tip).
  TearCandidate tipLineAt(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                          const std::vector<Mat2>& stress, int vertex, TearSearchCounts& counts);
  // Whether a vertex of a crack (its tip or a lip) lies within `radius` (material space) of
  // `restPosition`.
  bool nearCrack(const ClothMesh& mesh, const Vec2& restPosition, double radius);
  // The vertex is not offered again this step (every line at it was refused, or its crack has
  // run as far as it may this step).
  void exclude(int vertex);
  // The vertex is not offered as a crack start this step (it is still incubating); it is offered
  // again if a crack reaches it, as that crack's tip.
  void hold(int vertex);
  // Incubation (tear_stage.h): from now on, a vertex not listed as mature (`mature[v]` != 0) is
  // not offered as a crack start; when the search reaches it, it only asks whether the vertex is
  // overloaded (far cheaper than its best line), holds it, and lists it in newlyOverloaded().
  // Without a call, every vertex may start a crack.
  void gateStarts(std::vector<char> mature);
  struct Overloaded {
    int vertex;
    double angle;  // a line with omega > 1 (rad, material space)
  };
  const std::vector<Overloaded>& newlyOverloaded() const { return newlyOverloaded_; }
  // Whether some line at the vertex, as a crack start (not a tip), has omega > 1. The line at
  // `hintAngle` (last step's best) is tried first: a vertex whose load barely moved is settled by
  // one line instead of its whole fan. `angle` gets a line with omega > 1 when there is one.
  bool overloadedAsStart(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                         const std::vector<Mat2>& stress, int vertex, double hintAngle, double& angle,
                         TearSearchCounts& counts);

 private:
  // Every vertex's bound at the start of a step, the interior ones screened first by their arcs.
  void screenAndLookAtAll(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners,
                          const std::vector<Mat2>& stress, TearSearchCounts& counts);
  void lookAt(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners, const std::vector<Mat2>& stress,
              int vertex, TearSearchCounts& counts);
  void boundAt(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners, const std::vector<Mat2>& stress,
               int vertex, TearSearchCounts& counts);
  CrackPlace fanOf(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners, const std::vector<Mat2>& stress,
             int vertex, StressFan& fan);
  double strengthScaleAt(const ClothMesh& mesh, int vertex, const StressFan& fan) const;
  // The strength scale of the vertex's lines (factor times the map's, strength_map.h), and the
  // smallest map multiplier any of its lines can read (1 without a map).
  StrengthScale scaleAt(const ClothMesh& mesh, int vertex, double factor, bool ray) const;
  double lowestMultiplierAt(const ClothMesh& mesh, int vertex) const;
  TearCandidate bestLineOf(const ClothMesh& mesh, const std::vector<Mat2>& stress, int vertex, CrackPlace place,
                           TearSearchCounts& counts);
  TearCandidate candidateAt(const ClothMesh& mesh, int vertex, const StressFan& fan, CrackPlace place,
                            TearCandidate line) const;

  const TearTable* table_ = nullptr;
  const TearStrengthMap* map_ = nullptr;
  const TearRegion* region_ = nullptr;
  double weftAngleRad_ = 0.0;
  TearSearchSettings settings_;
  std::vector<int> triangleAt_;          // per vertex: a triangle that holds it (kNone: none)
  // The triangles around each vertex as the step began, in compressed rows (one pass over the
  // triangles, not a fan walk per vertex); a vertex a tear touched is `walked_` instead.
  std::vector<int> rowStart_, around_;
  std::vector<double> aroundSpan_;       // per entry of around_: the vertex's corner angle in that triangle
  std::vector<char> walked_;
  // Per vertex, this step: the mean stress of its closed fan read as one (closedFanAsOne), summed
  // from the rows by the screen; valid where fromRows_ is set and the vertex is not walked_ (no
  // tear has changed its fan's stress since). The incubation questions read it without the fan.
  std::vector<Mat2> rowMean_;
  std::vector<char> fromRows_;
  // Per vertex on a border, while the rows are valid: its crack place as a walk of its fan found
  // it (kUnknownPlace until then). The place changes only with a tear, which invalidates the rows.
  std::vector<signed char> rowPlace_;
  static constexpr signed char kUnknownPlace = -1;
  bool readsMeanFromRows(int vertex) const { return fromRows_[vertex] && !walked_[vertex]; }
  // Whether the line at `angle` has omega > 1 on the vertex's mean from the rows (a start).
  bool meanLineAboveOne(const ClothMesh& mesh, int vertex, double angle, TearSearchCounts& counts) const;
  std::vector<double> bound_;            // per vertex: bound on its best omega (0: cannot tear)
  std::vector<TearCandidate> best_;      // per vertex: its best line, valid while its heap entry is current
  std::vector<char> excluded_;
  std::vector<char> held_;
  std::vector<char> mature_;             // per vertex, with gated starts: may start a crack now
  bool gated_ = false;
  bool tipsOnly_ = false;                // this step offers crack tips only (start's argument)
  std::vector<Overloaded> newlyOverloaded_;
  std::vector<char> sharpened_;          // per vertex: bound_ is already the piecewise bound
  std::vector<CrackPlace> place_;        // per vertex, as last looked at
  std::vector<int> crackVertices_;       // every vertex once seen on a crack (place_ says if it still is)
  // nearCrack's index of crackVertices_ by rest-space cell (squares of side crackCellSize_): a
  // query reads the 3 x 3 cells around it, not every crack vertex. The first crackIndexed_ of
  // crackVertices_ are in it; a tear (which may move a vertex's rest position) or a new radius
  // rebuilds it.
  std::unordered_map<std::int64_t, std::vector<int>> crackCells_;
  double crackCellSize_ = 0.0;
  std::size_t crackIndexed_ = 0;
  bool crackCellsStale_ = true;
  std::int64_t crackCellCoordinate(double c) const;  // along one axis
  static std::int64_t crackCellKey(std::int64_t cx, std::int64_t cy);
  // A vertex's omega can be at most this, from a bound on its separation strength: the strength
  // scaled by `scale` (the propagation factor at a tip) and the lowest multiplier near it.
  double omegaCeiling(double zetaBound, double scale, double lowestMultiplier) const;
  // Per vertex: bumped whenever it is looked at again, so heap entries from before are stale.
  std::vector<unsigned> version_;
  struct Entry {
    double key;  // bound (waiting) or omega (evaluated)
    int vertex;
    unsigned version;
  };
  std::vector<Entry> waiting_;    // max-heap by bound: not yet evaluated since last looked at
  // The start fills waiting_ unordered; the first search makes it a heap once the step's held
  // vertices are known (thousands of them on a loaded sheet, each a push and a pop otherwise).
  bool waitingIsHeap_ = false;
  void wait(const Entry& entry);
  void heapWaiting();
  std::vector<Entry> evaluatedHeap_;  // max-heap by omega: evaluated starts (and tips with a finite bound)
  std::vector<Entry> unboundedHeap_;  // max-heap by omega: evaluated vertices without a bound (tips
                                      // that read ahead; every vertex when the bound is off)
  bool offerable(const Entry& entry) const;
  StressFan fan_;                        // reused
  std::vector<double> largestStress_;    // per triangle, this step's screen (reused)
  std::vector<char> onBorder_;           // per vertex, at the start of the step
  // Whether rowStart_, around_, aroundSpan_, triangleAt_ and onBorder_ still describe the mesh
  // (for that many vertices and triangles): the mesh changes only through tears, which refresh.
  bool rowsValid_ = false;
  std::size_t rowsVertices_ = 0, rowsTriangles_ = 0;
  // The rows above, from the mesh.
  void buildRows(const ClothMesh& mesh, const std::vector<TriangleCorners>& corners);
};

}  // namespace weft
