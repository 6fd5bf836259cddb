// `weft validate SCENE`: load everything a run would load (scene, material presets, meshes) and
// check each mesh, without simulating. Meant for CI over presets/ and for editing scene files.
#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"
#include "contact/obstacle.h"
#include "mesh/grid.h"
#include "mesh/mesh_check.h"
#include "mesh/obj_import.h"
#include "scene/scene_json.h"
#include "sim/world.h"
#include "util/input_error.h"

namespace weft::app {
namespace {

struct ValidateOptions {
  std::string scene;
  std::vector<std::string> overrides;
  bool showVertexMap = false;  // list every `v` line's cloth vertices, not only the summary
};

// How an OBJ cloth's `v` lines became cloth vertices (obj_import.h): pins by id name `v` lines,
// and frames written with --obj list the cloth vertices, so a user matching the two needs this.
std::string describeVertexMap(const ClothSpec& cloth, const ObjVertexMap& map, bool everyLine) {
  int unused = 0, split = 0;
  for (const auto& ids : map.clothVertices) {
    unused += ids.empty() ? 1 : 0;
    split += ids.size() > 1 ? 1 : 0;
  }
  std::ostringstream out;
  out << "  cloth " << cloth.name << ": " << map.objVertexCount() << " `v` lines of " << cloth.obj->path.filename().string()
      << "; pins.vertices ids are `v` lines counted from 0; ";
  if (map.isIdentity()) {
    out << "cloth vertex k is `v` line k\n";
  } else {
    out << split << " split on UV seams, " << unused << " used by no face"
        << (everyLine ? "" : " (--vertex-map lists them)") << "\n";
  }
  if (everyLine) {
    for (std::size_t k = 0; k < map.clothVertices.size(); ++k) {
      out << "    v " << k << " -> ";
      if (map.clothVertices[k].empty()) out << "(unused)";
      for (std::size_t j = 0; j < map.clothVertices[k].size(); ++j) out << (j ? ", " : "") << map.clothVertices[k][j];
      out << "\n";
    }
  }
  return out.str();
}

int validateScene(const ValidateOptions& options) {
  try {
    const Scene scene = loadScene(options.scene, options.overrides);
    long long vertices = 0;
    long long triangles = 0;
    int problems = 0;
    std::vector<std::string> vertexMaps;  // printed after the summary line
    for (std::size_t i = 0; i < scene.cloths.size(); ++i) {
      const ClothSpec& cloth = scene.cloths[i];
      ObjVertexMap objVertices;
      const ClothMesh mesh =
          cloth.grid ? makeGrid(*cloth.grid) : loadObjMesh(*cloth.obj, scene.file.string(), &objVertices);
      const std::vector<std::string> found = checkMesh(mesh);
      for (const auto& line : groupProblems(found)) {
        std::cerr << "weft: " << scene.file.string() << ": /cloths/" << i << "/mesh: " << line << "\n";
      }
      problems += static_cast<int>(found.size());
      if (cloth.obj) vertexMaps.push_back(describeVertexMap(cloth, objVertices, options.showVertexMap));
      vertices += mesh.vertexCount();
      triangles += mesh.triangleCount();
    }
    if (problems > 0) return kExitBadInput;
    // Building the world resolves pins and precomputes every element, as a run would.
    const World world(scene);
    std::cout << "ok: " << scene.name << ": " << scene.cloths.size() << " cloths, " << vertices << " vertices, "
              << triangles << " triangles";
    if (world.obstacleCount() > 0) {
      int sharp = 0;
      for (int i = 0; i < world.obstacleCount(); ++i) {
        const Obstacle& o = world.obstacle(i);
        const bool anySharp = std::count(o.sharpVertex.begin(), o.sharpVertex.end(), 1) > 0 ||
                              std::count(o.sharpEdge.begin(), o.sharpEdge.end(), 1) > 0;
        sharp += anySharp ? 1 : 0;
      }
      std::cout << ", " << world.obstacleCount() << " obstacles (" << sharp << " with sharp tags)";
    }
    if (scene.ground.enabled) std::cout << ", ground at y = " << scene.ground.height;
    std::cout << "\n";
    for (const std::string& map : vertexMaps) std::cout << map;
    for (const ClothSpec& cloth : scene.cloths) {
      if (!cloth.material.tearTable) continue;
      const TearTable& table = *cloth.material.tearTable;
      std::cout << "  cloth " << cloth.name << " tears: table "
                << (table.name.empty() ? std::string("inline") : table.name) << ", " << table.strength.size()
                << " direction(s), weakest " << weakestStrength(table) << " N/m"
                << (scene.stages.tearing ? "" : " (tearing switched off)") << "\n";
      if (cloth.tearStrengthMap) {
        std::cout << "    strength map " << cloth.tearStrengthMap->image << " (" << cloth.tearStrengthMap->width << " x "
                  << cloth.tearStrengthMap->height << " px, multipliers " << cloth.tearStrengthMap->black << " to "
                  << cloth.tearStrengthMap->white << ")\n";
      }
      if (cloth.tearRegion) {
        const TearRegion& region = *cloth.tearRegion;
        std::cout << "    tear region " << region.outside.image << " (" << region.outside.width << " x "
                  << region.outside.height << " px): table "
                  << (region.table.name.empty() ? std::string("inline") : region.table.name) << ", weakest "
                  << weakestStrength(region.table) << " N/m (where the image is white)\n";
      }
    }
    return kExitOk;
  } catch (const InputError& e) {
    std::cerr << "weft: " << e.what() << "\n";
    return kExitBadInput;
  }
}

}  // namespace

Command addValidateCommand(CLI::App& app) {
  auto options = std::make_shared<ValidateOptions>();
  CLI::App* cli = app.add_subcommand("validate", "Check a scene file, its presets and meshes without simulating");
  cli->add_option("scene", options->scene, "Scene file (JSON)")->required();
  cli->add_option("--set", options->overrides, "Override a scene value, e.g. --set solver.dt=0.005 (repeatable)")
      ->type_name("PATH=VALUE")
      ->allow_extra_args(false);
  cli->add_flag("--vertex-map", options->showVertexMap,
                "For OBJ cloths, list the cloth vertex id(s) of every `v` line (pins.vertices name `v` lines)");
  return {cli, [options] { return validateScene(*options); }};
}

}  // namespace weft::app
