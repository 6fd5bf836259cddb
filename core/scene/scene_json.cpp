#include "scene/scene_json.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "material/material.h"
#include "mesh/grid.h"
#include "mesh/obj_import.h"
#include "util/echo.h"
#include "util/input_error.h"
#include "util/json_text.h"
#include "util/json_fields.h"
#include "scene/contact_json.h"
#include "scene/tearing_json.h"
#include "scene/scene_json_parts.h"
#include "scene/scene_limits.h"

namespace weft {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Sections.

GridSpec parseGrid(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"width", "height", "resolution"});
  GridSpec grid;
  grid.width = r.number("width", grid.width, limits::kClothSize, "width");
  grid.height = r.number("height", grid.height, limits::kClothSize, "height");
  if (r.has("resolution")) {
    const json& res = r.at("resolution");
    const std::string at = r.pointer("resolution");
    if (!res.is_array() || res.size() != 2) {
      r.fail(at, "must be [vertices along x, vertices along y], two integers >= 2, " + got(res));
    }
    grid.resolutionX = r.integerValue(res[0], childPointer(at, std::size_t{0}), 2, limits::kMaxGridResolution);
    grid.resolutionY = r.integerValue(res[1], childPointer(at, std::size_t{1}), 2, limits::kMaxGridResolution);
    const std::int64_t vertices = std::int64_t{grid.resolutionX} * grid.resolutionY;
    if (vertices > limits::kMaxClothVertices) {
      r.fail(at, std::to_string(grid.resolutionX) + " x " + std::to_string(grid.resolutionY) + " = " +
                     std::to_string(vertices) + " vertices; a cloth has at most " +
                     std::to_string(limits::kMaxClothVertices) + " (1024 x 1024)");
    }
  }
  return grid;
}

ObjSpec parseObj(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"path", "uv_scale"});
  ObjSpec obj;
  const std::string relative = r.stringValue(r.required("path", "the OBJ file's path (a string)"), r.pointer("path"));
  obj.uvScale = r.number("uv_scale", obj.uvScale, limits::kUvScale, "uv_scale");
  obj.path = resolveAsset(relative, r, "path", ctx);
  return obj;
}

void parseMesh(const json& j, const std::string& pointer, const SceneReadContext& ctx, ClothSpec& cloth) {
  const FieldReader r(j, pointer, ctx.file, {"grid", "obj"});
  if (r.has("grid") == r.has("obj")) {
    r.fail(pointer, "needs exactly one of \"grid\" and \"obj\", e.g. {\"grid\": {\"resolution\": [32, 32]}}");
  }
  if (r.has("grid")) cloth.grid = parseGrid(r.at("grid"), r.pointer("grid"), ctx);
  if (r.has("obj")) cloth.obj = parseObj(r.at("obj"), r.pointer("obj"), ctx);
}

Placement parsePlacement(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"translate", "rotate_deg"});
  Placement p;
  p.translate = vec3(r, "translate", p.translate);
  p.rotateDeg = vec3(r, "rotate_deg", p.rotateDeg);
  return p;
}

void parseMaterialField(const FieldReader& r, const SceneReadContext& ctx, ClothSpec& cloth) {
  const json& value = r.required("material", "a preset name (presets/materials/NAME.json) or a material object");
  const std::string at = r.pointer("material");
  if (value.is_object()) {
    cloth.material = parseMaterial(value, ctx.file, at);
    cloth.materialName = "inline";
    return;
  }
  if (!value.is_string()) r.fail(at, "must be a preset name or a material object, " + got(value));
  const std::string name = value.get<std::string>();
  requirePresetNameLength(r, at, name);
  // loadMaterialPreset names the scene field and lists the available presets when `name` is unknown.
  fs::path found;
  cloth.material = loadMaterialPreset(name, ctx.paths.materialDirs, ctx.file, at, &found);
  cloth.materialName = name;
  ctx.read(found);
}

// A cloth's own tear table replaces its material's: a preset name (presets/tear_tables/NAME.json)
// or an inline table.
// The tear table at r's `key`: a preset name (presets/tear_tables/NAME.json) or an inline table.
TearTable parseTearTableValue(const FieldReader& r, const std::string& key, const SceneReadContext& ctx) {
  const json& value = r.at(key);
  const std::string at = r.pointer(key);
  if (value.is_object()) return parseTearTable(value, ctx.file, at);
  if (!value.is_string()) r.fail(at, "must be a tear table preset name or a tear table object, " + got(value));
  requirePresetNameLength(r, at, value.get<std::string>());
  fs::path found;
  TearTable table = loadTearTablePreset(value.get<std::string>(), ctx.paths.tearTableDirs, ctx.file, at, &found);
  ctx.read(found);
  return table;
}

