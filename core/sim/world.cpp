#include "sim/world.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "forces/elastic_forces.h"
#include "sim/world_impl.h"

namespace weft {

World::World(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->scene = scene;
  for (size_t i = 0; i < scene.cloths.size(); ++i) {
    impl_->cloths.push_back(buildCloth(scene.cloths[i], scene.file.string(), static_cast<int>(i)));
    impl_->integrators.push_back(makeIntegrator(scene.solver));
  }
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    impl_->obstacles.push_back(buildObstacle(scene.obstacles[i], scene.file.string(), static_cast<int>(i)));
  }
  impl_->contact = std::make_unique<ContactStage>(scene);
  impl_->tearing = std::make_unique<TearStage>(scene);
  impl_->startPositions.resize(impl_->cloths.size());
  impl_->kinematicTargets.resize(impl_->obstacles.size());
  impl_->kinematicFrom.resize(impl_->obstacles.size(), Vec3::Zero());
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
    w.beginObstacles(inputs, s, substeps);
    if (w.contact->runs()) w.saveStartPositions();
    w.contact->prepare(w.cloths, w.startPositions, w.obstacles, h, w.profile);
    for (size_t c = 0; c < w.cloths.size(); ++c) {
      inputs.bending = w.bendingRuns(w.cloths[c]);
      inputs.heldVertices = w.contact->heldVertices(static_cast<int>(c));
      inputs.grab = w.grabOn(c);
      inputs.membraneAhead = w.membraneAheadOf(c);
      w.integrators[c]->advance(w.cloths[c], inputs, w.profile, w.stats);
    }
    w.contact->applyHeldReactions(w.cloths, w.obstacles, h);
    w.contact->resolve(w.cloths, w.startPositions, w.obstacles, h, w.profile);
    w.endObstacles();
    w.evaluateMembraneAhead(inputs.threads);
    w.tear(inputs.time + h, h, inputs.threads);
  }
  ++w.steps;
  w.time = w.timeOrigin + static_cast<double>(w.steps - w.stepsAtOrigin) * w.scene.solver.dt;
}

double World::time() const { return impl_->time; }
long long World::stepCount() const { return impl_->steps; }
const Scene& World::scene() const { return impl_->scene; }
int World::clothCount() const { return static_cast<int>(impl_->cloths.size()); }
const ClothMesh& World::cloth(int i) const { return impl_->cloths.at(i).mesh; }
int World::obstacleCount() const { return static_cast<int>(impl_->obstacles.size()); }
const Obstacle& World::obstacle(int i) const { return impl_->obstacles.at(i); }
std::vector<Vec3> World::obstacleVertices(int i) const {
  const Obstacle& o = impl_->obstacles.at(i);
  std::vector<Vec3> world;
  world.reserve(o.bodyVertices.size());
  for (const Vec3& p : o.bodyVertices) world.push_back(o.body.state.position + o.body.state.orientation * p);
  return world;
}
bool World::contactRuns() const { return impl_->contact->runs(); }
const ContactStats& World::contactStats() const { return impl_->contact->stats(); }
const std::vector<SharpContactRecord>& World::sharpContacts() const { return impl_->contact->sharpRecords(); }
bool World::tearingRuns() const { return impl_->tearing->runs(); }
const std::vector<TearRecord>& World::tearLog() const { return impl_->tearing->log(); }
const TearStats& World::tearStats() const { return impl_->tearing->stats(); }
const StageProfile& World::profile() const { return impl_->profile; }
const SolverStats& World::solverStats() const { return impl_->stats; }

std::vector<std::string> World::stagesRun() const {
  const Impl& w = *impl_;
  std::vector<std::string> stages;
  if (w.gravityRuns()) stages.push_back("gravity");
  if (w.windRuns()) stages.push_back("wind");
  if (w.pinsRun()) stages.push_back("pins");
  stages.push_back("membrane");
  if (w.grab) stages.push_back("grab");
  bool bending = false;
  for (const Cloth& cloth : w.cloths) bending = bending || w.bendingRuns(cloth);
  if (bending) stages.push_back("bending");
  if (w.scene.solver.integrator != IntegratorKind::SymplecticEuler) {
    stages.push_back("assemble");
    stages.push_back("linear_solve");
  }
  stages.push_back("update");
  if (!w.obstacles.empty()) stages.push_back("obstacles");
  if (w.contact->runs()) {
    stages.push_back("contact_start_pairs");
    stages.push_back("contact_held");  // when the integrator holds vertices (the implicit ones)
    stages.push_back("contact_proximity");
    stages.push_back("contact_ccd");
    stages.push_back("contact_impact_zones");  // only when pass 2 leaves collisions
  }
  if (w.tearing->runs()) {
    stages.push_back("tear_stress");
    stages.push_back("tear_search");
    stages.push_back("tear_surgery");  // only in steps that tear
  }
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
    // NaN must not vanish into std::max (a blown-up run would report a strain of 0).
    const double strain = elastic.maxPrincipalStrain;
    m.maxStrain = std::isnan(strain) || std::isnan(m.maxStrain) ? std::numeric_limits<double>::quiet_NaN()
                                                                  : std::max(m.maxStrain, strain);
  }
  for (const Obstacle& o : w.obstacles) {
    if (o.motion != ObstacleMotion::Dynamic) continue;
    m.kineticEnergy += o.body.kineticEnergy();
    m.gravityEnergy -= o.body.mass * w.scene.forces.gravity.dot(o.body.state.position);
    if (!o.body.state.position.allFinite() || !o.body.state.linearVelocity.allFinite()) m.finite = false;
  }
  // The elastic evaluation skips what it cannot measure, so a NaN state would report a strain of 0.
  if (!m.finite) m.maxStrain = std::numeric_limits<double>::quiet_NaN();
  return m;
}

std::uint64_t World::stateHash() const {
  // FNV-1a, 64 bit, over the raw bytes of every cloth position in cloth and vertex id order, then
  // of each dynamic obstacle's position and orientation (scenes without one hash as before).
  std::uint64_t hash = 14695981039346656037ull;
  auto mix = [&hash](const double* values, int count) {
    unsigned char bytes[sizeof(double) * 4];
    std::memcpy(bytes, values, sizeof(double) * count);
    for (int k = 0; k < static_cast<int>(sizeof(double)) * count; ++k) {
      hash ^= bytes[k];
      hash *= 1099511628211ull;
    }
  };
  for (const Cloth& cloth : impl_->cloths) {
    for (const Vec3& x : cloth.mesh.x) mix(x.data(), 3);
  }
  for (const Obstacle& o : impl_->obstacles) {
    if (o.motion != ObstacleMotion::Dynamic) continue;
    mix(o.body.state.position.data(), 3);
    mix(o.body.state.orientation.coeffs().data(), 4);
  }
  return hash;
}

}  // namespace weft
