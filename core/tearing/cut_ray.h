#pragma once
// Where one ray of a tear goes from its vertex, so that the crack runs along the line the physics
// chose, whatever the mesh (Pfaff et al. 2014, §5):
//   - along an existing edge (a spoke of the fan) that already lies on the line;
//   - across the triangle it enters, splitting that triangle's opposite side where the ray leaves
//     it, when the pieces pass the guards;
//   - otherwise along a spoke whose far end is first moved onto the line (move_vertex.h): the end
//     nearer the crossing first, then the other;
//   - otherwise across, when only the triangle beyond the crossed side would be thin: edge flips
//     then restore the guards there (flip_edge.h), or, where flips alone cannot, flips and splits
//     over the vertex's fan and the split point's (restore_quality.h);
//   - otherwise across all the same, with that re-triangulation from the start: a piece at the
//     vertex is thin when the ray passes a spoke by less than the angle guard, and flipping that
//     spoke (its quad's other diagonal) widens it; refused only when the re-triangulation cannot
//     restore the guards (then the stage tries the vertex's next line);
//   - failing all of these, along the nearer spoke if it is within the snap angle (the line then
//     bends by at most that much, as ARCSim snaps); else the ray is refused.
#include <optional>
#include <vector>

#include "mesh/cloth_mesh.h"
#include "tearing/move_vertex.h"
#include "tearing/split_edge.h"
#include "tearing/tear_guards.h"
#include "tearing/vertex_fan.h"

namespace weft {

struct RayCut {
  int spoke = kNone;     // the fan edge the ray follows, or kNone when it crosses a triangle
  EdgeSplitPoint split;  // when crossing: the opposite side's split (split.triangle is the one entered)
  std::optional<VertexMove> move;  // with a spoke: its far end moved onto the line first
  bool repair = false;   // when crossing: the split leaves a thin triangle beyond the crossed side,
                         // which local re-triangulation must repair (tear_mesh.cpp; refused if it cannot)
  bool repairAtVertex = false;  // with repair: a piece at the vertex may be thin too (the ray passes
                                // within the angle guard of a spoke): the repair spans the vertex's fan
  bool followsEdge() const { return spoke != kNone; }
};

// Plans the ray from fan.vertex along unit `direction` (material space). `keep` lists vertices
// that must not move (the ends of cuts already made by this tear). Nothing when the ray leaves the
// fan, would follow a border edge, or no way above passes the guards.
std::optional<RayCut> planRayCut(const ClothMesh& mesh, const VertexFan& fan, const Vec2& direction,
                                 const TearGuards& guards, const std::vector<int>& keep = {});

}  // namespace weft
