#include "contact/obstacle.h"

#include <algorithm>

#include "rigid/closed_obj_import.h"
#include "rigid/mass_properties.h"
#include "rigid/shape_meshes.h"
#include "rigid/sharp_tags.h"
#include "scene/shape_size.h"
#include "util/input_error.h"

namespace weft {
namespace {

std::string obstaclePointer(int index) { return "/obstacles/" + std::to_string(index); }

TriangleMesh makeShapeMesh(const ShapeSpec& shape) {
  switch (shape.kind) {
    case ShapeKind::Sphere: return makeSphereMesh({shape.radius, shape.subdivisions});
    case ShapeKind::Box: {
      BoxShape box;
      box.halfExtents = shape.halfExtents;
      box.maxCellSize = 2.0 * shape.halfExtents.maxCoeff() / shape.resolution;
      return makeBoxMesh(box);
    }
    case ShapeKind::Capsule: return makeCapsuleMesh({shape.radius, shape.halfLength, shape.segments});
    case ShapeKind::Cylinder: {
      CylinderShape cylinder;
      cylinder.radius = shape.radius;
      cylinder.halfHeight = shape.halfLength;
      cylinder.segments = shape.segments;
      // Bands about as tall as the segments are wide, so the sides are not slivers (validation
      // bounded their number: scene/shape_size.h).
      cylinder.heightSegments = cylinderBands(shape);
      return makeCylinderMesh(cylinder);
    }
    case ShapeKind::Mesh: {
      TriangleMesh mesh = loadClosedObj(shape.meshPath);
      for (Vec3& p : mesh.vertices) p *= shape.scale;
      return mesh;
    }
  }
  return {};
}

KinematicScript makeScript(const ObstacleSpec& spec) {
  if (!spec.keyframes.empty()) {
    KeyframeMotion motion;
    for (const ObstacleKeyframe& key : spec.keyframes) motion.keys.push_back({key.time, key.translate, key.rotateDeg});
    return motion;
  }
  ConstantVelocityMotion motion;
  motion.translate = spec.translate;
  motion.rotateDeg = spec.rotateDeg;
  motion.linearVelocity = spec.velocity;
  motion.angularVelocityDeg = spec.angularVelocityDeg;
  return motion;
}

void placeVertices(const Obstacle& obstacle, const RigidPose& pose, std::vector<Vec3>& out) {
  out.resize(obstacle.bodyVertices.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = pose.toWorld(obstacle.bodyVertices[i]);
}

// Where a dynamic body's current velocities take it over the step.
RigidPose predictedEnd(const RigidBody& body, double h) {
  RigidBody moved = body;
  moved.advancePose(h);
  return moved.state.pose();
}


}  // namespace

void markSharpFeatures(const SharpTags& tags, Obstacle& obstacle) {
  obstacle.sharpVertex.assign(obstacle.bodyVertices.size(), 0);
  for (int v : tags.vertices) obstacle.sharpVertex[v] = 1;
  obstacle.sharpEdge.assign(obstacle.topology.edges.size(), 0);
  for (std::size_t e = 0; e < obstacle.topology.edges.size(); ++e) {
    const std::array<int, 2>& edge = obstacle.topology.edges[e];
    obstacle.sharpEdge[e] = std::binary_search(tags.edges.begin(), tags.edges.end(), edge) ? 1 : 0;
  }
}

namespace {

// The obstacle's mesh into `mesh`, and its sharp tags: from its tags file, or written in the scene
// (those errors name the scene file and the field themselves).
SharpTags shapeAndSharpTags(const ObstacleSpec& spec, const std::string& sceneFile, int index, TriangleMesh& mesh) {
  const std::string shapePointer = obstaclePointer(index) + "/shape";
  SharpTags tags;
  try {
    mesh = makeShapeMesh(spec.shape);
    if (!spec.shape.sharpTagsPath.empty()) tags = loadSharpTags(spec.shape.sharpTagsPath, mesh);
  } catch (const InputError& e) {
    throw InputError(sceneFile, shapePointer, e.what());
  }
  if (!spec.shape.sharpTagsInline.is_null()) {
    tags = readSharpTags(spec.shape.sharpTagsInline, sceneFile, shapePointer + "/mesh/sharp_tags", mesh);
  }
  return tags;
}

}  // namespace

SharpTags sharpTagsOfSpec(const ObstacleSpec& spec, const std::string& sceneFile, int index) {
  if (spec.shape.sharpTagsPath.empty() && spec.shape.sharpTagsInline.is_null()) return {};
  TriangleMesh mesh;
  return shapeAndSharpTags(spec, sceneFile, index, mesh);
}

SharpTags sharpTagsOf(const Obstacle& obstacle) {
  SharpTags tags;
  for (std::size_t v = 0; v < obstacle.sharpVertex.size(); ++v) {
    if (obstacle.sharpVertex[v]) tags.vertices.push_back(static_cast<int>(v));
  }
  for (std::size_t e = 0; e < obstacle.sharpEdge.size(); ++e) {
    if (obstacle.sharpEdge[e]) tags.edges.push_back(obstacle.topology.edges[e]);
  }
  std::sort(tags.edges.begin(), tags.edges.end());
  return tags;
}

Obstacle buildObstacle(const ObstacleSpec& spec, const std::string& sceneFile, int index) {
  Obstacle obstacle;
  obstacle.name = spec.name;
  obstacle.motion = spec.motion;
  obstacle.friction = spec.friction;
  TriangleMesh mesh;
  const SharpTags tags = shapeAndSharpTags(spec, sceneFile, index, mesh);

  RigidState state;
  state.position = spec.translate;
  state.orientation = rotationFromDegrees(spec.rotateDeg);
  state.linearVelocity = spec.velocity;
  state.angularVelocity = spec.angularVelocityDeg * (kPi / 180.0);
  if (spec.motion == ObstacleMotion::Dynamic) {
    try {
      // A dynamic body turns about its centre of mass: the body frame moves there, and so does
      // the placed position (the placement gave the mesh's own origin).
      const Vec3 oldCentre = recentreAtCentreOfMass(mesh, spec.name);
      state.position += state.orientation * oldCentre;
      const double volume = computeMassProperties(mesh, 1.0, spec.name).volume;
      obstacle.body = makeDynamicBody(computeMassProperties(mesh, spec.mass / volume, spec.name), state);
    } catch (const InputError& e) {
      throw InputError(sceneFile, obstaclePointer(index) + "/shape", e.what());
    }
  } else {
    if (spec.motion == ObstacleMotion::Static) state.linearVelocity = state.angularVelocity = Vec3::Zero();
    obstacle.body = makeKinematicBody(state);
    obstacle.script = makeScript(spec);
  }
  obstacle.bodyVertices = mesh.vertices;
  obstacle.topology = makeCollisionMesh(static_cast<int>(mesh.vertices.size()), mesh.triangles);
  markSharpFeatures(tags, obstacle);
  obstacle.start = obstacle.end = obstacle.body.state.pose();
  if (spec.motion == ObstacleMotion::Kinematic) obstacle.start = obstacle.end = poseAt(obstacle.script, 0.0);
  placeVertices(obstacle, obstacle.start, obstacle.x0);
  obstacle.x1 = obstacle.x0;
  return obstacle;
}

void beginObstacleStep(Obstacle& obstacle, double t, double h, const Vec3& gravity) {
  obstacle.stepDuration = h;
  switch (obstacle.motion) {
    case ObstacleMotion::Static:
      obstacle.start = obstacle.end = obstacle.body.state.pose();
      break;
    case ObstacleMotion::Kinematic:
      // From the script at both ends: no drift from summing steps.
      obstacle.start = poseAt(obstacle.script, t);
      obstacle.end = poseAt(obstacle.script, t + h);
      break;
    case ObstacleMotion::Dynamic:
      obstacle.start = obstacle.body.state.pose();
      obstacle.body.applyGravity(gravity, h);
      obstacle.end = predictedEnd(obstacle.body, h);
      break;
  }
  placeVertices(obstacle, obstacle.start, obstacle.x0);
  placeVertices(obstacle, obstacle.end, obstacle.x1);
}

void beginObstacleStepTo(Obstacle& obstacle, const RigidPose& end, double h) {
  obstacle.stepDuration = h;
  obstacle.start = obstacle.body.state.pose();
  obstacle.end = end;
  placeVertices(obstacle, obstacle.start, obstacle.x0);
  placeVertices(obstacle, obstacle.end, obstacle.x1);
}

void endObstacleStep(Obstacle& obstacle) {
  switch (obstacle.motion) {
    case ObstacleMotion::Static:
      break;
    case ObstacleMotion::Kinematic: {
      const PoseChange change{obstacle.start, obstacle.end, obstacle.stepDuration};
      obstacle.body.state.position = obstacle.end.position;
      obstacle.body.state.orientation = obstacle.end.orientation;
      obstacle.body.state.linearVelocity = change.linearVelocity();
      obstacle.body.state.angularVelocity = change.angularVelocity();
      break;
    }
    case ObstacleMotion::Dynamic:
      obstacle.body.advancePose(obstacle.stepDuration);
      break;
  }
  obstacle.start = obstacle.end = obstacle.body.state.pose();
  obstacle.x0 = obstacle.x1;
}

double obstacleInverseMass(const Obstacle& obstacle, const Vec3& point, const Vec3& n) {
  if (obstacle.motion != ObstacleMotion::Dynamic) return 0.0;
  return obstacle.body.effectiveInverseMass(n, point);
}

void applyObstacleImpulse(Obstacle& obstacle, const Vec3& impulse, const Vec3& point, double h) {
  if (obstacle.motion != ObstacleMotion::Dynamic) return;
  obstacle.body.applyImpulse(impulse, point);
  obstacle.end = predictedEnd(obstacle.body, h);
  placeVertices(obstacle, obstacle.end, obstacle.x1);
}

void setObstacleVelocity(Obstacle& obstacle, const Vec3& linearVelocity, const Vec3& angularVelocity, double h) {
  if (obstacle.motion != ObstacleMotion::Dynamic) return;
  obstacle.body.state.linearVelocity = linearVelocity;
  obstacle.body.state.angularVelocity = angularVelocity;
  obstacle.end = predictedEnd(obstacle.body, h);
  placeVertices(obstacle, obstacle.end, obstacle.x1);
}

Vec3 carriedByObstacle(const Obstacle& obstacle, const Vec3& pointAtStart) {
  return obstacle.end.toWorld(obstacle.start.toBody(pointAtStart));
}

bool isSharpVertex(const Obstacle& obstacle, int vertex) { return obstacle.sharpVertex[vertex] != 0; }
bool isSharpEdge(const Obstacle& obstacle, int collisionEdge) { return obstacle.sharpEdge[collisionEdge] != 0; }

}  // namespace weft
