#pragma once
// World's private state, shared by the files that implement World: world.cpp (construction, the
// step, queries), world_live_edits.cpp and world_interaction.cpp. Not part of the public API.
#include <optional>

#include "contact/obstacle.h"
#include "forces/wind.h"
#include "integrate/integrator.h"
#include "sim/cloth.h"
#include "sim/world.h"
#include "tearing/tear_stage.h"

namespace weft {

struct World::Impl {
  Impl() = default;
  // For World::clone (world_clone.cpp): every member below, deep. A member added here must be
  // added there too (WorldClone tests step a clone beside its original and compare).
  Impl(const Impl& other);
  Impl& operator=(const Impl&) = delete;

  Scene scene;
  std::vector<Cloth> cloths;
  std::vector<std::unique_ptr<Integrator>> integrators;
  std::vector<Obstacle> obstacles;
  std::unique_ptr<ContactStage> contact;
  std::unique_ptr<TearStage> tearing;
  std::vector<std::vector<Vec3>> startPositions;  // each cloth's positions at the start of the step (contact)
  // Per cloth: its next step's membrane stage, evaluated at the end of this one when the cloth
  // tears (forces/membrane_ahead.h); the tear stage reads its stresses.
  std::vector<MembraneAhead> membraneAhead;
  double time = 0.0;
  long long steps = 0;
  // time() = timeOrigin + (steps - stepsAtOrigin) dt: no drift from summing dt, and a live change
  // of dt continues from the time reached.
  double timeOrigin = 0.0;
  long long stepsAtOrigin = 0;
  std::optional<GrabState> grab;
  std::vector<std::optional<Vec3>> kinematicTargets;  // per obstacle: where the editor drags it
  std::vector<Vec3> kinematicFrom;                     // per obstacle: its position when the step began
  StageProfile profile;
  SolverStats stats;

  bool windRuns() const { return scene.stages.wind && windEnabled(scene.forces.wind); }
  bool gravityRuns() const { return scene.stages.gravity && scene.forces.gravity.squaredNorm() > 0.0; }
  bool bendingRuns(const Cloth& cloth) const { return scene.stages.bending && !cloth.hinges.empty(); }
  // Substep `substep` of `substeps`: a dragged kinematic obstacle covers its share of the way
  // from where it was when the step began to its target.
  void beginObstacles(const StepInputs& inputs, int substep, int substeps) {
    if (obstacles.empty()) return;
    StageTimer timer(profile, "obstacles");
    for (size_t o = 0; o < obstacles.size(); ++o) {
      Obstacle& obstacle = obstacles[o];
      if (!kinematicTargets[o]) {
        beginObstacleStep(obstacle, inputs.time, inputs.dt, inputs.gravity);
        continue;
      }
      if (substep == 0) kinematicFrom[o] = obstacle.body.state.position;
      const double share = static_cast<double>(substep + 1) / substeps;
      RigidPose end = obstacle.body.state.pose();
      end.position = kinematicFrom[o] + share * (*kinematicTargets[o] - kinematicFrom[o]);
      beginObstacleStepTo(obstacle, end, inputs.dt);
    }
  }
  const GrabSpring* grabOn(size_t cloth) const {
    return grab && grab->cloth == static_cast<int>(cloth) ? &grab->spring : nullptr;
  }
  void endObstacles() {
    if (obstacles.empty()) return;
    StageTimer timer(profile, "obstacles");
    for (Obstacle& o : obstacles) endObstacleStep(o);
  }
  void saveStartPositions() {
    for (size_t c = 0; c < cloths.size(); ++c) startPositions[c] = cloths[c].mesh.x;
  }
  // The next step's membrane evaluation, done now for each cloth that can tear and whose
  // integrator evaluates the membrane where the cloth stands: the tear stage reads its stresses.
  // Any other cloth's cache is emptied.
  void evaluateMembraneAhead(int threads) {
    membraneAhead.resize(cloths.size());
    for (size_t c = 0; c < cloths.size(); ++c) {
      const std::optional<HessianMode> mode = integrators[c]->membraneModeAtStart();
      if (tearing->runs() && cloths[c].material.tearTable && mode) {
        membraneAhead[c].evaluate(cloths[c], *mode, threads, profile);
      } else {
        membraneAhead[c].clear();
      }
    }
  }
  const MembraneAhead* membraneAheadOf(size_t cloth) const {
    return cloth < membraneAhead.size() ? &membraneAhead[cloth] : nullptr;
  }
  // Tears what must tear, and has whatever depends on a torn cloth's topology patched with what
  // changed (the matrix pattern, the collision topology and broad phase).
  void tear(double time, double dt, int threads) {
    if (!tearing->runs()) return;
    const std::vector<TopologyChange> changes = tearing->run(cloths, membraneAhead, time, dt, threads, profile);
    for (size_t c = 0; c < cloths.size(); ++c) {
      if (changes[c].empty()) continue;
      integrators[c]->topologyChanged(cloths[c], changes[c]);
      contact->clothTopologyChanged(static_cast<int>(c), cloths[c].mesh, changes[c]);
    }
  }
  bool pinsRun() const {
    for (const Cloth& cloth : cloths)
      if (!cloth.pins.empty()) return true;
    return false;
  }
};

}  // namespace weft
