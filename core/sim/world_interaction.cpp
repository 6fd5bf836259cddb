// The editor's hands on a running World (world.h): a grab spring on a cloth vertex, balls thrown
// in, kinematic tools dragged by hand.
#include <cmath>
#include <stdexcept>

#include "sim/world_impl.h"

namespace weft {

void World::grab(int cloth, int vertex, const Vec3& target, double stiffness) {
  Impl& w = *impl_;
  if (cloth < 0 || cloth >= clothCount()) throw std::out_of_range("grab: no cloth " + std::to_string(cloth));
  if (vertex < 0 || vertex >= w.cloths[cloth].mesh.vertexCount())
    throw std::out_of_range("grab: cloth " + std::to_string(cloth) + " has no vertex " + std::to_string(vertex));
  if (!(stiffness >= 0.0) || !std::isfinite(stiffness))
    throw std::invalid_argument("grab: stiffness must be finite and >= 0 (N/m)");
  GrabState state;
  state.cloth = cloth;
  state.spring.vertex = vertex;
  state.spring.target = target;
  state.spring.stiffness = stiffness;
  w.grab = state;
}

void World::moveGrab(const Vec3& target) {
  if (impl_->grab) impl_->grab->spring.target = target;
}

void World::releaseGrab() { impl_->grab.reset(); }

std::optional<GrabState> World::grabState() const { return impl_->grab; }

int World::throwBall(const Vec3& position, const Vec3& velocity, double radius, double mass) {
  Impl& w = *impl_;
  if (!(radius > 0.0) || !(mass > 0.0)) throw std::invalid_argument("throwBall: radius and mass must be > 0");
  const int index = obstacleCount();
  ObstacleSpec ball;
  ball.name = "ball " + std::to_string(index);
  ball.shape.kind = ShapeKind::Sphere;
  ball.shape.radius = radius;
  ball.translate = position;
  ball.motion = ObstacleMotion::Dynamic;
  ball.velocity = velocity;
  ball.mass = mass;
  // Turn contact with obstacles on if it was off, and only it: what did not run before (the
  // ground, self-collision) stays off, as the scene copy then says.
  const bool obstaclesCollided = w.scene.stages.collision && w.scene.contact.obstacles;
  if (!obstaclesCollided) {
    w.scene.ground.enabled = false;
    if (!w.scene.stages.collision) w.scene.contact.self = false;
    w.scene.stages.collision = true;
    w.scene.contact.obstacles = true;
  }
  w.obstacles.push_back(buildObstacle(ball, w.scene.file.string(), index));
  w.scene.obstacles.push_back(ball);
  w.kinematicTargets.emplace_back();
  w.kinematicFrom.push_back(position);
  w.contact->reconfigure(w.scene);
  return index;
}

void World::setKinematicOverride(int obstacle, const Vec3& position) {
  Impl& w = *impl_;
  if (obstacle < 0 || obstacle >= obstacleCount())
    throw std::out_of_range("setKinematicOverride: no obstacle " + std::to_string(obstacle));
  if (w.obstacles[obstacle].motion != ObstacleMotion::Kinematic)
    throw std::invalid_argument("setKinematicOverride: obstacle '" + w.obstacles[obstacle].name + "' is not kinematic");
  w.kinematicTargets[obstacle] = position;
}

void World::clearKinematicOverride(int obstacle) {
  if (obstacle < 0 || obstacle >= obstacleCount())
    throw std::out_of_range("clearKinematicOverride: no obstacle " + std::to_string(obstacle));
  impl_->kinematicTargets[obstacle].reset();
}

}  // namespace weft
