#include "scene/contact_json.h"

#include "scene/scene_limits.h"
#include "scene/shape_size.h"
#include "util/echo.h"

#include <filesystem>

namespace weft {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

const char* kShapeExample = "{\"sphere\": {\"radius\": 0.1}}, {\"box\": {\"half_extents\": [x, y, z]}}, "
                            "{\"capsule\": {...}}, {\"cylinder\": {...}} or {\"mesh\": {\"path\": \"tools/sword.obj\"}}";

ShapeSpec parseShape(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader outer(j, pointer, ctx.file, {"sphere", "box", "capsule", "cylinder", "mesh"});
  if (j.size() != 1) outer.fail(pointer, std::string("needs exactly one shape, e.g. ") + kShapeExample);
  const std::string kind = j.begin().key();
  const FieldReader r(j.begin().value(), outer.pointer(kind), ctx.file);
  ShapeSpec shape;
  if (kind == "sphere") {
    r.allowOnly({"radius", "subdivisions"});
    shape.kind = ShapeKind::Sphere;
    shape.radius = r.numberValue(r.required("radius", "the sphere's radius (m)"), r.pointer("radius"),
                                 limits::kShapeSize, "the sphere's radius");
    shape.subdivisions = r.integer("subdivisions", shape.subdivisions, 0);
    if (shape.subdivisions > 6) r.fail(r.pointer("subdivisions"), "must be at most 6 (81,920 triangles)");
  } else if (kind == "box") {
    r.allowOnly({"half_extents", "resolution"});
    shape.kind = ShapeKind::Box;
    shape.halfExtents = vec3Value(r, r.required("half_extents", "[x, y, z] half extents (m)"), r.pointer("half_extents"));
    for (int k = 0; k < 3; ++k) {
      (void)r.numberValue(r.at("half_extents")[static_cast<std::size_t>(k)], childPointer(r.pointer("half_extents"), std::size_t(k)),
                          limits::kShapeSize, "a half extent");
    }
    shape.resolution = r.integer("resolution", shape.resolution, 1, limits::kMaxBoxResolution);
  } else if (kind == "capsule" || kind == "cylinder") {
    r.allowOnly({"radius", "half_length", "segments"});
    shape.kind = kind == "capsule" ? ShapeKind::Capsule : ShapeKind::Cylinder;
    shape.radius = r.numberValue(r.required("radius", "the radius (m)"), r.pointer("radius"), limits::kShapeSize, "the radius");
    shape.halfLength = r.numberValue(r.required("half_length", "half the length along body y (m)"),
                                     r.pointer("half_length"), limits::kShapeSize, "half the length");
    shape.segments = r.integer("segments", shape.segments, 3, limits::kMaxShapeSegments);
    if (const std::int64_t triangles = shapeTriangleCount(shape); triangles > limits::kMaxShapeTriangles) {
      const std::string bands =
          shape.kind == ShapeKind::Cylinder
              ? " (" + std::to_string(cylinderBands(shape)) + " bands along its length, each as tall as a segment is wide)"
              : "";
      r.fail(outer.pointer(kind), "radius " + formatNumber(shape.radius) + " m, half length " +
                                      formatNumber(shape.halfLength) + " m and " + std::to_string(shape.segments) +
                                      " segments make " + std::to_string(triangles) + " triangles" + bands +
                                      "; at most " + std::to_string(limits::kMaxShapeTriangles) +
                                      " (fewer segments, a larger radius or a shorter shape)");
    }
  } else {
    r.allowOnly({"path", "scale", "sharp_tags"});
    shape.kind = ShapeKind::Mesh;
    const std::string relative = r.stringValue(r.required("path", "the OBJ file's path (a string)"), r.pointer("path"));
    shape.meshPath = resolveAsset(relative, r, "path", ctx);
    shape.scale = r.number("scale", shape.scale, limits::kMeshScale, "scale");
    if (r.has("sharp_tags") && r.at("sharp_tags").is_object()) {
      // Inline: the keys are checked now, the ids against the mesh when it is built.
      const FieldReader tags(r.at("sharp_tags"), r.pointer("sharp_tags"), ctx.file, {"sharp_vertices", "sharp_edges"});
      if (tags.has("sharp_vertices")) (void)tags.array("sharp_vertices");
      if (tags.has("sharp_edges")) (void)tags.array("sharp_edges");
      shape.sharpTagsInline = r.at("sharp_tags");
    } else if (r.has("sharp_tags")) {
      if (!r.at("sharp_tags").is_string()) {
        r.fail(r.pointer("sharp_tags"), "must be a sharp-tag file's path or the tags themselves "
                                        "{\"sharp_edges\": [[a, b], ...], \"sharp_vertices\": [...]}, " +
                                            r.got(r.at("sharp_tags")));
      }
      const std::string tags = r.stringValue(r.at("sharp_tags"), r.pointer("sharp_tags"));
      shape.sharpTagsPath = resolveAsset(tags, r, "sharp_tags", ctx);
    } else {
      // Tools keep their tags beside their mesh: sword.obj -> sword.sharp.json.
      fs::path beside = shape.meshPath;
      beside.replace_extension(".sharp.json");
      std::error_code error;  // a name too long for the file system has no tags beside it
      if (fs::is_regular_file(beside, error)) {
        shape.sharpTagsPath = beside;
        ctx.read(beside);
      }
    }
  }
  return shape;
}

std::vector<ObstacleKeyframe> parseKeyframes(const FieldReader& parent, const SceneReadContext& ctx) {
  const json& keys = parent.array("keyframes");
  if (keys.empty()) parent.fail(parent.pointer("keyframes"), "must contain at least one key");
  std::vector<ObstacleKeyframe> out;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const FieldReader r(keys[k], childPointer(parent.pointer("keyframes"), k), ctx.file, {"t", "translate", "rotate_deg"});
    ObstacleKeyframe key;
    key.time = r.numberValue(r.required("t", "the key's time in seconds"), r.pointer("t"), Bound::NonNegative);
    key.translate = vec3Value(r, r.required("translate", "the body origin's position [x, y, z] (m)"), r.pointer("translate"));
    key.rotateDeg = vec3(r, "rotate_deg", key.rotateDeg);
    if (!out.empty() && key.time <= out.back().time) {
      r.fail(r.pointer("t"), "keys must be in increasing time order; this key's time " + std::to_string(key.time) +
                                 " does not come after the previous key's " + std::to_string(out.back().time));
    }
    out.push_back(key);
  }
  return out;
}

