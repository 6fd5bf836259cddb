#include "viewport_interaction.h"

#include <cmath>

#include "contact/obstacle.h"
#include "sim/pick.h"

namespace weft::editor {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

Vec3 ViewportInteraction::onDragPlane(const ui::OrbitCamera& camera, const Vec3& anchor, const Vec3& origin,
                                      const Vec3& dir) {
  const Vec3 normal = (camera.eye() - camera.target).normalized();
  const double along = dir.dot(normal);
  if (std::abs(along) < 1e-9) return anchor;  // the ray runs in the plane: stay put
  const double s = (anchor - origin).dot(normal) / along;
  return origin + std::max(s, 0.0) * dir;
}

bool ViewportInteraction::update(EditorSession& session, const ui::OrbitCamera& camera, const ui::MouseState& mouse,
                                 ViewportKeys keys, int width, int height, ToolTagEditor* tags) {
  Vec3 origin, dir;
  ui::cameraRay(camera, mouse.x, mouse.y, width, height, origin, dir);
  World& world = session.world();
  const bool pressed = mouse.left && !wasDown_;
  const bool released = !mouse.left && wasDown_;
  wasDown_ = mouse.left;

  // In tag mode, what a click would toggle, found (and shown) before the click.
  hovered_.reset();
  if (tags != nullptr && mode_ != Mode::Grab && mode_ != Mode::DragTool && mode_ != Mode::Box) {
    TagPickSettings pick;
    pick.edgePixels = settings_.tagTolerancePixels;
    hovered_ = pickTagTarget(world, tags->obstacle(), camera, mouse.x, mouse.y, width, height, pick);
  }

  if (pressed) {
    mode_ = Mode::Orbit;  // unless the press lands on something below
    if (tags != nullptr && keys.shift) {
      mode_ = Mode::Box;
      box_ = DragBox{mouse.x, mouse.y, mouse.x, mouse.y};
      hovered_.reset();
      return true;
    }
    if (hovered_) {
      if (hovered_->isVertex()) {
        tags->toggleVertex(session, hovered_->vertex);
      } else {
        tags->toggleEdge(session, hovered_->edge);
      }
      mode_ = Mode::Idle;
      return true;
    }
    if (keys.alt) {
      if (auto hit = pickObstacleFeature(world, origin, dir, 0.0)) {
        const Obstacle& o = world.obstacle(hit->obstacle);
        if (o.motion == ObstacleMotion::Kinematic) {
          mode_ = Mode::DragTool;
          tool_ = hit->obstacle;
          anchor_ = hit->point;
          toolOffset_ = o.body.state.position - hit->point;
          return true;
        }
      }
    }
    if (auto hit = pickCloth(world, origin, dir)) {
      mode_ = Mode::Grab;
      anchor_ = hit->point;
      world.grab(hit->cloth, hit->vertex, hit->point, settings_.grabStiffness);
      return true;
    }
  }

  if (released && mode_ == Mode::Box) {
    mode_ = Mode::Idle;
    if (tags != nullptr && std::abs(box_.x1 - box_.x0) > 2 && std::abs(box_.y1 - box_.y0) > 2) {
      const auto edges = edgesInBox(world, tags->obstacle(), camera, box_.x0, box_.y0, box_.x1, box_.y1, width, height);
      if (tags->tagEdges(session, edges, "tag the edges in a box") == 0) session.status = "no untagged edge in the box";
    }
    return true;
  }
  if (mode_ == Mode::Box) {
    box_.x1 = mouse.x;
    box_.y1 = mouse.y;
    return true;
  }

  if (released) {
    if (mode_ == Mode::Grab) world.releaseGrab();
    const bool taken = mode_ == Mode::Grab || mode_ == Mode::DragTool;
    mode_ = Mode::Idle;
    return taken;
  }

  if (mode_ == Mode::Grab) {
    world.moveGrab(onDragPlane(camera, anchor_, origin, dir));
    return true;
  }
  if (mode_ == Mode::DragTool) {
    world.setKinematicOverride(tool_, onDragPlane(camera, anchor_, origin, dir) + toolOffset_);
    return true;
  }
  return false;
}

void ViewportInteraction::throwBall(EditorSession& session, const ui::OrbitCamera& camera, double x, double y, int width,
                                    int height) const {
  Vec3 origin, dir;
  ui::cameraRay(camera, x, y, width, height, origin, dir);
  // From a little in front of the eye, so the ball starts in view.
  session.world().throwBall(origin + 0.1 * camera.distance * dir, settings_.ballSpeed * dir, settings_.ballRadius,
                            settings_.ballMass);
  session.status = "threw a ball (a reset removes it)";
}

}  // namespace weft::editor
