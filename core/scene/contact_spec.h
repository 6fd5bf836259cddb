#pragma once
// The contact part of a scene: the ground, obstacles and tools, and how contact is resolved.
// Plain structs with in-class defaults (units in the comment); scene/contact_json.cpp reads them.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/types.h"

namespace weft {

// The shape of an obstacle, in its body frame. Procedural shapes are centred at the origin;
// a mesh keeps the origin its file has (a tool's grip, say), scaled by `scale`.
enum class ShapeKind { Sphere, Box, Capsule, Cylinder, Mesh };
struct ShapeSpec {
  ShapeKind kind = ShapeKind::Sphere;
  double radius = 0.1;                  // sphere, capsule, cylinder (m)
  int subdivisions = 3;                 // sphere: icosphere subdivisions (3: 1280 triangles)
  Vec3 halfExtents{0.1, 0.1, 0.1};      // box (m)
  int resolution = 4;                   // box: quads per face side
  double halfLength = 0.2;              // capsule: half the cylinder's length along body y; cylinder: half height (m)
  int segments = 32;                    // capsule, cylinder: segments around body y
  std::filesystem::path meshPath;       // mesh: the OBJ file (resolved against the asset folders)
  std::filesystem::path sharpTagsPath;  // mesh: NAME.sharp.json beside the OBJ when it exists; empty: nothing sharp
  // mesh: the tags written in the scene itself ("sharp_tags": {...}, the sharp-tag file's form),
  // checked against the mesh when it is built; null: none (then sharpTagsPath, if any).
  nlohmann::json sharpTagsInline;
  double scale = 1.0;                   // mesh: metres per OBJ unit

  friend bool operator==(const ShapeSpec&, const ShapeSpec&) = default;
};

// A kinematic key: the pose of the body origin at a time (a scene with keys gives no placement).
struct ObstacleKeyframe {
  double time = 0.0;             // s
  Vec3 translate = Vec3::Zero(); // world position of the body origin (m)
  Vec3 rotateDeg = Vec3::Zero(); // about world x, then y, then z (degrees)

  friend bool operator==(const ObstacleKeyframe&, const ObstacleKeyframe&) = default;
};

enum class ObstacleMotion {
  Static,     // never moves
  Kinematic,  // follows keyframes, or a constant velocity and spin; not pushed by the cloth
  Dynamic,    // a rigid body moved by gravity and by the impulses it exchanges with the cloth
};

struct ObstacleSpec {
  std::string name = "obstacle";
  ShapeSpec shape;
  Vec3 translate = Vec3::Zero();        // placement of the body origin (m)
  Vec3 rotateDeg = Vec3::Zero();        // placement rotation about world x, then y, then z (degrees)
  ObstacleMotion motion = ObstacleMotion::Static;
  std::vector<ObstacleKeyframe> keyframes;   // kinematic: piecewise-linear path, held after the last key
  Vec3 velocity = Vec3::Zero();              // kinematic without keys: constant; dynamic: initial (m/s)
  Vec3 angularVelocityDeg = Vec3::Zero();    // likewise, about world axes through the body origin (deg/s)
  double mass = 1.0;                         // dynamic: total mass (kg), uniform density
  double friction = 0.3;                     // Coulomb coefficient against cloth

  friend bool operator==(const ObstacleSpec&, const ObstacleSpec&) = default;
};

// An infinite plane y = height that cloth vertices stay above.
struct GroundSpec {
  bool enabled = false;
  double height = 0.0;    // m
  double friction = 0.5;  // Coulomb coefficient against cloth

  friend bool operator==(const GroundSpec&, const GroundSpec&) = default;
};

struct ContactSpec {
  bool obstacles = true;           // cloth against obstacles and the ground
  bool self = false;               // cloth against itself
  double thickness = 0.004;        // cloth contact thickness (m): proximity pass distance
  double selfFriction = 0.2;       // Coulomb coefficient of cloth against cloth
  int ccdIterations = 8;           // pass 2: bound on iterated CCD impulses before impact zones
  int impactZoneIterations = 50;   // pass 3: bound on impact-zone merging rounds
  // Keep the near pairs from step to step in a skin list (contact/pair_cache.h) instead of
  // searching every time. Exact either way (the same pairs meet the same tests); off only to
  // measure what it saves or to rule it out.
  bool reusePairs = true;
  // Pass 2 tests, after its first iteration, only the pairs near what the last iteration moved or
  // found crossing. Exact either way (the others cannot cross); on tests every pair each time, only
  // to rule the shortcut out.
  bool recheckAllPairs = false;

  friend bool operator==(const ContactSpec&, const ContactSpec&) = default;
};

}  // namespace weft