void parseTearTableField(const FieldReader& r, const SceneReadContext& ctx, ClothSpec& cloth) {
  if (r.has("tear_table")) cloth.material.tearTable = parseTearTableValue(r, "tear_table", ctx);
}

// An image's rectangle in material space, when r has an "extent": {"min": [x, y], "max": [x, y]}.
void parseImageExtent(const FieldReader& r, const SceneReadContext& ctx, TearStrengthMap& map) {
  if (!r.has("extent")) return;
  const FieldReader box(r.at("extent"), r.pointer("extent"), ctx.file, {"min", "max"});
  map.lo = vec2Value(box, box.required("min", "the image's [x, y] minimum in material space (m)"), box.pointer("min"));
  map.hi = vec2Value(box, box.required("max", "the image's [x, y] maximum in material space (m)"), box.pointer("max"));
  if (!(map.hi.x() > map.lo.x() && map.hi.y() > map.lo.y())) {
    box.fail(box.pointer("max"), "must be above \"min\" in x and y (the image's rectangle in material space)");
  }
  map.explicitExtent = true;
}

// A painted multiplier on the tear table's strength (tearing/strength_map.h):
// {"image": "FILE.png", "black": 0.25, "white": 1.0, "reach_m": 0.04,
//  "extent": {"min": [x, y], "max": [x, y]}}; the image is found as OBJ meshes are.
void parseTearStrengthMapField(const FieldReader& parent, const SceneReadContext& ctx, ClothSpec& cloth) {
  if (!parent.has("tear_strength_map")) return;
  const json& value = parent.at("tear_strength_map");
  const std::string at = parent.pointer("tear_strength_map");
  if (!value.is_object()) {
    parent.fail(at, "must be an object, e.g. {\"image\": \"perforation.png\", \"black\": 0.2, \"white\": 1}, " +
                        got(value));
  }
  const FieldReader r(value, at, ctx.file, {"image", "black", "white", "reach_m", "extent"});
  TearStrengthMap map;
  map.image = r.stringValue(r.required("image", "the grayscale image's file (PNG), found as OBJ meshes are"),
                            r.pointer("image"));
  const Range multiplier{0.0, 1000.0, true, ""};
  map.black = r.number("black", map.black, multiplier, "the multiplier on the tear strength where the image is black");
  map.white = r.number("white", map.white, multiplier, "the multiplier on the tear strength where the image is white");
  map.reach = r.number("reach_m", map.reach, Range{0.0, 1.0, true, "m"},
                       "how far along a line the map is read either side of its vertex (m)");
  parseImageExtent(r, ctx, map);
  const fs::path file = resolveAsset(map.image, r, "image", ctx);
  readStrengthImage(file.string(), ctx.file, r.pointer("image"), map);
  cloth.tearStrengthMap = std::move(map);
}

// A second tear table over part of the cloth (tearing/tear_region.h):
// {"image": "FILE.png", "tear_table": NAME or {...}, "reach_m": 0.04,
//  "extent": {"min": [x, y], "max": [x, y]}}; white is the region, black the cloth's own table.
void parseTearRegionField(const FieldReader& parent, const SceneReadContext& ctx, ClothSpec& cloth) {
  if (!parent.has("tear_region")) return;
  const json& value = parent.at("tear_region");
  const std::string at = parent.pointer("tear_region");
  if (!value.is_object()) {
    parent.fail(at, "must be an object, e.g. {\"image\": \"seam.png\", \"tear_table\": \"NAME\"}, " + got(value));
  }
  const FieldReader r(value, at, ctx.file, {"image", "tear_table", "reach_m", "extent"});
  const std::string image =
      r.stringValue(r.required("image", "the region's grayscale image (PNG; white: the region), found as OBJ meshes are"),
                    r.pointer("image"));
  r.required("tear_table", "the region's tear table: a preset name or a table object");
  const TearTable table = parseTearTableValue(r, "tear_table", ctx);
  if (!cloth.material.tearTable) {
    parent.fail(at, "needs the cloth's own tear table (\"tear_table\" on the cloth or its material): the region "
                    "blends its table with it");
  }
  const double reach = r.number("reach_m", 0.04, Range{0.0, 1.0, true, "m"},
                                "how far along a line the region's image is read either side of its vertex (m)");
  const fs::path file = resolveAsset(image, r, "image", ctx);
  TearRegion region = makeTearRegion(file.string(), ctx.file, r.pointer("image"), table, reach);
  region.outside.image = image;
  parseImageExtent(r, ctx, region.outside);
  cloth.tearRegion = std::move(region);
}

