#pragma once
// Patching a cloth's caches after a topology change (a tear), without rebuilding them.
#include <vector>

#include "mesh/topology_change.h"
#include "sim/cloth.h"

namespace weft {

// Brings the cloth's element caches and pins up to date with a change already made to
// cloth.mesh:
//   - membranes: remade for the changed and new triangles only;
//   - hinges: those on changed edges are dropped, and every changed edge that is interior gets a
//     fresh one (appended), so that the set equals what rebuildElements would build;
//   - pins: a point inserted between two pinned vertices joins the first one's PinTracks, at the
//     start interpolated between theirs; a copy of a pinned vertex joins every PinTrack of its
//     original, at the same start.
// The integrator's matrix pattern and the contact stage's collision structures are not touched
// here: the world passes the change to Integrator::topologyChanged and ContactStage::clothTopologyChanged.
void applyTopologyChange(Cloth& cloth, const TopologyChange& change);

// For a series of changes made one after another (a step's tears): applyTopologyChange but the
// hinges after each, then the hinges once, from the changed edges of each change in the order they
// were made. The result is the same, hinge for hinge and in the same order, as applyTopologyChange
// after each change: a hinge depends only on its edge's triangles and rest shapes, which a change
// that touches them lists. Why: the hinges' pass runs over every hinge of the cloth, and a running
// crack tears a dozen times a step.
void applyTopologyChangeButHinges(Cloth& cloth, const TopologyChange& change);
void refreshHingesAfter(Cloth& cloth, const std::vector<std::vector<int>>& changedEdgesInOrder);

}  // namespace weft
