#pragma once
// A scene: what to simulate and how. Plain structs with in-class defaults (units in the comment);
// scene/scene_json.cpp converts JSON to these and rejects unknown keys, wrong types and
// out-of-range values with an InputError naming the file and the JSON path of the field.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "material/material.h"
#include "scene/contact_spec.h"
#include "scene/tearing_spec.h"
#include "tearing/strength_map.h"
#include "tearing/tear_region.h"
#include "util/types.h"

namespace weft {

struct GridSpec {
  double width = 1.0;   // extent along material x (m)
  double height = 1.0;  // extent along material y (m)
  int resolutionX = 32; // vertices along x (>= 2)
  int resolutionY = 32; // vertices along y (>= 2)

  friend bool operator==(const GridSpec&, const GridSpec&) = default;
};

struct ObjSpec {
  std::filesystem::path path;  // resolved against the scene file's folder, then the project root
  double uvScale = 1.0;        // metres per UV unit: UVs times this become rest coordinates

  friend bool operator==(const ObjSpec&, const ObjSpec&) = default;
};

// Where a mesh is placed in the world: world = rotate(rest) + translate. A grid lies in its rest
// plane (material x -> world x, material y -> world y, z = 0) before this transform.
struct Placement {
  Vec3 translate = Vec3::Zero();  // m
  Vec3 rotateDeg = Vec3::Zero();  // rotation about world x, then y, then z (degrees)

  friend bool operator==(const Placement&, const Placement&) = default;
};

struct PinKeyframe {
  double time = 0.0;              // s
  Vec3 offset = Vec3::Zero();     // displacement from the pinned vertices' start positions (m)

  friend bool operator==(const PinKeyframe&, const PinKeyframe&) = default;
};

// A group of pinned vertices, chosen by corner names, by a box in material space, or by id.
struct PinGroup {
  std::vector<std::string> corners;  // any of "top_left", "top_right", "bottom_left", "bottom_right" (grid, material space: top = max y)
  std::optional<std::pair<Vec2, Vec2>> restBox;  // min and max corner in material space (m)
  std::vector<int> vertices;         // explicit vertex ids
  std::vector<PinKeyframe> script;   // empty: fixed; otherwise piecewise-linear offsets over time, held after the last key

  friend bool operator==(const PinGroup&, const PinGroup&) = default;
};

// How a cloth looks in the renderer; the simulation never reads it. The woven texture's threads
// follow the weft angle whatever the pattern.
enum class WeavePattern {
  Gingham,  // yarn-dyed check: bands of `threadsPerBand` coloured threads alternate with light ones
  Plain,    // every thread in the cloth's colour
};

struct ClothAppearance {
  std::optional<Vec3> color;     // RGB in [0, 1] of the dyed threads; unset: a palette colour by cloth index
  WeavePattern pattern = WeavePattern::Gingham;
  double threadPitch = 0.005;    // m between neighbouring threads
  int threadsPerBand = 8;        // gingham: threads per colour band

  friend bool operator==(const ClothAppearance&, const ClothAppearance&) = default;
};

struct ClothSpec {
  std::string name = "cloth";
  std::optional<GridSpec> grid;  // exactly one of grid and obj
  std::optional<ObjSpec> obj;
  Placement placement;
  std::string materialName;      // the preset's name, or "inline"
  Material material;             // resolved material (preset or inline)
  double weftAngleDeg = 0.0;     // weft direction U in material space, degrees from material x
  // A painted multiplier on the tear table's strength (tearing/strength_map.h), or none.
  std::optional<TearStrengthMap> tearStrengthMap;
  // A second tear table over part of the cloth (tearing/tear_region.h), or none.
  std::optional<TearRegion> tearRegion;
  std::vector<PinGroup> pins;
  ClothAppearance appearance;

  friend bool operator==(const ClothSpec&, const ClothSpec&) = default;
};

struct WindSpec {
  Vec3 velocity = Vec3::Zero();  // wind velocity (m/s); zero means no wind stage
  double airDensity = 1.2;       // kg/m^3
  double drag = 1.0;             // drag coefficient along the triangle normal
  double lift = 0.2;             // lift coefficient (acts perpendicular to the relative velocity)
  double gustAmplitude = 0.0;    // relative amplitude of a smooth deterministic gust, in [0, 1]
  double gustFrequency = 0.5;    // Hz