const std::vector<std::string>& cornerNames() {
  static const std::vector<std::string> names{"top_left", "top_right", "bottom_left", "bottom_right"};
  return names;
}

std::vector<PinKeyframe> parseScript(const json& j, const std::string& pointer, const SceneReadContext& ctx,
                                     const FieldReader& parent) {
  if (!j.is_array()) parent.fail(pointer, "must be an array of {\"t\": seconds, \"offset\": [x, y, z]}, " + got(j));
  std::vector<PinKeyframe> script;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const FieldReader r(j[k], childPointer(pointer, k), ctx.file, {"t", "offset"});
    PinKeyframe key;
    key.time = r.numberValue(r.required("t", "the key's time in seconds"), r.pointer("t"), Bound::NonNegative);
    key.offset = vec3Value(r, r.required("offset", "the offset [x, y, z] in metres"), r.pointer("offset"));
    if (!script.empty() && key.time <= script.back().time) {
      r.fail(r.pointer("t"), "keys must be in increasing time order; this key's time " + std::to_string(key.time) +
                                 " does not come after the previous key's " + std::to_string(script.back().time));
    }
    script.push_back(key);
  }
  return script;
}

PinGroup parsePinGroup(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"corners", "rest_box", "vertices", "script"});
  const int selectors = int(r.has("corners")) + int(r.has("rest_box")) + int(r.has("vertices"));
  if (selectors != 1) {
    r.fail(pointer, "a pin group needs exactly one of \"corners\", \"rest_box\" and \"vertices\", found " +
                        std::to_string(selectors));
  }
  PinGroup pins;
  if (r.has("corners")) {
    const json& corners = r.array("corners");
    if (corners.empty()) r.fail(r.pointer("corners"), "must name at least one corner: " + joinNames(cornerNames()));
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const std::string at = childPointer(r.pointer("corners"), k);
      const std::string name = r.stringValue(corners[k], at);
      const auto& known = cornerNames();
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        r.fail(at, "unknown corner \"" + echo(name) + "\"; expected one of " + joinNames(known));
      }
      pins.corners.push_back(name);
    }
  }
  if (r.has("rest_box")) {
    const FieldReader box(r.at("rest_box"), r.pointer("rest_box"), ctx.file, {"min", "max"});
    const Vec2 lo = vec2Value(box, box.required("min", "the box's [x, y] minimum in material space (m)"), box.pointer("min"));
    const Vec2 hi = vec2Value(box, box.required("max", "the box's [x, y] maximum in material space (m)"), box.pointer("max"));
    if (lo.x() > hi.x() || lo.y() > hi.y()) {
      box.fail(box.pointer(), "min must not exceed max in x or y, got min [" + std::to_string(lo.x()) + ", " +
                                  std::to_string(lo.y()) + "], max [" + std::to_string(hi.x()) + ", " +
                                  std::to_string(hi.y()) + "]");
    }
    pins.restBox = std::make_pair(lo, hi);
  }
  if (r.has("vertices")) {
    const json& ids = r.array("vertices");
    if (ids.empty()) r.fail(r.pointer("vertices"), "must list at least one vertex id");
    for (std::size_t k = 0; k < ids.size(); ++k) {
      pins.vertices.push_back(r.integerValue(ids[k], childPointer(r.pointer("vertices"), k), 0));
    }
  }
  if (r.has("script")) pins.script = parseScript(r.at("script"), r.pointer("script"), ctx, r);
  return pins;
}

