#include "render_view.h"

#include <algorithm>
#include <cmath>

#include "contact/obstacle.h"
#include "sim/world.h"

namespace weft::ui {

std::array<float, 3> clothTint(int index) {
  static const std::array<std::array<float, 3>, 4> palette{{
      {0.78f, 0.26f, 0.22f},  // madder red
      {0.22f, 0.40f, 0.70f},  // indigo
      {0.85f, 0.66f, 0.22f},  // ochre
      {0.30f, 0.58f, 0.34f},  // green
  }};
  return palette[static_cast<std::size_t>(index) % palette.size()];
}

RenderView renderViewOf(const World& world) {
  RenderView view;
  const Scene& scene = world.scene();
  for (int i = 0; i < world.clothCount(); ++i) {
    ClothView cloth;
    const ClothSpec& spec = scene.cloths[static_cast<std::size_t>(i)];
    cloth.mesh = &world.cloth(i);
    cloth.weftAngleRad = spec.weftAngleDeg * 3.14159265358979323846 / 180.0;
    const ClothAppearance& look = spec.appearance;
    cloth.tint = look.color ? std::array<float, 3>{static_cast<float>(look.color->x()), static_cast<float>(look.color->y()),
                                                   static_cast<float>(look.color->z())}
                            : clothTint(i);
    cloth.pattern = look.pattern;
    cloth.threadPitch = look.threadPitch;
    cloth.threadsPerBand = look.threadsPerBand;
    for (const PinGroup& pins : spec.pins) {
      for (const PinKeyframe& key : pins.script) cloth.pinTravel.push_back(key.offset);
    }
    view.cloths.push_back(cloth);
  }
  for (int i = 0; i < world.obstacleCount(); ++i) {
    const Obstacle& obstacle = world.obstacle(i);
    ObstacleView o;
    o.vertices = world.obstacleVertices(i);
    o.triangles = obstacle.topology.triangles;
    for (std::size_t e = 0; e < obstacle.topology.edges.size(); ++e) {
      if (isSharpEdge(obstacle, static_cast<int>(e))) o.sharpEdges.push_back(obstacle.topology.edges[e]);
    }
    for (int v = 0; v < static_cast<int>(o.vertices.size()); ++v) {
      if (isSharpVertex(obstacle, v)) o.sharpVertices.push_back(v);
    }
    view.obstacles.push_back(std::move(o));
  }
  if (scene.ground.enabled) view.groundHeight = scene.ground.height;
  view.gravity = scene.stages.gravity ? scene.forces.gravity : Vec3::Zero();
  return view;
}

void actionBox(const RenderView& view, Vec3& outMin, Vec3& outMax) {
  Vec3 lo = Vec3::Constant(1e30), hi = Vec3::Constant(-1e30);
  const Vec3 down = view.gravity.norm() > 0.0 ? Vec3(view.gravity.normalized()) : Vec3::Zero();
  for (const ClothView& cloth : view.cloths) {
    if (cloth.mesh->x.empty()) continue;
    Vec3 clo = Vec3::Constant(1e30), chi = Vec3::Constant(-1e30);
    double deepest = -1e30, highest = 1e30;  // along gravity
    for (const Vec3& p : cloth.mesh->x) {
      clo = clo.cwiseMin(p);
      chi = chi.cwiseMax(p);
      deepest = std::max(deepest, p.dot(down));
      highest = std::min(highest, p.dot(down));
    }
    lo = lo.cwiseMin(clo);
    hi = hi.cwiseMax(chi);
    // Hanging from its highest point, a cloth reaches at most its own extent below it.
    const double extent = (chi - clo).maxCoeff();
    const double fall = std::max(0.0, extent - (deepest - highest));
    lo = lo.cwiseMin(clo + fall * down);
    hi = hi.cwiseMax(chi + fall * down);
    // Pins carry the cloth where their scripts go; the whole cloth follows, more or less.
    for (const Vec3& travel : cloth.pinTravel) {
      lo = lo.cwiseMin(clo + travel);
      hi = hi.cwiseMax(chi + travel);
    }
  }
  for (const ObstacleView& o : view.obstacles) {
    for (const Vec3& p : o.vertices) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  if (lo.x() > hi.x()) {  // nothing to frame
    lo = Vec3::Constant(-0.5);
    hi = Vec3::Constant(0.5);
  }
  if (view.groundHeight && lo.y() < *view.groundHeight) lo.y() = std::min(*view.groundHeight, hi.y());
  outMin = lo;
  outMax = hi;
}

}  // namespace weft::ui

namespace weft::ui {

OrbitCamera defaultCamera(const RenderView& view, const CameraSpec& spec, double aspect) {
  Vec3 lo, hi;
  if (spec.frame) {
    lo = spec.frame->first;
    hi = spec.frame->second;
  } else {
    actionBox(view, lo, hi);
  }
  return frameBox(lo, hi, aspect, spec.yawDeg, spec.pitchDeg);
}

}  // namespace weft::ui
