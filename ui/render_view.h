#pragma once
// What the renderer draws, gathered from a World (or built directly, as the tests do): the cloth
// meshes with their weft angle and tint, the obstacles at their current pose with their sharp
// tags, and the ground. Plain data, no GL.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "mesh/cloth_mesh.h"
#include "orbit_camera.h"
#include "scene/scene.h"
#include "util/types.h"

namespace weft {
class World;
}

namespace weft::ui {

struct ClothView {
  const ClothMesh* mesh = nullptr;      // not owned; must outlive the draw
  double weftAngleRad = 0.0;            // weft direction in material space, from material x
  std::array<float, 3> tint{0.80f, 0.30f, 0.25f};  // RGB of the dyed threads
  WeavePattern pattern = WeavePattern::Gingham;
  double threadPitch = 0.005;  // m: distance between neighbouring threads of the woven texture
  int threadsPerBand = 8;      // gingham: threads of one colour before the check changes colour
  bool woven = true;           // false: one flat colour (the tint), no threads: the user study's texture-hidden clips
  std::vector<Vec3> pinTravel; // m: every offset a pin script moves pinned vertices by (for framing)
  // The editor's tear strength brush: this painted map drawn over the cloth, weak red, strong
  // blue (none: not shown).
  std::shared_ptr<const TearStrengthMap> strengthTint;
};

struct ObstacleView {
  std::vector<Vec3> vertices;                  // world positions at the current time (m)
  std::vector<std::array<int, 3>> triangles;   // vertex ids
  std::vector<std::array<int, 2>> sharpEdges;  // vertex-id pairs tagged sharp (drawn red)
  std::vector<int> sharpVertices;              // vertex ids tagged sharp (drawn red)
  std::vector<std::array<int, 2>> highlightEdges;  // under the editor's cursor (drawn amber, on top)
  std::vector<int> highlightVertices;
};

struct RenderView {
  std::vector<ClothView> cloths;
  std::vector<ObstacleView> obstacles;
  std::optional<double> groundHeight;  // m; the ground plane y = height when the scene has one
  Vec3 gravity = Vec3(0, -9.81, 0);    // m/s^2, for the default framing
};

// The world at its current time. The cloth views point into the world's meshes.
RenderView renderViewOf(const World& world);

// The tint of the i-th cloth of a scene that chooses no colour (a fixed palette, cycled).
std::array<float, 3> clothTint(int index);

// The box the default camera frames: cloths and obstacles, each cloth grown along gravity to as
// far as it could hang below its highest point (a sheet pinned flat swings down by its own size)
// and carried along by its pin scripts, but not below the ground.
void actionBox(const RenderView& view, Vec3& outMin, Vec3& outMax);

// The scene's camera for an image of the given aspect: its yaw and pitch, framing its box or,
// when it sets none, the action box of `view` (normally the view at time 0).
OrbitCamera defaultCamera(const RenderView& view, const CameraSpec& spec, double aspect);

}  // namespace weft::ui