// Pins are checked against the mesh they will hold, so that a vertex id past the end or a box
// that misses the cloth is reported at load time instead of silently pinning nothing.
void checkPinsAgainstMesh(const ClothSpec& cloth, const ClothMesh& mesh, const ObjVertexMap& objVertices,
                          const std::string& pointer, const SceneReadContext& ctx) {
  for (std::size_t g = 0; g < cloth.pins.size(); ++g) {
    const PinGroup& pins = cloth.pins[g];
    const std::string at = childPointer(childPointer(pointer, "pins"), g);
    for (std::size_t k = 0; k < pins.vertices.size(); ++k) {
      if (cloth.obj) {  // ids name `v` lines (obj_import.h)
        const int id = pins.vertices[k];
        if (id >= objVertices.objVertexCount()) {
          throw InputError(ctx.file, childPointer(childPointer(at, "vertices"), k),
                           "vertex id " + std::to_string(id) + " is out of range; on an OBJ cloth ids count the "
                           "file's `v` lines from 0, and it has " + std::to_string(objVertices.objVertexCount()) +
                           " (ids 0.." + std::to_string(objVertices.objVertexCount() - 1) + ")");
        }
        if (objVertices.clothVertices[static_cast<std::size_t>(id)].empty()) {
          throw InputError(ctx.file, childPointer(childPointer(at, "vertices"), k),
                           "vertex id " + std::to_string(id) + " is the file's `v` line " + std::to_string(id + 1) +
                               ", which no face uses");
        }
        continue;
      }
      if (pins.vertices[k] >= mesh.vertexCount()) {
        throw InputError(ctx.file, childPointer(childPointer(at, "vertices"), k),
                         "vertex id " + std::to_string(pins.vertices[k]) + " is out of range; the mesh has " +
                             std::to_string(mesh.vertexCount()) + " vertices (ids 0.." +
                             std::to_string(mesh.vertexCount() - 1) + ")");
      }
    }
    if (pins.restBox) {
      // Named references, not a structured binding: clang before 16 cannot capture one in a lambda.
      const Vec2& lo = pins.restBox->first;
      const Vec2& hi = pins.restBox->second;
      const double slack = 1e-9;  // a box edge drawn exactly on a row of vertices still catches it
      // A vertex's rest coordinates are its triangles' corners; scanned in place (a list per vertex
      // cost a million small allocations on a 1024 x 1024 grid).
      const bool any = std::any_of(mesh.tris.begin(), mesh.tris.end(), [&](const auto& t) {
        return std::any_of(t.rest.begin(), t.rest.end(), [&](const Vec2& p) {
          return p.x() >= lo.x() - slack && p.x() <= hi.x() + slack && p.y() >= lo.y() - slack &&
                 p.y() <= hi.y() + slack;
        });
      });
      if (!any) {
        throw InputError(ctx.file, childPointer(at, "rest_box"),
                         "contains no vertex of the cloth; boxes are in material space (metres), e.g. a 1 m grid "
                         "spans [0, 1] x [0, 1]");
      }
    }
  }
}

// Builds the mesh once at load time: a missing UV set or a degenerate triangle in an OBJ file is
// a problem with this scene, so it is reported against the scene field that names the file.
ClothMesh buildMeshForChecks(const ClothSpec& cloth, const std::string& pointer, const SceneReadContext& ctx,
                             ObjVertexMap& outObjVertices) {
  if (cloth.grid) return makeGrid(*cloth.grid);
  try {
    return loadObjMesh(*cloth.obj, ctx.file, &outObjVertices);
  } catch (const InputError& e) {
    throw InputError(ctx.file, childPointer(childPointer(childPointer(pointer, "mesh"), "obj"), "path"), e.what());
  }
}

ClothAppearance parseAppearance(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"color", "pattern", "thread_pitch_mm", "threads_per_band"});
  ClothAppearance appearance;
  if (r.has("color")) {
    const auto rgb = r.numberRow<3>(r.at("color"), r.pointer("color"), "color (RGB in [0, 1])");
    for (double c : rgb) {
      if (c < 0.0 || c > 1.0) r.fail(r.pointer("color"), "color (RGB in [0, 1]) has a channel outside [0, 1], " + r.got(r.at("color")));
    }
    appearance.color = Vec3(rgb[0], rgb[1], rgb[2]);
  }
  if (r.has("pattern")) {
    const std::string name = r.stringValue(r.at("pattern"), r.pointer("pattern"));
    if (name == "gingham") {
      appearance.pattern = WeavePattern::Gingham;
    } else if (name == "plain") {
      appearance.pattern = WeavePattern::Plain;
    } else {
      r.fail(r.pointer("pattern"), "unknown pattern \"" + echo(name) + "\"; expected gingham or plain");
    }
  }
  appearance.threadPitch = 1e-3 * r.number("thread_pitch_mm", 1e3 * appearance.threadPitch, Bound::Positive, "thread pitch in mm");
  appearance.threadsPerBand = r.integer("threads_per_band", appearance.threadsPerBand, 1);
  return appearance;
}

