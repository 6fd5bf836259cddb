#pragma once
// Patching a cloth's caches after a topology change (a tear), without rebuilding them.
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

}  // namespace weft
