#pragma once
// One simulated cloth: its mesh, material, weft angle, precomputed elements and pins.
#include <optional>
#include <string>
#include <vector>

#include "forces/bending.h"
#include "forces/membrane.h"
#include "material/material.h"
#include "mesh/cloth_mesh.h"
#include "mesh/topology_change.h"
#include "scene/scene.h"
#include "sim/stage_profile.h"
#include "tearing/strength_map.h"
#include "tearing/tear_region.h"

namespace weft {

// Pinned vertices that move together along a keyframed script.
struct PinTrack {
  std::vector<int> vertices;         // sorted, unique
  std::vector<Vec3> start;           // positions at time 0
  std::vector<PinKeyframe> script;   // empty: held in place
};

struct Cloth {
  std::string name;
  ClothMesh mesh;
  Material material;
  double weftAngleRad = 0.0;
  // A painted multiplier on the tear table's strength over material space (strength_map.h).
  std::optional<TearStrengthMap> tearStrengthMap;
  // A second tear table over part of the cloth (tear_region.h).
  std::optional<TearRegion> tearRegion;
  std::vector<MembraneElement> membranes;  // one per triangle, same ids
  std::vector<BendingHinge> hinges;        // one per interior edge with stiffness
  std::vector<PinTrack> pins;
};

// Builds the mesh (grid or OBJ), places it, assigns masses, precomputes elements and resolves
// pins. Throws InputError (naming `sceneFile` and the cloth's JSON path) for a degenerate mesh or
// a pin selection that selects nothing.
Cloth buildCloth(const ClothSpec& spec, const std::string& sceneFile, int clothIndex);

// The rotation of a placement: about world x, then y, then z.
Mat3 placementRotation(const Placement& placement);

// Recomputes the membrane elements and bending hinges from the mesh's rest data (after a
// topology change or a weft-angle edit).
void rebuildElements(Cloth& cloth);

// Piecewise-linear offset of a pin script at time t (held before the first and after the last key).
Vec3 pinOffset(const std::vector<PinKeyframe>& script, double t);

// Every pinned vertex with its target position at time t.
// Timed as the "pins" stage when the cloth has pins.
void pinTargets(const Cloth& cloth, double t, std::vector<int>& outVertices, std::vector<Vec3>& outPositions,
                StageProfile& profile);

// Vertex pairs coupled by an element: the system matrix pattern. The two vertices of a triangle
// edge are coupled by the membrane; the wing vertices of a bending hinge only by bending, which is
// orders of magnitude weaker (a preconditioner may leave those couplings out).
struct CoupledVertexPairs {
  std::vector<std::pair<int, int>> edges;
  std::vector<std::pair<int, int>> hingeWings;
};
CoupledVertexPairs coupledVertexPairs(const Cloth& cloth);
// The pairs a topology change (already applied to the cloth and its hinges, cloth_topology.h) may
// have coupled anew: the ends of its changed edges and the wings of their hinges. Pairs it
// uncoupled are not listed (nothing is ever removed from a pattern).
CoupledVertexPairs coupledVertexPairs(const Cloth& cloth, const TopologyChange& change);

}  // namespace weft