  friend bool operator==(const WindSpec&, const WindSpec&) = default;
};

struct DampingSpec {
  double mass = 0.0;       // mass-proportional damping coefficient (1/s): f = -mass * m v
  double stiffness = 0.0;  // stiffness-proportional (Rayleigh) damping coefficient (s): f = -stiffness * K v

  friend bool operator==(const DampingSpec&, const DampingSpec&) = default;
};

struct ForcesSpec {
  Vec3 gravity{0.0, -9.81, 0.0};  // m/s^2
  WindSpec wind;
  DampingSpec damping;

  friend bool operator==(const ForcesSpec&, const ForcesSpec&) = default;
};

// Bdf2 and Bdf2Newton: the second-order BDF2 step solved like LinearizedBackwardEuler (one
// linear solve) and like Newton (to a tolerance); integrate/bdf2.h.
enum class IntegratorKind { LinearizedBackwardEuler, Newton, SymplecticEuler, Bdf2, Bdf2Newton };
enum class LinearSolverKind { ConjugateGradient, Cholmod };
enum class PreconditionerKind { BlockJacobi, LaggedCholesky, LaggedExactCholesky, Amg };

struct SolverSpec {
  double dt = 1.0 / 60.0;         // time step (s)
  int substeps = 1;               // each step is split into this many equal substeps
  IntegratorKind integrator = IntegratorKind::LinearizedBackwardEuler;
  int newtonMaxIterations = 10;   // Newton and Bdf2Newton: iteration bound per (sub)step
  double newtonTolerance = 1e-6;  // Newton and Bdf2Newton: stop when the max velocity change of an iteration is below this (m/s)
  LinearSolverKind linearSolver = LinearSolverKind::ConjugateGradient;
  PreconditionerKind linearPreconditioner = PreconditionerKind::Amg;  // CG: see integrate/linear_solver.h
  double linearTolerance = 1e-6;  // CG: stop at |r| <= tolerance * max(|b|, |one step's external impulse| in b's units)
  int linearMaxIterations = 1000; // CG: iteration bound
  int threads = 1;                // worker threads: force assembly and the CG/multigrid row-wise products (results do not depend on it)

  friend bool operator==(const SolverSpec&, const SolverSpec&) = default;
};

// Stages a scene may switch off explicitly; a stage that has nothing to do is skipped anyway.
struct StageSwitches {
  bool bending = true;
  bool wind = true;
  bool gravity = true;
  bool collision = true;  // contact with obstacles, the ground and (if on) the cloth itself
  bool tearing = true;    // cloths whose material has a tear table tear

  friend bool operator==(const StageSwitches&, const StageSwitches&) = default;
};

// How images of the scene are taken (`weft run --png`, the editor's first view). The camera orbits
// the centre of the box it frames; unset fields fall back to the automatic framing.
struct CameraSpec {
  double yawDeg = 30.0;    // degrees about world +y; 0 looks along -z
  double pitchDeg = 20.0;  // degrees above the horizontal (positive looks down)
  std::optional<std::pair<Vec3, Vec3>> frame;  // world box (min, max, m) kept in view; unset: the action box

  friend bool operator==(const CameraSpec&, const CameraSpec&) = default;
};

struct OutputSpec {
  int frames = 120;     // frames to simulate in `weft run`
  double fps = 30.0;    // frames per simulated second; steps per frame = round(1/(fps*dt))
  CameraSpec camera;

  friend bool operator==(const OutputSpec&, const OutputSpec&) = default;
};

struct Scene {
  std::filesystem::path file;       // where it was loaded from (for messages and relative paths)
  std::string name;
  std::string description;
  std::vector<ClothSpec> cloths;
  ForcesSpec forces;
  SolverSpec solver;
  StageSwitches stages;
  OutputSpec output;
  GroundSpec ground;
  std::vector<ObstacleSpec> obstacles;
  ContactSpec contact;
  TearingSpec tearing;

  friend bool operator==(const Scene&, const Scene&) = default;
};

std::int64_t stepsPerFrame(const Scene& scene);

}  // namespace weft
