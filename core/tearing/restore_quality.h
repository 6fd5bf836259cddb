#pragma once
// Restoring the tear guards around a tear's new edges by local re-triangulation, as adaptive
// tearing does (Pfaff, Narain, de Joya & O'Brien 2014, §5: split and flip edges near the crack tip
// to keep the elements well shaped): edge flips first (flip_edge.h), then, while a triangle of the
// region is still thinner than the angle guard, its longest edge split at its midpoint
// (split_edge.h, longest-edge bisection as in Rivara 1984) and the flips run again around the new
// vertex. The crack's line never moves: the edges it must keep (the cut and the crack's lips) are
// neither flipped nor split.
#include <vector>

#include "mesh/cloth_mesh.h"
#include "mesh/topology_change.h"
#include "tearing/tear_guards.h"

namespace weft {

// Flips and splits in and around `region` (triangle ids) until every triangle of the region, as it
// has grown, keeps the guards (angle and edge length); `keep` edges are neither flipped nor split.
// Returns false when it cannot within a few splits: the caller then puts the mesh back (the
// changes made so far are in `change` and the mesh).
bool restoreQuality(ClothMesh& mesh, std::vector<int> region, const std::vector<int>& keep, const TearGuards& guards,
                    double areaDensity, TopologyChange& change);

// Whether a triangle keeps the guards (its smallest rest angle and shortest rest edge).
bool keepsGuards(const Triangle& triangle, const TearGuards& guards);

}  // namespace weft
