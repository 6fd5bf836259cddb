#include "support/moving_sheet_system.h"

#include <string>
#include <vector>

#include "forces/elastic_forces.h"
#include "scene/scene_json.h"
#include "sim/cloth.h"
#include "sim/world.h"

namespace weft::test {

ClothSystem movingSheetSystem(int resolution, int stepsBefore) {
  const std::string file = std::string(WEFT_SOURCE_DIR) + "/presets/scenes/hanging-sheet.json";
  const std::string size = std::to_string(resolution);
  const Scene scene = loadScene(file, {"cloths.0.mesh.grid.resolution=[" + size + "," + size + "]"});
  World world(scene);
  for (int s = 0; s < stepsBefore; ++s) world.step();
  Cloth cloth = buildCloth(scene.cloths[0], file, 0);
  cloth.mesh = world.cloth(0);
  const int n = cloth.mesh.vertexCount();
  const double h = scene.solver.dt;

  ClothSystem system;
  const CoupledVertexPairs pairs = coupledVertexPairs(cloth);
  system.A.setPattern(n, pairs.edges, pairs.hingeWings);
  system.A.setZero();
  ElasticOptions options;
  options.hessian = HessianMode::Definite;
  ElasticWorkspace workspace;
  std::vector<Vec3> forces;
  StageProfile profile;
  evaluateElasticForces(cloth, cloth.mesh.x, options, workspace, forces, &system.A, profile);
  system.A.matrix() *= h * h;
  system.b.resize(3 * n);
  for (int i = 0; i < n; ++i) {
    const double m = cloth.mesh.mass[i];
    system.A.addDiagonal(i, (1.0 + h * scene.forces.damping.mass) * m);
    system.b.segment<3>(3 * i) = m * cloth.mesh.v[i] + h * (forces[i] + m * scene.forces.gravity);
  }
  std::vector<int> pinned;
  std::vector<Vec3> targets;
  pinTargets(cloth, world.time() + h, pinned, targets, profile);
  Eigen::VectorXd known = Eigen::VectorXd::Zero(3 * n);
  for (size_t k = 0; k < pinned.size(); ++k)
    known.segment<3>(3 * pinned[k]) = (targets[k] - cloth.mesh.x[pinned[k]]) / h;
  system.A.constrainVertices(pinned, known, system.b);
  return system;
}

}  // namespace weft::test
