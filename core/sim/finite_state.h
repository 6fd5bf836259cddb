#pragma once
// Whether a world's state is still usable: every cloth position and velocity finite. A non-finite
// state only gets worse, so runs and the live viewer check this after each frame and stop.
namespace weft {

class World;

// Checked on the state itself rather than through World::metrics(), which also evaluates the
// energies and would cost a force evaluation per frame.
bool stateIsFinite(const World& world);

}  // namespace weft
