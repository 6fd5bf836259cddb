// World::clone: a deep copy of the world's state, for the editor's timeline (issue 21, item 7),
// which resumes from a cached frame after an edit instead of re-simulating from t = 0.
//
// What is copied and why it is safe to copy:
//  - cloths, obstacles, time, grab, dragged tools, profile, statistics: plain values;
//  - the contact stage: its held contacts and kept pairs change what the next step does. Its
//    bodies point into the world (cloth positions, obstacles) and are re-pointed at the start of
//    every prepare() and resolve(), before any use; its pair caches identify a mesh by address
//    and revision, so in the copy they miss once and search afresh, which gives the same pairs in
//    the same order (pair_cache.h);
//  - the tear stage: its log, statistics and crack-tip overshoots; the search's table pointer is
//    set at the start of every search;
//  - the integrators: Integrator::copyWithoutCaches (integrator.h);
//  - not the membrane evaluated ahead (membrane_ahead.h: ~550 bytes a triangle, which the
//    timeline would keep per frame): the copy's first step evaluates it, which gives the same
//    numbers.
#include "sim/world.h"
#include "sim/world_impl.h"

namespace weft {

World::Impl::Impl(const Impl& other)
    : scene(other.scene),
      cloths(other.cloths),
      obstacles(other.obstacles),
      contact(std::make_unique<ContactStage>(*other.contact)),
      tearing(std::make_unique<TearStage>(*other.tearing)),
      startPositions(other.startPositions),
      time(other.time),
      steps(other.steps),
      timeOrigin(other.timeOrigin),
      stepsAtOrigin(other.stepsAtOrigin),
      grab(other.grab),
      kinematicTargets(other.kinematicTargets),
      kinematicFrom(other.kinematicFrom),
      profile(other.profile),
      stats(other.stats) {
  integrators.reserve(other.integrators.size());
  for (const std::unique_ptr<Integrator>& integrator : other.integrators) {
    integrators.push_back(integrator->copyWithoutCaches(scene.solver));
  }
}

World::World(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

std::unique_ptr<World> World::clone() const {
  return std::unique_ptr<World>(new World(std::make_unique<Impl>(*impl_)));
}

}  // namespace weft