ClothSpec parseCloth(const json& j, const std::string& pointer, std::size_t index, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file,
                      {"name", "mesh", "placement", "material", "tear_table", "tear_strength_map", "tear_region", "weft_angle_deg", "pins",
                       "appearance"});
  ClothSpec cloth;
  cloth.name = r.string("name", index == 0 ? std::string("cloth") : "cloth" + std::to_string(index));
  requireSafeName(r, "name", cloth.name);
  parseMesh(r.required("mesh", "{\"grid\": {...}} or {\"obj\": {\"path\": ...}}"), r.pointer("mesh"), ctx, cloth);
  if (r.has("placement")) cloth.placement = parsePlacement(r.at("placement"), r.pointer("placement"), ctx);
  parseMaterialField(r, ctx, cloth);
  parseTearTableField(r, ctx, cloth);
  parseTearStrengthMapField(r, ctx, cloth);
  parseTearRegionField(r, ctx, cloth);
  cloth.weftAngleDeg = r.number("weft_angle_deg", cloth.weftAngleDeg, Bound::Finite);
  if (r.has("pins")) {
    const json& groups = r.array("pins");
    for (std::size_t g = 0; g < groups.size(); ++g) {
      cloth.pins.push_back(parsePinGroup(groups[g], childPointer(r.pointer("pins"), g), ctx));
    }
  }
  if (r.has("appearance")) cloth.appearance = parseAppearance(r.at("appearance"), r.pointer("appearance"), ctx);
  // A grid is valid by construction: its mesh is built here only to check pins against it.
  if (cloth.grid && cloth.pins.empty()) return cloth;
  ObjVertexMap objVertices;
  const ClothMesh mesh = buildMeshForChecks(cloth, pointer, ctx, objVertices);
  checkPinsAgainstMesh(cloth, mesh, objVertices, pointer, ctx);
  return cloth;
}

ForcesSpec parseForces(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"gravity", "wind", "damping"});
  ForcesSpec forces;
  forces.gravity = boundedVec3(r, "gravity", forces.gravity, limits::kMaxGravity, "m/s^2");
  if (r.has("wind")) {
    const FieldReader w(r.at("wind"), r.pointer("wind"), ctx.file,
                        {"velocity", "air_density", "drag", "lift", "gust_amplitude", "gust_frequency"});
    WindSpec& wind = forces.wind;
    wind.velocity = boundedVec3(w, "velocity", wind.velocity, limits::kMaxWindSpeed, "m/s");
    wind.airDensity = w.number("air_density", wind.airDensity, Bound::NonNegative);
    wind.drag = w.number("drag", wind.drag, Bound::NonNegative);
    wind.lift = w.number("lift", wind.lift, Bound::NonNegative);
    wind.gustAmplitude = w.number("gust_amplitude", wind.gustAmplitude, Bound::UnitInterval);
    wind.gustFrequency = w.number("gust_frequency", wind.gustFrequency, Bound::NonNegative);
  }
  if (r.has("damping")) {
    const FieldReader d(r.at("damping"), r.pointer("damping"), ctx.file, {"mass", "stiffness"});
    forces.damping.mass = d.number("mass", forces.damping.mass, Bound::NonNegative);
    forces.damping.stiffness = d.number("stiffness", forces.damping.stiffness, Bound::NonNegative);
  }
  return forces;
}

IntegratorKind parseIntegrator(const FieldReader& r) {
  const std::string name = r.stringValue(r.at("integrator"), r.pointer("integrator"));
  if (name == "linearized_backward_euler") return IntegratorKind::LinearizedBackwardEuler;
  if (name == "newton") return IntegratorKind::Newton;
  if (name == "symplectic_euler") return IntegratorKind::SymplecticEuler;
  if (name == "bdf2") return IntegratorKind::Bdf2;
  if (name == "bdf2_newton") return IntegratorKind::Bdf2Newton;
  r.fail(r.pointer("integrator"), "unknown integrator \"" + echo(name) +
                                      "\"; expected linearized_backward_euler, newton, symplectic_euler, bdf2 or bdf2_newton");
}

PreconditionerKind parsePreconditioner(const FieldReader& r) {
  const std::string name = r.stringValue(r.at("preconditioner"), r.pointer("preconditioner"));
  if (name == "block_jacobi") return PreconditionerKind::BlockJacobi;
  if (name == "lagged_cholesky") return PreconditionerKind::LaggedCholesky;
  if (name == "lagged_exact_cholesky") return PreconditionerKind::LaggedExactCholesky;
  if (name == "amg") return PreconditionerKind::Amg;
  r.fail(r.pointer("preconditioner"), "unknown preconditioner \"" + echo(name) +
                                          "\"; expected lagged_cholesky, lagged_exact_cholesky, amg or block_jacobi");
}