void parseMotion(const json& j, const std::string& pointer, const SceneReadContext& ctx, ObstacleSpec& obstacle) {
  const char* usage = "must be \"static\", {\"kinematic\": {...}} or {\"dynamic\": {\"mass\": kg}}";
  if (j.is_string()) {
    if (j.get<std::string>() != "static") throw InputError(ctx.file, pointer, std::string(usage) + ", " + got(j));
    obstacle.motion = ObstacleMotion::Static;
    return;
  }
  const FieldReader outer(j, pointer, ctx.file, {"kinematic", "dynamic"});
  if (j.size() != 1) outer.fail(pointer, usage);
  const std::string kind = j.begin().key();
  const FieldReader r(j.begin().value(), outer.pointer(kind), ctx.file);
  if (kind == "kinematic") {
    r.allowOnly({"keyframes", "velocity", "angular_velocity_deg"});
    obstacle.motion = ObstacleMotion::Kinematic;
    if (r.has("keyframes") && (r.has("velocity") || r.has("angular_velocity_deg"))) {
      r.fail(r.pointer(), "give either \"keyframes\" or a constant \"velocity\"/\"angular_velocity_deg\", not both");
    }
    if (r.has("keyframes")) obstacle.keyframes = parseKeyframes(r, ctx);
  } else {
    r.allowOnly({"mass", "velocity", "angular_velocity_deg"});
    obstacle.motion = ObstacleMotion::Dynamic;
    obstacle.mass = r.requiredNumber("mass", Bound::Positive, "the body's mass (kg)");
  }
  obstacle.velocity = boundedVec3(r, "velocity", obstacle.velocity, limits::kMaxBodySpeed, "m/s");
  obstacle.angularVelocityDeg = vec3(r, "angular_velocity_deg", obstacle.angularVelocityDeg);
}

