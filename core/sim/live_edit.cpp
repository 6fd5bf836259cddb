#include "sim/live_edit.h"

#include <stdexcept>

#include "contact/obstacle.h"
#include "sim/world.h"

namespace weft {

namespace {

bool sameSharpTagsSource(const ShapeSpec& a, const ShapeSpec& b) {
  return a.sharpTagsPath == b.sharpTagsPath && a.sharpTagsInline == b.sharpTagsInline;
}

// Whether obstacle `i`'s sharp-tags source in `edited` yields the tags it has in `world`.
bool sourceHoldsWorldsTags(const Scene& edited, int i, const World& world) {
  if (i >= world.obstacleCount()) return false;
  const ObstacleSpec& spec = edited.obstacles[static_cast<std::size_t>(i)];
  const Obstacle& obstacle = world.obstacle(i);
  if (obstacle.name != spec.name) return false;
  try {
    return sharpTagsOfSpec(spec, edited.file.string(), i) == sharpTagsOf(obstacle);
  } catch (const std::exception&) {
    return false;  // unreadable: the reset reports why
  }
}

// `edited` with every live field taken from `running`: what is left to differ needs a reset.
// With `world`, an obstacle's sharp-tags source holding the tags it has there counts as live too.
Scene withoutLiveEdits(const Scene& running, Scene edited, const World* world = nullptr) {
  if (world != nullptr && edited.obstacles.size() == running.obstacles.size()) {
    for (std::size_t i = 0; i < edited.obstacles.size(); ++i) {
      ShapeSpec& shape = edited.obstacles[i].shape;
      const ShapeSpec& was = running.obstacles[i].shape;
      if (!sameSharpTagsSource(shape, was) && sourceHoldsWorldsTags(edited, static_cast<int>(i), *world)) {
        shape.sharpTagsPath = was.sharpTagsPath;
        shape.sharpTagsInline = was.sharpTagsInline;
      }
    }
  }
  // Where the file lives names it in messages; what it loads is compared resolved (mesh and
  // preset paths), so saving it elsewhere (Save as) does not make the next edit need a reset.
  edited.file = running.file;
  edited.name = running.name;
  edited.description = running.description;
  edited.forces = running.forces;
  edited.solver = running.solver;
  edited.output = running.output;
  if (edited.cloths.size() != running.cloths.size()) return edited;
  for (size_t c = 0; c < edited.cloths.size(); ++c) {
    ClothSpec& cloth = edited.cloths[c];
    const ClothSpec& was = running.cloths[c];
    cloth.name = was.name;
    cloth.materialName = was.materialName;
    cloth.material = was.material;
    cloth.weftAngleDeg = was.weftAngleDeg;
    cloth.appearance = was.appearance;
    cloth.tearStrengthMap = was.tearStrengthMap;
    cloth.tearRegion = was.tearRegion;
  }
  return edited;
}

}  // namespace

bool needsReset(const Scene& running, const Scene& edited) { return !(withoutLiveEdits(running, edited) == running); }

bool needsReset(const Scene& running, const Scene& edited, const World& world) {
  return !(withoutLiveEdits(running, edited, &world) == running);
}

void applyLiveEdits(World& world, const Scene& edited) {
  const Scene running = world.scene();  // a copy: the setters change world.scene()
  if (needsReset(running, edited) && needsReset(running, edited, world))
    throw std::invalid_argument("applyLiveEdits: the edit needs the world rebuilt (see needsReset)");
  for (int c = 0; c < static_cast<int>(edited.cloths.size()); ++c) {
    const ClothSpec& cloth = edited.cloths[c];
    const ClothSpec& was = running.cloths[c];
    if (!(cloth.material == was.material)) world.setClothMaterial(c, cloth.material);
    if (cloth.weftAngleDeg != was.weftAngleDeg) world.setClothWeftAngle(c, cloth.weftAngleDeg);
    if (!(cloth.appearance == was.appearance)) world.setClothAppearance(c, cloth.appearance);
    if (!(cloth.tearStrengthMap == was.tearStrengthMap)) world.setClothTearStrengthMap(c, cloth.tearStrengthMap);
    if (!(cloth.tearRegion == was.tearRegion)) world.setClothTearRegion(c, cloth.tearRegion);
    if (cloth.name != was.name || cloth.materialName != was.materialName)
      world.setClothLabels(c, cloth.name, cloth.materialName);
  }
  if (!(edited.forces == running.forces)) world.setForces(edited.forces);
  if (!(edited.solver == running.solver)) world.setSolver(edited.solver);
  if (!(edited.output == running.output)) world.setOutput(edited.output);
  if (edited.name != running.name || edited.description != running.description)
    world.setSceneLabels(edited.name, edited.description);
  if (edited.obstacles.size() == running.obstacles.size()) {
    for (std::size_t i = 0; i < edited.obstacles.size(); ++i) {
      const ShapeSpec& shape = edited.obstacles[i].shape;
      if (!sameSharpTagsSource(shape, running.obstacles[i].shape)) {
        world.setObstacleSharpTagsSource(static_cast<int>(i), shape.sharpTagsPath, shape.sharpTagsInline);
      }
    }
  }
}

}  // namespace weft
