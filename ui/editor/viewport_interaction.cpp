#include "viewport_interaction.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

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
  const bool pressed = mouse.left && !wasDown_;
  const bool released = !mouse.left && wasDown_;
  wasDown_ = mouse.left;

  // In tag mode, what a click would toggle, found (and shown) before the click.
  // Picking reads the world: while a step runs, the last frame's pick stays shown (hovering must
  // not wait for the step), and a press waits for the step so the click toggles what is under it.
  // A cached frame of the timeline is for looking: the mouse orbits; grabbing and tagging work on
  // the live world (an edit, Play or the end of the timeline goes back to it).
  if (session.shownFrame()) {
    hovered_.reset();
    if (mode_ == Mode::Paint) session.strengthPainting(paintCloth_).endStroke();
    mode_ = Mode::Idle;
    return false;
  }
  const bool hovering = tags != nullptr && mode_ != Mode::Grab && mode_ != Mode::DragTool && mode_ != Mode::Box;
  if (!hovering) {
    hovered_.reset();
  } else if (pressed || !session.stepping()) {
    TagPickSettings pick;
    pick.edgePixels = settings_.tagTolerancePixels;
    hovered_ = pickTagTarget(session.worldBetweenSteps(), tags->obstacle(), camera, mouse.x, mouse.y, width, height,
                             pick);
  }

  // The brush's outline under the cursor. As with the tags' hover, a running step is not waited
  // for: the outline follows the cursor at the size the last pick found.
  if (paintBrush_ == nullptr || tags != nullptr || (mode_ != Mode::Idle && mode_ != Mode::Paint)) {
    brushOutline_.reset();
  } else if (const auto hit = session.stepping() ? std::nullopt : pickCloth(session.worldBetweenSteps(), origin, dir)) {
    brushOutline_ = BrushOutline{mouse.x, mouse.y, paintBrush_->radius * ui::pixelsPerMetreAt(camera, hit->point, height)};
  } else if (brushOutline_ && (session.stepping() || mode_ == Mode::Paint)) {
    brushOutline_->x = mouse.x;  // a stroke that slips off the cloth keeps its outline's size
    brushOutline_->y = mouse.y;
  } else {
    brushOutline_.reset();
  }

  if (pressed) {
    // A press picks on the world itself: it waits for the step in flight (not for every owed
    // step), so the click lands on what was drawn, and is never lost.
    const World& world = session.worldBetweenSteps();
    mode_ = Mode::Orbit;  // unless the press lands on something below
    if (paintBrush_ != nullptr) {
      if (auto hit = pickCloth(world, origin, dir)) {
        mode_ = Mode::Paint;
        paintCloth_ = hit->cloth;
        lastDab_ = materialPointOfHit(world, *hit);
        StrengthPainting& painting = session.strengthPainting(paintCloth_);
        painting.beginStroke();
        painting.dab(lastDab_, *paintBrush_);
        return true;
      }
    }
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
      session.applyToWorld([hit = *hit, stiffness = settings_.grabStiffness](World& w) {
        w.grab(hit.cloth, hit.vertex, hit.point, stiffness);
      });
      return true;
    }
  }

  if (released && mode_ == Mode::Box) {
    mode_ = Mode::Idle;
    if (tags != nullptr && std::abs(box_.x1 - box_.x0) > 2 && std::abs(box_.y1 - box_.y0) > 2) {
      const auto edges = edgesInBox(session.worldBetweenSteps(), tags->obstacle(), camera, box_.x0, box_.y0, box_.x1, box_.y1, width, height);
      if (tags->tagEdges(session, edges, "tag the edges in a box") == 0) session.status = "no untagged edge in the box";
    }
    return true;
  }
  if (mode_ == Mode::Box) {
    box_.x1 = mouse.x;
    box_.y1 = mouse.y;
    return true;
  }

  if (mode_ == Mode::Paint) {
    if (released || paintBrush_ == nullptr) {
      mode_ = Mode::Idle;
      session.strengthPainting(paintCloth_).endStroke();
      session.strengthPaintingChanged(paintCloth_);  // the running world tears by the new map
      session.status = "painted the tear strength of " + session.scene().cloths[static_cast<std::size_t>(paintCloth_)].name +
                       " (Ctrl+Z takes the stroke back)";
      return true;
    }
    const World& world = session.worldBetweenSteps();
    if (auto hit = pickCloth(world, origin, dir); hit && hit->cloth == paintCloth_) paintTo(session, materialPointOfHit(world, *hit));
    return true;
  }

  if (released) {
    if (mode_ == Mode::Grab) session.applyToWorld([](World& world) { world.releaseGrab(); });
    const bool taken = mode_ == Mode::Grab || mode_ == Mode::DragTool;
    mode_ = Mode::Idle;
    return taken;
  }

  if (mode_ == Mode::Grab) {
    const Vec3 target = onDragPlane(camera, anchor_, origin, dir);
    session.applyToWorld(WorldChange{[target](World& world) { world.moveGrab(target); }, "grab target", 0});
    return true;
  }
  if (mode_ == Mode::DragTool) {
    const Vec3 position = onDragPlane(camera, anchor_, origin, dir) + toolOffset_;
    session.applyToWorld(WorldChange{[tool = tool_, position](World& world) { world.setKinematicOverride(tool, position); },
                                     "tool " + std::to_string(tool_) + " position", 0});
    return true;
  }
  return false;
}

void ViewportInteraction::paintTo(EditorSession& session, const Vec2& to) {
  StrengthPainting& painting = session.strengthPainting(paintCloth_);
  const double spacing = std::max(0.25 * paintBrush_->radius, 1e-4);
  const Vec2 step = to - lastDab_;
  const int dabs = std::min(static_cast<int>(std::ceil(step.norm() / spacing)), 1000);
  for (int k = 1; k <= dabs; ++k) painting.dab(lastDab_ + (static_cast<double>(k) / dabs) * step, *paintBrush_);
  lastDab_ = to;
}

void ViewportInteraction::throwBall(EditorSession& session, const ui::OrbitCamera& camera, double x, double y, int width,
                                    int height) const {
  Vec3 origin, dir;
  ui::cameraRay(camera, x, y, width, height, origin, dir);
  // From a little in front of the eye, so the ball starts in view.
  const Vec3 from = origin + 0.1 * camera.distance * dir;
  const Vec3 velocity = settings_.ballSpeed * dir;
  session.applyToWorld([from, velocity, radius = settings_.ballRadius, mass = settings_.ballMass](World& world) {
    world.throwBall(from, velocity, radius, mass);
  });
  session.status = "threw a ball (a reset removes it)";
}

}  // namespace weft::editor
