#pragma once
// The values a scene file may hold, beyond their type: what makes physical sense for cloth, and
// what keeps a run's work and its counters bounded. Each is refused at load time with its range in
// the message ("must be a number in [1e-06, 1] s"), so a typo such as dt = 1e-12 or a thickness of
// 1e6 m is caught before it costs hours, exhausts memory or overflows a count. The scene tables of
// presets/scenes/README.md list the same ranges.
#include <cstdint>

#include "util/json_fields.h"

namespace weft::limits {

// Meshes. A cloth of a million vertices already takes minutes per frame; ids are ints.
inline constexpr int kMaxGridResolution = 4096;            // vertices along one side of a grid
inline constexpr std::int64_t kMaxClothVertices = 1 << 20;  // per cloth, grid or OBJ
inline constexpr Range kClothSize{0.0, 100.0, true, "m"};   // grid width and height
inline constexpr Range kUvScale{0.0, 1000.0, true, "m per UV unit"};  // an OBJ cloth's uv_scale

// Time. Below a microsecond a run of seconds needs millions of steps; above a second a step
// skips everything a cloth does.
inline constexpr Range kTimeStep{1e-6, 1.0, false, "s"};
inline constexpr int kMaxSubsteps = 1000;
inline constexpr std::int64_t kMaxStepsPerFrame = 1'000'000;  // round(1 / (fps dt))
inline constexpr int kMaxFrames = 1'000'000;
inline constexpr Range kFramesPerSecond{0.0, 10'000.0, true, "frames/s"};

// Solver effort.
inline constexpr int kMaxThreads = 256;  // the OpenMP runtime fails far above a machine's cores
inline constexpr int kMaxNewtonIterations = 1000;
inline constexpr int kMaxLinearIterations = 100'000;

// Forces and motion: far beyond anything cloth meets (100 g; wind and bodies past the speed of
// sound), far below what breaks the arithmetic.
inline constexpr double kMaxGravity = 1000.0;       // m/s^2, magnitude
inline constexpr double kMaxWindSpeed = 340.0;      // m/s, magnitude
inline constexpr double kMaxBodySpeed = 340.0;      // m/s, an obstacle's constant or initial velocity

// Contact. Thickness is a few millimetres in practice; every vertex within it of a surface is a
// candidate pair, so a thickness of metres makes the pair lists quadratic in the mesh.
inline constexpr Range kContactThickness{0.0, 0.1, true, "m"};
inline constexpr int kMaxContactIterations = 1000;  // ccd_iterations, impact_zone_iterations

// Obstacle shapes generated in code: below a millimetre a body is finer than any cloth it meets
// (and its triangles break the contact arithmetic); the mesh counts grow as resolution^2 and
// segments^2.
inline constexpr Range kShapeSize{1e-3, 100.0, false, "m"};  // radius, half length, half extents
inline constexpr Range kMeshScale{0.0, 1000.0, true, ""};
inline constexpr int kMaxBoxResolution = 256;
inline constexpr int kMaxShapeSegments = 1024;
// Triangles of one generated shape, its fields taken together (scene/shape_size.h): a cylinder's
// bands are as tall as a segment is wide, so a thin, long one in range field by field once asked
// for 67 billion. The finest capsule (1,024 segments) has 1,050,624.
inline constexpr std::int64_t kMaxShapeTriangles = 1 << 21;

}  // namespace weft::limits