SolverSpec parseSolver(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"dt", "substeps", "integrator", "newton", "linear_solver", "threads"});
  SolverSpec solver;
  solver.dt = r.number("dt", solver.dt, limits::kTimeStep, "time step");
  solver.substeps = r.integer("substeps", solver.substeps, 1, limits::kMaxSubsteps);
  if (r.has("integrator")) solver.integrator = parseIntegrator(r);
  if (r.has("newton")) {
    const FieldReader n(r.at("newton"), r.pointer("newton"), ctx.file, {"max_iterations", "tolerance"});
    solver.newtonMaxIterations = n.integer("max_iterations", solver.newtonMaxIterations, 1, limits::kMaxNewtonIterations);
    solver.newtonTolerance = n.number("tolerance", solver.newtonTolerance, Bound::NonNegative);
  }
  if (r.has("linear_solver")) {
    const FieldReader l(r.at("linear_solver"), r.pointer("linear_solver"), ctx.file,
                        {"type", "preconditioner", "tolerance", "max_iterations"});
    if (l.has("type")) {
      const std::string type = l.stringValue(l.at("type"), l.pointer("type"));
      if (type == "cg") solver.linearSolver = LinearSolverKind::ConjugateGradient;
      else if (type == "cholmod") solver.linearSolver = LinearSolverKind::Cholmod;
      else l.fail(l.pointer("type"), "unknown linear solver \"" + echo(type) + "\"; expected cg or cholmod");
    }
    if (l.has("preconditioner")) solver.linearPreconditioner = parsePreconditioner(l);
    solver.linearTolerance = l.number("tolerance", solver.linearTolerance, Bound::NonNegative);
    solver.linearMaxIterations = l.integer("max_iterations", solver.linearMaxIterations, 1, limits::kMaxLinearIterations);
  }
  solver.threads = r.integer("threads", solver.threads, 1, limits::kMaxThreads);
  return solver;
}

StageSwitches parseStages(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"bending", "wind", "gravity", "collision", "tearing"});
  StageSwitches stages;
  stages.tearing = r.boolean("tearing", stages.tearing);
  stages.collision = r.boolean("collision", stages.collision);
  stages.bending = r.boolean("bending", stages.bending);
  stages.wind = r.boolean("wind", stages.wind);
  stages.gravity = r.boolean("gravity", stages.gravity);
  return stages;
}

CameraSpec parseCamera(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"yaw_deg", "pitch_deg", "frame"});
  CameraSpec camera;
  camera.yawDeg = r.number("yaw_deg", camera.yawDeg, Bound::Finite);
  camera.pitchDeg = r.number("pitch_deg", camera.pitchDeg, Bound::Finite);
  if (camera.pitchDeg < -89.0 || camera.pitchDeg > 89.0) {
    r.fail(r.pointer("pitch_deg"), "must lie in [-89, 89] degrees (the camera cannot look straight up or down), " +
                                       r.got(r.at("pitch_deg")));
  }
  if (r.has("frame")) {
    const FieldReader f(r.at("frame"), r.pointer("frame"), ctx.file, {"min", "max"});
    const Vec3 lo = vec3Value(f, f.required("min", "the box's lowest corner [x, y, z] (m)"), f.pointer("min"));
    const Vec3 hi = vec3Value(f, f.required("max", "the box's highest corner [x, y, z] (m)"), f.pointer("max"));
    if ((hi - lo).minCoeff() < 0.0) f.fail(f.pointer("max"), "must be >= min in every coordinate");
    camera.frame = std::make_pair(lo, hi);
  }
  return camera;
}

OutputSpec parseOutput(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"frames", "fps", "camera"});
  OutputSpec output;
  output.frames = r.integer("frames", output.frames, 0, limits::kMaxFrames);
  output.fps = r.number("fps", output.fps, limits::kFramesPerSecond, "frame rate");
  if (r.has("camera")) output.camera = parseCamera(r.at("camera"), r.pointer("camera"), ctx);
  return output;
}

// ---------------------------------------------------------------------------------------------
// Overrides.

struct Override {
  std::string text;                 // as given, for messages
  std::vector<std::string> path;    // dotted path split into components
  std::string value;
};

Override splitOverride(const std::string& text, const std::string& file) {
  const std::size_t eq = text.find('=');
  const std::string usage = "an override must look like PATH=VALUE, e.g. solver.dt=0.005 or cloths.0.weft_angle_deg=30";
  if (eq == std::string::npos) throw InputError(file, "override \"" + echo(text) + "\"", "missing '='; " + usage);
  Override o{text, {}, text.substr(eq + 1)};
  std::stringstream path(text.substr(0, eq));
  std::string part;
  while (std::getline(path, part, '.')) o.path.push_back(part);
  const bool emptyPart = std::any_of(o.path.begin(), o.path.end(), [](const std::string& p) { return p.empty(); });
  if (o.path.empty() || emptyPart || text.substr(0, eq).back() == '.') {
    throw InputError(file, "override \"" + echo(text) + "\"", "empty path component; " + usage);
  }
  return o;
}

