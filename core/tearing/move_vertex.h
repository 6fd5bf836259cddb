#pragma once
// Moving a vertex in material space: how a tear line that passes close to an existing vertex is
// followed exactly without a sliver (Pfaff, Narain, de Joya & O'Brien 2014, "Adaptive tearing and
// cracking of thin sheets", §5: a node near the fracture line is moved onto it; ARCSim's
// try_move_node). The vertex slides to the closest point of the line, its triangles keep their
// other corners, and the crack then runs along the vertex's edge, which now lies on the line.
//
// What is kept. The cloth's material domain (only an interior vertex, or a border vertex along a
// straight border, moves); the deformation: the vertex's world position is the old piecewise-linear
// deformation map evaluated at its new material point, so a rigid motion stays rigid and a uniform
// strain stays uniform; the total mass (the fan's outline does not move); the momentum exactly
// (the moved vertex takes the momentum its neighbours' lumped masses gave up or took, as
// split_edge.cpp does for an inserted vertex).
#include <optional>

#include "mesh/cloth_mesh.h"
#include "mesh/topology_change.h"
#include "tearing/tear_guards.h"
#include "tearing/vertex_fan.h"

namespace weft {

// A planned move of `vertex` to the material point `to`.
struct VertexMove {
  int vertex = kNone;
  Vec2 to = Vec2::Zero();
};

// Plans moving `vertex` onto the line through `linePoint` along unit `lineDirection` (material
// space): to the line's closest point for an interior vertex, along its border to where the line
// crosses it for a vertex on a straight border. Nothing when the vertex is pinned, on a seam (its
// triangles disagree on its rest position), a corner of the border, or when a moved triangle would
// break the guards (an angle below guards.minAngleDeg, or below the fan's smallest angle before
// the move where that was already smaller; an edge below guards.minEdgeLength; a flipped
// triangle).
std::optional<VertexMove> planVertexMove(const ClothMesh& mesh, int vertex, const Vec2& linePoint,
                                         const Vec2& lineDirection, const TearGuards& guards);

// Carries out a planned move; `areaDensity` (kg/m^2) is the cloth's, for the lumped masses.
// Records the fan's triangles, their edges and the vertices whose masses changed in `change`.
void moveVertex(ClothMesh& mesh, const VertexMove& move, double areaDensity, TopologyChange& change);

}  // namespace weft
