#pragma once
// The mesh surgery of a tear: open the cloth along a line through one vertex.
//
// Design. The physics (stress, separation strength) picks a vertex and a direction in material
// space; this file only changes the mesh, locally and in a fixed order, so that the same call on
// the same mesh gives the same ids:
//   1. Each ray in turn (cut_ray.h): an interior vertex (closed fan) is opened along +direction and
//      -direction, a border vertex (on the border or an earlier tear) along +direction only, which
//      must point into its fan. A ray follows an existing edge that lies on the line, crosses the
//      triangle it enters (splitting that triangle's opposite side where the ray leaves it) when
//      the pieces pass the guards, or else moves the nearer end of that side onto the line and
//      follows its edge (move_vertex.h), or else crosses and re-triangulates around the crossing
//      by flips and splits (restore_quality.h), so the crack stays on the line the physics chose. Each
//      ray is planned on the mesh as the rays before it left it and carried out at once.
//      A ray from a pinned vertex whose far end is pinned too is refused: the clamp holds both.
//   2. Open the cut edges and separate every vertex left with two fans (separate_vertex.h): the
//      torn vertex itself and any far end already on a border. So a tear that reaches the border
//      or another tear opens the cloth.
// Lumped masses are patched for the vertices whose triangles changed; mass and momentum are kept
// to round-off (split_edge.cpp explains the velocity of an inserted vertex; a separated vertex's
// copies share its mass and keep its velocity). The returned TopologyChange says what to patch in
// the caches (sim/cloth_topology.h).
//
// Cost: the size of the vertex's fan and its neighbours, plus one scan of the triangles to find a
// first triangle at the vertex (the mesh keeps no vertex-to-triangle map).
#include "mesh/cloth_mesh.h"
#include "mesh/topology_change.h"
#include "tearing/tear_guards.h"

namespace weft {

// Tears the cloth through `vertex` along the line with direction `direction` (material space, the
// frame of Triangle::rest; need not be unit). `areaDensity` (kg/m^2) is the cloth's, for the
// lumped masses. Returns false, with the mesh untouched and `outChange` empty, when no valid tear
// exists: every ray points out of the fan, would run along a border edge or cannot keep the guards,
// would open a line whose two ends are pinned (a pinned vertex to a pinned vertex, or to a point
// inserted between two pinned vertices: held in a clamp's jaws, it cannot open), or the direction
// is zero or not finite (an interior vertex needs both of its rays).
bool tearThroughVertex(ClothMesh& mesh, int vertex, const Vec2& direction, const TearGuards& guards,
                       double areaDensity, TopologyChange& outChange);

}  // namespace weft