std::string overridePointer(const Override& o) {
  std::string pointer;
  for (const auto& part : o.path) pointer = childPointer(pointer, part);
  return pointer;
}

// A decimal index that fits a size_t; false for anything else, a number too large included
// (std::stoul threw std::out_of_range on "cloths.99999999999999999999.name=x": exit 1).
bool parseIndex(const std::string& text, std::size_t& index) {
  if (text.empty() || !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; })) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
  return error == std::errc() && end == text.data() + text.size();
}

// Appends to an InputError caused by an override the override that caused it: the scene file
// itself may be fine, and the user should look at their command line instead.
[[noreturn]] void rethrowNamingOverride(const InputError& e, const std::vector<Override>& overrides) {
  const std::string& message = e.message();
  for (auto it = overrides.rbegin(); it != overrides.rend(); ++it) {
    const std::string p = overridePointer(*it);
    const bool related = e.field() == p || e.field().rfind(p + "/", 0) == 0 || p.rfind(e.field() + "/", 0) == 0;
    if (related && !e.field().empty()) {
      throw InputError(e.file(), e.field(), message + " (from the override " + echo(it->text) + ")");
    }
  }
  throw e;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

SearchPaths defaultSearchPaths(const fs::path& sceneFile) {
  SearchPaths paths;
  const fs::path folder = sceneFile.parent_path().empty() ? fs::path(".") : sceneFile.parent_path();
  paths.materialDirs.push_back((folder / ".." / "materials").lexically_normal());
  paths.materialDirs.push_back(fs::path(WEFT_SOURCE_DIR) / "presets" / "materials");
  paths.tearTableDirs.push_back((folder / ".." / "tear_tables").lexically_normal());
  paths.tearTableDirs.push_back(fs::path(WEFT_SOURCE_DIR) / "presets" / "tear_tables");
  paths.assetDirs.push_back(folder);
  paths.assetDirs.push_back(fs::path(WEFT_SOURCE_DIR) / "assets");
  if (const char* data = std::getenv("WEFT_DATA_DIR"); data != nullptr && *data != '\0') {
    paths.materialDirs.push_back(fs::path(data) / "presets" / "materials");
    paths.tearTableDirs.push_back(fs::path(data) / "presets" / "tear_tables");
    paths.assetDirs.push_back(fs::path(data) / "assets");
  }
  // A scene inside presets/scenes finds the same folder twice: list each folder once.
  for (auto* dirs : {&paths.materialDirs, &paths.tearTableDirs, &paths.assetDirs}) {
    std::vector<fs::path> unique;
    for (const fs::path& dir : *dirs) {
      std::error_code error;
      const fs::path canonical = fs::weakly_canonical(dir, error);
      const fs::path key = error ? dir : canonical;
      if (std::find(unique.begin(), unique.end(), key) == unique.end()) unique.push_back(key);
    }
    *dirs = std::move(unique);
  }
  return paths;
}

void applyOverrides(json& scene, const std::vector<std::string>& overrides, const std::string& file) {
  for (const auto& text : overrides) {
    const Override o = splitOverride(text, file);
    const std::string field = "override \"" + echo(text) + "\"";
    // A shell passes any bytes; a scene holds text. Refused here, before the bytes reach a
    // message or a JSON dump (which would throw on them).
    if (!isValidUtf8(text)) throw InputError(file, field, "is not valid UTF-8 text");
    // JSON when it is JSON (read as strictly as a file), otherwise a plain string such as a preset name.
    json value = o.value;
    char* numberEnd = nullptr;
    const double number = std::strtod(o.value.c_str(), &numberEnd);
    const bool looksLikeANumber = !o.value.empty() && o.value.find_first_not_of("0123456789+-.eE") == std::string::npos;
    if (looksLikeANumber && numberEnd == o.value.c_str() + o.value.size() && !std::isfinite(number)) {
      throw InputError(file, field, "VALUE: the number " + echo(o.value) + " is too large for a double");
    }
    if (json::accept(o.value)) {
      try {
        value = parseJsonText(o.value, file);
      } catch (const InputError& e) {
        throw InputError(file, field, "VALUE: " + e.message() + (e.field().empty() ? "" : " (at " + e.field() + ")"));
      }
    }

    json* node = &scene;
    for (std::size_t k = 0; k < o.path.size(); ++k) {
      const std::string& part = o.path[k];
      const bool last = k + 1 == o.path.size();
      if (node->is_array()) {
        std::size_t index = 0;
        if (!parseIndex(part, index) || index >= node->size()) {
          throw InputError(file, field,
                           "\"" + echo(part) + "\" is not an index of the array there (it has " +
                               std::to_string(node->size()) + " elements, indices 0.." +
                               std::to_string(static_cast<long>(node->size()) - 1) + ")");
        }
        node = &(*node)[index];
      } else if (node->is_object() || node->is_null()) {
        // A missing object on the way is created: "solver.newton.tolerance" works on a scene with
        // no solver section. Unknown keys are rejected later by the strict parser.
        if (node->is_null()) *node = json::object();
        node = &(*node)[part];
        if (!last && node->is_null()) *node = json::object();
      } else {
        throw InputError(file, field,
                         "cannot set \"" + echo(part) + "\" inside a " + std::string(node->type_name()) +
                             " value; only objects and arrays have fields");
      }
      if (last) *node = value;
    }
  }
}

namespace {

Scene parseSceneReading(const json& j, const fs::path& file, const SearchPaths& paths, std::vector<fs::path>* filesRead) {
  const SceneReadContext ctx{file.string(), paths, filesRead};
  const FieldReader r(j, "", ctx.file, {"name",   "description", "cloths", "forces",   "solver",
                                              "stages", "output",      "ground", "obstacles", "contact", "tearing"});
  Scene scene;
  scene.file = file;
  scene.name = r.string("name", file.stem().string());
  requireSafeName(r, "name", scene.name);
  scene.description = r.string("description", "");
  r.required("cloths", "an array of at least one cloth");
  const json& cloths = r.array("cloths");
  if (cloths.empty()) r.fail(r.pointer("cloths"), "must contain at least one cloth");
  for (std::size_t i = 0; i < cloths.size(); ++i) {
    ClothSpec cloth = parseCloth(cloths[i], childPointer(r.pointer("cloths"), i), i, ctx);
    for (const auto& other : scene.cloths) {
      if (other.name == cloth.name) {
        throw InputError(ctx.file, childPointer(childPointer(r.pointer("cloths"), i), "name"),
                         "cloth names must be unique (they name output files); \"" + echo(cloth.name) + "\" is used twice");
      }
    }
    scene.cloths.push_back(std::move(cloth));
  }
  if (r.has("forces")) scene.forces = parseForces(r.at("forces"), r.pointer("forces"), ctx);
  if (r.has("solver")) scene.solver = parseSolver(r.at("solver"), r.pointer("solver"), ctx);
  if (r.has("stages")) scene.stages = parseStages(r.at("stages"), r.pointer("stages"), ctx);
  if (r.has("output")) scene.output = parseOutput(r.at("output"), r.pointer("output"), ctx);
  if (r.has("ground")) scene.ground = parseGround(r.at("ground"), r.pointer("ground"), ctx);
  if (r.has("obstacles")) scene.obstacles = parseObstacles(r.array("obstacles"), r.pointer("obstacles"), ctx);
  if (r.has("contact")) scene.contact = parseContact(r.at("contact"), r.pointer("contact"), ctx);
  if (r.has("tearing")) scene.tearing = parseTearing(r.at("tearing"), r.pointer("tearing"), ctx);
  // Each is in range, but together they may ask for millions of steps per frame.
  if (const double steps = 1.0 / (scene.output.fps * scene.solver.dt); steps > double(limits::kMaxStepsPerFrame)) {
    throw InputError(ctx.file, "/output/fps",
                     "with solver.dt = " + formatNumber(scene.solver.dt) + " s, " + formatNumber(scene.output.fps) +
                         " frames/s need " + formatNumber(steps) + " steps per frame; at most " +
                         std::to_string(limits::kMaxStepsPerFrame) + " (raise fps or dt)");
  }
  return scene;
}

}  // namespace

Scene parseScene(const json& j, const fs::path& file, const SearchPaths& paths) {
  return parseSceneReading(j, file, paths, nullptr);
}

std::vector<fs::path> sceneInputFiles(const fs::path& file) {
  const json j = readJsonFile(file, "the scene file", JsonTextOptions{.allowComments = true});
  std::vector<fs::path> files;
  (void)parseSceneReading(j, file, defaultSearchPaths(file), &files);
  return files;
}

Scene loadScene(const fs::path& file, const std::vector<std::string>& overrides) {
  json j = readJsonFile(file, "the scene file", JsonTextOptions{.allowComments = true});
  std::vector<Override> parsed;
  for (const auto& text : overrides) parsed.push_back(splitOverride(text, file.string()));
  applyOverrides(j, overrides, file.string());
  try {
    return parseScene(j, file, defaultSearchPaths(file));
  } catch (const InputError& e) {
    rethrowNamingOverride(e, parsed);
  }
}

}  // namespace weft
