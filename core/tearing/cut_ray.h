#pragma once
// Where one ray of a tear goes from its vertex: along an existing edge (a spoke of the fan), or
// across the triangle it enters, splitting that triangle's opposite side where the ray leaves it.
#include <optional>

#include "mesh/cloth_mesh.h"
#include "tearing/split_edge.h"
#include "tearing/tear_guards.h"
#include "tearing/vertex_fan.h"

namespace weft {

struct RayCut {
  int spoke = kNone;     // the fan edge the ray follows, or kNone when it crosses a triangle
  EdgeSplitPoint split;  // when crossing: the opposite side's split (split.triangle is the one entered)
  bool followsEdge() const { return spoke != kNone; }
};

// Plans the ray from fan.vertex along unit `direction` (material space). It follows the nearer
// spoke of the triangle it enters when within guards.snapAngleDeg of it, or when crossing would
// make a triangle that breaks a guard; otherwise it crosses. Nothing when the ray leaves the fan
// or would follow a border edge (there is nothing to open).
std::optional<RayCut> planRayCut(const ClothMesh& mesh, const VertexFan& fan, const Vec2& direction,
                                 const TearGuards& guards);

}  // namespace weft
