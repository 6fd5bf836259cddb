#include "editor/tag_picking.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "contact/obstacle.h"
#include "sim/pick.h"

namespace weft::editor {

namespace {

struct ScreenPoint {
  Vec2 pixel = Vec2::Zero();
  bool inFront = false;  // in front of the eye (behind it, a point has no place on screen)
};

ScreenPoint toScreen(const Eigen::Matrix4f& viewProjection, const Vec3& p, int width, int height) {
  const Eigen::Vector4f clip = viewProjection * Eigen::Vector4f(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                                                static_cast<float>(p.z()), 1.0f);
  ScreenPoint s;
  s.inFront = clip.w() > 1e-6f;
  if (!s.inFront) return s;
  const double nx = clip.x() / clip.w(), ny = clip.y() / clip.w();
  s.pixel = Vec2((0.5 * nx + 0.5) * width, (0.5 - 0.5 * ny) * height);
  return s;
}

// Distance from c to the segment ab, and where along it (0 at a, 1 at b).
double segmentDistance(const Vec2& a, const Vec2& b, const Vec2& c, double& t) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  t = length2 > 0.0 ? std::clamp((c - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - c).norm();
}

}  // namespace

std::optional<TagTarget> pickTagTarget(const World& world, int tool, const ui::OrbitCamera& camera, double x, double y,
                                       int width, int height, const TagPickSettings& settings) {
  if (tool < 0 || tool >= world.obstacleCount() || width <= 0 || height <= 0) return std::nullopt;
  const Eigen::Matrix4f viewProjection =
      camera.projection(static_cast<double>(width) / height) * camera.view();
  const std::vector<Vec3> vertices = world.obstacleVertices(tool);
  const CollisionMesh& mesh = world.obstacle(tool).topology;
  const Vec3 eye = camera.eye();
  const Vec2 cursor(x, y);

  // How far the tool's front surface is under the cursor; features well behind it are hidden.
  Vec3 origin, dir;
  ui::cameraRay(camera, x, y, width, height, origin, dir);
  double visibleDepth = std::numeric_limits<double>::infinity();
  if (auto hit = pickObstacleFeature(world, origin, dir, 0.0); hit && hit->obstacle == tool) {
    const double depth = (hit->point - eye).norm();
    visibleDepth = depth + 0.02 * depth + 1e-3;  // a little slack for the feature's own faces
  }

  std::vector<ScreenPoint> screen(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) screen[v] = toScreen(viewProjection, vertices[v], width, height);

  int nearestVertex = -1;
  double vertexDistance = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!screen[v].inFront || (vertices[v] - eye).norm() > visibleDepth) continue;
    const double d = (screen[v].pixel - cursor).norm();
    if (d < vertexDistance) {
      vertexDistance = d;
      nearestVertex = static_cast<int>(v);
    }
  }
  if (nearestVertex >= 0 && vertexDistance <= settings.vertexPixels) return TagTarget{nearestVertex, {-1, -1}};

  int nearestEdge = -1;
  double edgeDistance = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto [a, b] = mesh.edges[e];
    if (!screen[a].inFront || !screen[b].inFront) continue;
    double t = 0.0;
    const double d = segmentDistance(screen[a].pixel, screen[b].pixel, cursor, t);
    if (d > settings.edgePixels || d >= edgeDistance) continue;
    if ((vertices[a] + t * (vertices[b] - vertices[a]) - eye).norm() > visibleDepth) continue;
    edgeDistance = d;
    nearestEdge = static_cast<int>(e);
  }
  if (nearestEdge >= 0) return TagTarget{-1, mesh.edges[static_cast<std::size_t>(nearestEdge)]};
  if (nearestVertex >= 0 && vertexDistance <= settings.edgePixels) return TagTarget{nearestVertex, {-1, -1}};
  return std::nullopt;
}

std::vector<std::array<int, 2>> edgesInBox(const World& world, int tool, const ui::OrbitCamera& camera, double x0, double y0,
                                           double x1, double y1, int width, int height) {
  std::vector<std::array<int, 2>> edges;
  if (tool < 0 || tool >= world.obstacleCount() || width <= 0 || height <= 0) return edges;
  const Eigen::Matrix4f viewProjection = camera.projection(static_cast<double>(width) / height) * camera.view();
  const std::vector<Vec3> vertices = world.obstacleVertices(tool);
  const Vec3 eye = camera.eye();
  const double left = std::min(x0, x1), right = std::max(x0, x1), top = std::min(y0, y1), bottom = std::max(y0, y1);
  // Each vertex in the box, seen: nothing of the tool nearer the eye along its own pixel's ray.
  std::vector<char> inside(vertices.size(), 0);
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const ScreenPoint s = toScreen(viewProjection, vertices[v], width, height);
    if (!s.inFront || s.pixel.x() < left || s.pixel.x() > right || s.pixel.y() < top || s.pixel.y() > bottom) continue;
    const double depth = (vertices[v] - eye).norm();
    const Vec3 dir = (vertices[v] - eye) / depth;
    const auto hit = pickObstacleFeature(world, eye, dir, 0.0);
    const bool hidden = hit && hit->obstacle == tool && (hit->point - eye).norm() < depth - (0.02 * depth + 1e-3);
    inside[v] = hidden ? 0 : 1;
  }
  for (const auto& e : world.obstacle(tool).topology.edges) {
    if (inside[static_cast<std::size_t>(e[0])] && inside[static_cast<std::size_t>(e[1])]) edges.push_back(e);
  }
  return edges;
}

}  // namespace weft::editor
