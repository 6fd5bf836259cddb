// Live edits of a running World (world.h): each keeps positions, velocities and the torn topology,
// refreshes what was derived from the edited value, and records the value in the World's scene.
#include <stdexcept>

#include "sim/world_impl.h"

namespace weft {

namespace {

Cloth& clothAt(std::vector<Cloth>& cloths, int cloth) {
  if (cloth < 0 || cloth >= static_cast<int>(cloths.size()))
    throw std::out_of_range("no cloth " + std::to_string(cloth) + " (the world has " + std::to_string(cloths.size()) + ")");
  return cloths[cloth];
}

// The settings an integrator is built from (makeIntegrator), as opposed to those it is handed each
// step (dt, substeps, threads).
bool integratorSettingsDiffer(const SolverSpec& a, SolverSpec b) {
  b.dt = a.dt;
  b.substeps = a.substeps;
  b.threads = a.threads;
  return !(a == b);
}

}  // namespace

void World::setClothMaterial(int index, const Material& material) {
  Impl& w = *impl_;
  Cloth& cloth = clothAt(w.cloths, index);
  cloth.material = material;
  // Masses from the current triangles: after tears the same lumping the surgery keeps up.
  assignLumpedMasses(cloth.mesh, material.areaDensity);
  rebuildElements(cloth);  // the bending model decides which hinges exist
  // The masses and possibly the hinges changed: a fresh pattern, so the lagged factorization is
  // redone at the next solve instead of preconditioning with the old matrix.
  w.integrators[index]->topologyChanged();
  w.scene.cloths[index].material = material;
  w.tearing->materialsChanged(w.scene);
}

void World::setClothWeftAngle(int index, double degrees) {
  Impl& w = *impl_;
  Cloth& cloth = clothAt(w.cloths, index);
  cloth.weftAngleRad = degToRad(degrees);
  rebuildElements(cloth);  // membrane elements and hinge stiffnesses are oriented by the weft
  w.integrators[index]->topologyChanged();
  w.scene.cloths[index].weftAngleDeg = degrees;
}

void World::setClothAppearance(int index, const ClothAppearance& appearance) {
  clothAt(impl_->cloths, index);
  impl_->scene.cloths[index].appearance = appearance;
}

void World::setClothLabels(int index, const std::string& name, const std::string& materialName) {
  clothAt(impl_->cloths, index).name = name;
  impl_->scene.cloths[index].name = name;
  impl_->scene.cloths[index].materialName = materialName;
}

void World::setClothTearStrengthMap(int index, const std::optional<TearStrengthMap>& map) {
  Impl& w = *impl_;
  Cloth& cloth = clothAt(w.cloths, index);
  cloth.tearStrengthMap = map;
  // Over the material bounding box, as buildCloth places it.
  if (cloth.tearStrengthMap) prepareStrengthMapFor(*cloth.tearStrengthMap, cloth.mesh);
  w.scene.cloths[index].tearStrengthMap = map;
}

void World::setClothTearRegion(int index, const std::optional<TearRegion>& region) {
  Impl& w = *impl_;
  Cloth& cloth = clothAt(w.cloths, index);
  cloth.tearRegion = region;
  if (cloth.tearRegion) prepareStrengthMapFor(cloth.tearRegion->outside, cloth.mesh);
  w.scene.cloths[index].tearRegion = region;
}

void World::setForces(const ForcesSpec& forces) { impl_->scene.forces = forces; }

void World::setSolver(const SolverSpec& solver) {
  Impl& w = *impl_;
  const SolverSpec old = w.scene.solver;
  if (solver.dt != old.dt) {
    w.timeOrigin = w.time;
    w.stepsAtOrigin = w.steps;
  }
  w.scene.solver = solver;
  if (!integratorSettingsDiffer(old, solver)) return;
  for (auto& integrator : w.integrators) integrator = makeIntegrator(solver);
  // Only linearized backward Euler holds resting vertices in its solve (contact_stage.h).
  if (solver.integrator != old.integrator) w.contact->reconfigure(w.scene);
}

void World::setOutput(const OutputSpec& output) { impl_->scene.output = output; }

void World::setObstacleSharpTags(int index, const SharpTags& tags) {
  std::vector<Obstacle>& obstacles = impl_->obstacles;
  if (index < 0 || index >= static_cast<int>(obstacles.size())) throw std::out_of_range("no obstacle " + std::to_string(index));
  Obstacle& obstacle = obstacles[static_cast<std::size_t>(index)];
  const int vertices = static_cast<int>(obstacle.bodyVertices.size());
  for (int v : tags.vertices) {
    if (v < 0 || v >= vertices) throw std::out_of_range("no vertex " + std::to_string(v) + " on " + obstacle.name);
  }
  for (const auto& e : tags.edges) {
    if (e[0] < 0 || e[1] >= vertices || e[0] >= e[1]) throw std::out_of_range("no edge on " + obstacle.name);
  }
  markSharpFeatures(tags, obstacle);
}

void World::setObstacleSharpTagsSource(int index, const std::filesystem::path& file, const nlohmann::json& inlineTags) {
  std::vector<ObstacleSpec>& specs = impl_->scene.obstacles;
  if (index < 0 || index >= static_cast<int>(specs.size())) throw std::out_of_range("no obstacle " + std::to_string(index));
  ShapeSpec& shape = specs[static_cast<std::size_t>(index)].shape;
  shape.sharpTagsPath = file;
  shape.sharpTagsInline = inlineTags;
}

void World::setSceneLabels(const std::string& name, const std::string& description) {
  impl_->scene.name = name;
  impl_->scene.description = description;
}

}  // namespace weft
