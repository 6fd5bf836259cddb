#pragma once
// The simulated world: cloths and forces advanced in time. World::step is a short list of named
// stages, each timed into the profile.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_passes.h"
#include "contact/contact_stage.h"
#include "mesh/cloth_mesh.h"
#include "scene/scene.h"
#include "sim/stage_profile.h"
#include "tearing/tear_stage.h"

namespace weft {

struct Obstacle;

struct SolverStats {
  long long linearIterations = 0;   // total linear-solver iterations (CG) since the start
  double lastLinearResidual = 0.0;  // relative residual of the last linear solve
  double maxLinearResidual = 0.0;   // largest relative residual of any linear solve
  long long newtonIterations = 0;   // total Newton iterations since the start
  double lastNewtonResidual = 0.0;  // last Newton step's final max velocity change (m/s)
  long long linearSolveFailures = 0;  // solves that hit their iteration bound or failed to factor
};

struct WorldMetrics {
  double maxStrain = 0.0;        // largest principal Green strain over all triangles
  double kineticEnergy = 0.0;    // J (cloths and dynamic obstacles)
  double elasticEnergy = 0.0;    // membrane + bending (J)
  double gravityEnergy = 0.0;    // J, relative to y = 0 (cloths and dynamic obstacles)
  bool finite = true;            // every position and velocity is finite
};

class World {
 public:
  explicit World(const Scene& scene);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  void step();  // advance by scene.solver.dt

  double time() const;
  long long stepCount() const;
  const Scene& scene() const;
  int clothCount() const;
  const ClothMesh& cloth(int i) const;
  int obstacleCount() const;
  const Obstacle& obstacle(int i) const;
  // The obstacle's mesh in the world at the current time.
  std::vector<Vec3> obstacleVertices(int i) const;
  bool contactRuns() const;  // the scene has a collision stage
  const ContactStats& contactStats() const;
  const std::vector<SharpContactRecord>& sharpContacts() const;  // of the latest step
  bool tearingRuns() const;  // some cloth can tear
  const std::vector<TearRecord>& tearLog() const;  // every tear since the start, in order
  const TearStats& tearStats() const;
  const StageProfile& profile() const;
  const SolverStats& solverStats() const;
  std::vector<std::string> stagesRun() const;  // names of the stages this scene runs
  WorldMetrics metrics() const;
  std::uint64_t stateHash() const;  // FNV-1a over the bytes of every position, in id order

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace weft