ObstacleSpec parseObstacle(const json& j, const std::string& pointer, std::size_t index, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"name", "shape", "placement", "motion", "friction"});
  ObstacleSpec obstacle;
  obstacle.name = r.string("name", "obstacle" + std::to_string(index));
  requireSafeName(r, "name", obstacle.name);
  obstacle.shape = parseShape(r.required("shape", kShapeExample), r.pointer("shape"), ctx);
  if (r.has("placement")) {
    const FieldReader p(r.at("placement"), r.pointer("placement"), ctx.file, {"translate", "rotate_deg"});
    obstacle.translate = vec3(p, "translate", obstacle.translate);
    obstacle.rotateDeg = vec3(p, "rotate_deg", obstacle.rotateDeg);
  }
  if (r.has("motion")) parseMotion(r.at("motion"), r.pointer("motion"), ctx, obstacle);
  if (!obstacle.keyframes.empty() && r.has("placement")) {
    r.fail(r.pointer("placement"), "an obstacle moved by keyframes takes its pose from them; remove \"placement\"");
  }
  if (!obstacle.keyframes.empty()) {
    obstacle.translate = obstacle.keyframes.front().translate;
    obstacle.rotateDeg = obstacle.keyframes.front().rotateDeg;
  }
  obstacle.friction = r.number("friction", obstacle.friction, Bound::NonNegative);
  return obstacle;
}

}  // namespace

GroundSpec parseGround(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file, {"height", "friction"});
  GroundSpec ground;
  ground.enabled = true;
  ground.height = r.number("height", ground.height, Bound::Finite);
  ground.friction = r.number("friction", ground.friction, Bound::NonNegative);
  return ground;
}

std::vector<ObstacleSpec> parseObstacles(const json& array, const std::string& pointer, const SceneReadContext& ctx) {
  std::vector<ObstacleSpec> obstacles;
  for (std::size_t i = 0; i < array.size(); ++i) {
    ObstacleSpec obstacle = parseObstacle(array[i], childPointer(pointer, i), i, ctx);
    for (const auto& other : obstacles) {
      if (other.name == obstacle.name) {
        throw InputError(ctx.file, childPointer(childPointer(pointer, i), "name"),
                         "obstacle names must be unique; \"" + echo(obstacle.name) + "\" is used twice");
      }
    }
    obstacles.push_back(std::move(obstacle));
  }
  return obstacles;
}

ContactSpec parseContact(const json& j, const std::string& pointer, const SceneReadContext& ctx) {
  const FieldReader r(j, pointer, ctx.file,
                      {"obstacles", "self", "thickness", "self_friction", "ccd_iterations", "impact_zone_iterations",
                       "reuse_pairs", "recheck_all_pairs"});
  ContactSpec contact;
  contact.obstacles = r.boolean("obstacles", contact.obstacles);
  contact.self = r.boolean("self", contact.self);
  contact.thickness = r.number("thickness", contact.thickness, limits::kContactThickness, "contact thickness");
  contact.selfFriction = r.number("self_friction", contact.selfFriction, Bound::NonNegative);
  contact.ccdIterations = r.integer("ccd_iterations", contact.ccdIterations, 1, limits::kMaxContactIterations);
  contact.impactZoneIterations =
      r.integer("impact_zone_iterations", contact.impactZoneIterations, 1, limits::kMaxContactIterations);
  contact.reusePairs = r.boolean("reuse_pairs", contact.reusePairs);
  contact.recheckAllPairs = r.boolean("recheck_all_pairs", contact.recheckAllPairs);
  return contact;
}

}  // namespace weft
