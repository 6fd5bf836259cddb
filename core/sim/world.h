#pragma once
// The simulated world: cloths and forces advanced in time. World::step is a short list of named
// stages, each timed into the profile.
//
// The editor changes a running world between steps through two groups of calls:
//  - live edits (world_live_edits.cpp; sim/live_edit.h decides which edits of a scene qualify):
//    they keep positions, velocities and the torn topology, and update scene() to match;
//  - interaction (world_interaction.cpp): grabbing a vertex, throwing a ball, dragging a tool.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/contact_passes.h"
#include "contact/contact_stage.h"
#include "forces/grab_spring.h"
#include "mesh/cloth_mesh.h"
#include "rigid/sharp_tags.h"
#include "scene/scene.h"
#include "sim/stage_profile.h"
#include "tearing/tear_record.h"

namespace weft {

struct Obstacle;
class TearStage;

struct SolverStats {
  long long linearIterations = 0;   // total linear-solver iterations (CG) since the start
  double lastLinearResidual = 0.0;  // relative residual of the last linear solve
  double maxLinearResidual = 0.0;   // largest relative residual of any linear solve
  long long newtonIterations = 0;   // total Newton iterations since the start
  double lastNewtonResidual = 0.0;  // last Newton step's final max velocity change (m/s)
  double lastNewtonFirstChange = 0.0;  // the same step's first iteration's max velocity change (m/s)
  long long linearSolveFailures = 0;  // solves that hit their iteration bound or failed to factor
  // BDF2 (integrate/bdf2.h): cloth steps taken as one backward Euler step because the two-step
  // history was invalid (the first step, a tear or edit, a contact response, held contacts, a new dt).
  long long bdf2Restarts = 0;
};

struct WorldMetrics {
  double maxStrain = 0.0;        // largest principal Green strain over all triangles; NaN when not finite
  double kineticEnergy = 0.0;    // J (cloths and dynamic obstacles)
  double elasticEnergy = 0.0;    // membrane + bending (J)
  double gravityEnergy = 0.0;    // J, relative to y = 0 (cloths and dynamic obstacles)
  bool finite = true;            // every position and velocity is finite
};

// The vertex the user holds and where the grab spring pulls it.
struct GrabState {
  int cloth = 0;
  GrabSpring spring;  // vertex id (stable across tears), target (m), stiffness (N/m)
};

class World {
 public:
  explicit World(const Scene& scene);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  void step();  // advance by scene.solver.dt

  // A copy that steps on exactly as this world would (world_clone.cpp): the cloths, obstacles,
  // contact memory (held contacts, kept pairs), tear state and log, grab, dragged tools, time,
  // statistics and the integrators' history, copied. The linear solvers' caches are not copied
  // (a pattern, a lagged Cholesky factor: the copy builds them at its first step), so with the
  // default lagged-Cholesky CG the copy's next solves differ from the original's within the CG
  // tolerance; with block Jacobi or the direct solver they agree bit for bit. The editor's
  // timeline keeps one per cached frame and continues from it after an edit (issue 21, item 7).
  std::unique_ptr<World> clone() const;
  // What a clone holds in memory, approximately (the contents of its vectors), for the timeline's
  // memory budget.
  std::size_t approximateBytes() const;

  // Live edits, applied between steps. Indices out of range throw std::out_of_range.
  // The material: elasticity, bending, density (the lumped masses are recomputed from the current,
  // possibly torn, triangles and the integrator refactors), the tear table (tearing starts or
  // stops with it).
  void setClothMaterial(int cloth, const Material& material);
  void setClothWeftAngle(int cloth, double degrees);  // membrane elements and hinges are rebuilt
  void setClothAppearance(int cloth, const ClothAppearance& appearance);  // no simulation effect
  void setClothLabels(int cloth, const std::string& name, const std::string& materialName);
  // The cloth's painted tear strength (tearing/strength_map.h; none: the table alone), prepared over
  // the cloth's material bounds unless its extent is explicit; read by the tearing stage from the
  // next step on (the editor's tear strength brush).
  void setClothTearStrengthMap(int cloth, const std::optional<TearStrengthMap>& map);
  // A second tear table over part of the cloth (tearing/tear_region.h), or none; live.
  void setClothTearRegion(int cloth, const std::optional<TearRegion>& region);
  void setForces(const ForcesSpec& forces);  // read afresh every step
  // dt, substeps and threads are read every step (time() continues from where it is); any other
  // change (integrator kind, linear solver, preconditioner, tolerances, iteration bounds) builds
  // fresh integrators, dropping their cached factorizations.
  void setSolver(const SolverSpec& solver);
  void setOutput(const OutputSpec& output);
  // A tool's sharp tags (the editor's tools panel): the contact stage records hits of the newly
  // sharp features from the next step on. Throws std::out_of_range for a bad obstacle or id.
  void setObstacleSharpTags(int obstacle, const SharpTags& tags);  // frames, fps, camera: no simulation effect
  void setSceneLabels(const std::string& name, const std::string& description);
  // Where an obstacle's sharp tags come from, as scene() records it (its shape's "sharp_tags"
  // file or inline tags): the tags themselves are not touched (applyLiveEdits calls it only when
  // that source holds the tags the obstacle already has). Throws std::out_of_range for a bad index.
  void setObstacleSharpTagsSource(int obstacle, const std::filesystem::path& file, const nlohmann::json& inlineTags);

  // Grab: a zero-rest-length spring (forces/grab_spring.h) from `vertex` of `cloth` to `target`,
  // part of the implicit solve; the "grab" stage runs while it is held. One grab at a time: a new
  // grab replaces the old one. Tears never renumber vertices, so the grab stays on the vertex id
  // (the original of a split vertex keeps it). Throws std::out_of_range for a bad cloth or vertex,
  // std::invalid_argument for a negative or non-finite stiffness.
  void grab(int cloth, int vertex, const Vec3& target, double stiffness);
  void moveGrab(const Vec3& target);  // no effect without a grab
  void releaseGrab();
  std::optional<GrabState> grabState() const;

  // Adds a dynamic rigid sphere (what a scene obstacle with shape sphere and motion dynamic
  // builds) at `position` moving at `velocity`, and returns its obstacle index. When the scene had
  // no contact with obstacles, this turns it on (only it: self-collision and the ground, which did
  // not run, stay off). The contact stage is rebuilt (its statistics are kept).
  int throwBall(const Vec3& position, const Vec3& velocity, double radius, double mass);

  // A kinematic obstacle follows `position` (its orientation kept) instead of its script, starting
  // with the next step: each step takes it from where it is to there (in equal parts over the
  // substeps), and its recorded velocity is that displacement over the step, as CCD and the sharp
  // records see it. Clearing hands it back to its script at the current time (from where the
  // script is, which may be a jump). Throws std::out_of_range for a bad index,
  // std::invalid_argument for an obstacle that is not kinematic.
  void setKinematicOverride(int obstacle, const Vec3& position);
  void clearKinematicOverride(int obstacle);

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
  explicit World(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace weft
