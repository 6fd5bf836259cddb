#include "sim/world.h"

#include <cmath>
#include <cstring>

#include "forces/elastic_forces.h"
#include "forces/wind.h"
#include "integrate/integrator.h"
#include "sim/cloth.h"

namespace weft {

struct World::Impl {
  Scene scene;
  std::vector<Cloth> cloths;
  std::vector<std::unique_ptr<Integrator>> integrators;
  double time = 0.0;
  long long steps = 0;
  StageProfile profile;
  SolverStats stats;

  bool windRuns() const { return scene.stages.wind && windEnabled(scene.forces.wind); }
  bool gravityRuns() const { return scene.stages.gravity && scene.forces.gravity.squaredNorm() > 0.0; }
  bool bendingRuns(const Cloth& cloth) const { return scene.stages.bending && !cloth.hinges.empty(); }
  bool pinsRun() const {
    for (const Cloth& cloth : cloths)
      if (!cloth.pins.empty()) return true;
    return false;
  }
};

World::World(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->scene = scene;
  for (size_t i = 0; i < scene.cloths.size(); ++i) {
    impl_->cloths.push_back(buildCloth(scene.cloths[i], scene.file.string(), static_cast<int>(i)));
    impl_->integrators.push_back(makeIntegrator(scene.solver));
  }
}

World::~World() = default;

void World::step() {
  Impl& w = *impl_;
  const int substeps = std::max(1, w.scene.solver.substeps);
  const double h = w.scene.solver.dt / substeps;
  for (int s = 0; s < substeps; ++s) {
    StepInputs inputs;
    inputs.time = w.time + s * h;
    inputs.dt = h;
    inputs.gravity = w.gravityRuns() ? w.scene.forces.gravity : Vec3::Zero();
    inputs.wind = w.windRuns() ? &w.scene.forces.wind : nullptr;
    inputs.damping = w.scene.forces.damping;
    inputs.threads = std::max(1, w.scene.solver.threads);
    for (size_t c = 0; c < w.cloths.size(); ++c) {
      inputs.bending = w.bendingRuns(w.cloths[c]);
      w.integrators[c]->advance(w.cloths[c], inputs, w.profile, w.stats);
    }
  }
  ++w.steps;
  w.time = w.steps * w.scene.solver.dt;  // no drift from summing dt
}

double World::time() const { return impl_->time; }
long long World::stepCount() const { return impl_->steps; }
const Scene& World::scene() const { return impl_->scene; }
int World::clothCount() const { return static_cast<int>(impl_->cloths.size()); }
const ClothMesh& World::cloth(int i) const { return impl_->cloths.at(i).mesh; }
const StageProfile& World::profile() const { return impl_->profile; }
const SolverStats& World::solverStats() const { return impl_->stats; }

std::vector<std::string> World::stagesRun() const {
  const Impl& w = *impl_;
  std::vector<std::string> stages;
  if (w.gravityRuns()) stages.push_back("gravity");
  if (w.windRuns()) stages.push_back("wind");
  if (w.pinsRun()) stages.push_back("pins");
  stages.push_back("membrane");
  bool bending = false;
  for (const Cloth& cloth : w.cloths) bending = bending || w.bendingRuns(cloth);
  if (bending) stages.push_back("bending");
  if (w.scene.solver.integrator != IntegratorKind::SymplecticEuler) {
    stages.push_back("assemble");
    stages.push_back("linear_solve");
  }
  stages.push_back("update");
  return stages;
}

WorldMetrics World::metrics() const {
  const Impl& w = *impl_;
  WorldMetrics m;
  StageProfile scratchProfile;  // metrics are not part of the step's timing
  for (const Cloth& cloth : w.cloths) {
    const ClothMesh& mesh = cloth.mesh;
    for (int i = 0; i < mesh.vertexCount(); ++i) {
      if (!mesh.x[i].allFinite() || !mesh.v[i].allFinite()) m.finite = false;
      m.kineticEnergy += 0.5 * mesh.mass[i] * mesh.v[i].squaredNorm();
      m.gravityEnergy -= mesh.mass[i] * w.scene.forces.gravity.dot(mesh.x[i]);
    }
    ElasticWorkspace workspace;
    std::vector<Vec3> forces;
    ElasticOptions options;
    options.bending = w.bendingRuns(cloth);
    const ElasticSummary elastic = evaluateElasticForces(cloth, mesh.x, options, workspace, forces, nullptr, scratchProfile);
    m.elasticEnergy += elastic.membraneEnergy + elastic.bendingEnergy;
    m.maxStrain = std::max(m.maxStrain, elastic.maxPrincipalStrain);
  }
  return m;
}

std::uint64_t World::stateHash() const {
  // FNV-1a, 64 bit, over the raw bytes of every position in cloth and vertex id order.
  std::uint64_t hash = 14695981039346656037ull;
  for (const Cloth& cloth : impl_->cloths) {
    for (const Vec3& x : cloth.mesh.x) {
      unsigned char bytes[sizeof(double) * 3];
      std::memcpy(bytes, x.data(), sizeof(bytes));
      for (unsigned char b : bytes) {
        hash ^= b;
        hash *= 1099511628211ull;
      }
    }
  }
  return hash;
}

}  // namespace weft
