#include "sim/live_edit.h"

#include <stdexcept>

#include "sim/world.h"

namespace weft {

namespace {

// `edited` with every live field taken from `running`: what is left to differ needs a reset.
Scene withoutLiveEdits(const Scene& running, Scene edited) {
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
  }
  return edited;
}

}  // namespace

bool needsReset(const Scene& running, const Scene& edited) { return !(withoutLiveEdits(running, edited) == running); }

void applyLiveEdits(World& world, const Scene& edited) {
  const Scene running = world.scene();  // a copy: the setters change world.scene()
  if (needsReset(running, edited))
    throw std::invalid_argument("applyLiveEdits: the edit needs the world rebuilt (see needsReset)");
  for (int c = 0; c < static_cast<int>(edited.cloths.size()); ++c) {
    const ClothSpec& cloth = edited.cloths[c];
    const ClothSpec& was = running.cloths[c];
    if (!(cloth.material == was.material)) world.setClothMaterial(c, cloth.material);
    if (cloth.weftAngleDeg != was.weftAngleDeg) world.setClothWeftAngle(c, cloth.weftAngleDeg);
    if (!(cloth.appearance == was.appearance)) world.setClothAppearance(c, cloth.appearance);
    if (cloth.name != was.name || cloth.materialName != was.materialName)
      world.setClothLabels(c, cloth.name, cloth.materialName);
  }
  if (!(edited.forces == running.forces)) world.setForces(edited.forces);
  if (!(edited.solver == running.solver)) world.setSolver(edited.solver);
  if (!(edited.output == running.output)) world.setOutput(edited.output);
  if (edited.name != running.name || edited.description != running.description)
    world.setSceneLabels(edited.name, edited.description);
}

}  // namespace weft
