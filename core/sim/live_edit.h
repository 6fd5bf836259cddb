#pragma once
// Which edits of a scene the editor can apply to a running World (keeping its state: positions,
// velocities, tears) and which need the World rebuilt from the edited scene.
//
// Live (World's setters, world.h): per cloth its material (elasticity, bending, density, tear
// table), painted tear strength map, weft angle, appearance, name and material name; the forces; the solver (dt, substeps and
// threads as they are, any other solver setting with fresh integrators); the output (frames, fps,
// camera); the scene's name and description; an obstacle's sharp-tags source when it holds the
// tags the running world already has (needsReset with the world, below).
// Reset: everything else — the number of cloths, a cloth's mesh (grid, resolution, OBJ),
// placement and pins; the obstacles (a thrown ball makes the running scene differ from the
// editor's too), the ground, the contact settings, the tearing settings, the stage switches, and
// the scene file (relative paths resolve against it). A field added to Scene later counts as a
// reset until it is listed here as live.
#include "scene/scene.h"

namespace weft {

class World;

bool needsReset(const Scene& running, const Scene& edited);
// As above, with one more live edit that only the running world can tell: an obstacle's sharp-tags
// source (its mesh's "sharp_tags", a file or inline tags) that yields exactly the tags the
// obstacle has in `world` (the editor saved the tags it had applied into the file the scene now
// names). Applying it changes nothing in the world but scene()'s record. A source that cannot be
// read, or whose tags differ, still needs a reset. Reads the tags files: call it only when
// needsReset(running, edited) says yes.
bool needsReset(const Scene& running, const Scene& edited, const World& world);

// Applies every live difference between world.scene() and `edited` through World's setters.
// Precondition: !needsReset(world.scene(), edited, world) (throws std::invalid_argument otherwise).
void applyLiveEdits(World& world, const Scene& edited);

}  // namespace weft
