#include "sim/pick.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/obstacle.h"
#include "sim/world.h"

namespace weft {

namespace {

// Ray parameter s >= 0 where origin + s dir meets triangle (a, b, c), either face (Moller and
// Trumbore); none for a miss or a ray in the triangle's plane.
std::optional<double> rayTriangle(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a;
  const Vec3 ac = c - a;
  const Vec3 p = dir.cross(ac);
  const double det = ab.dot(p);
  const double scale = ab.norm() * ac.norm() * dir.norm();
  if (!(std::abs(det) > 1e-14 * scale)) return std::nullopt;
  const Vec3 t = origin - a;
  const double u = t.dot(p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 q = t.cross(ab);
  const double v = dir.dot(q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double s = ac.dot(q) / det;
  if (s < 0.0) return std::nullopt;
  return s;
}

double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + s * ab)).norm();
}

}  // namespace

std::optional<ClothHit> pickCloth(const World& world, const Vec3& rayOrigin, const Vec3& rayDir) {
  std::optional<ClothHit> best;
  for (int c = 0; c < world.clothCount(); ++c) {
    const ClothMesh& mesh = world.cloth(c);
    for (int t = 0; t < mesh.triangleCount(); ++t) {
      const Triangle& tri = mesh.tris[t];
      const std::optional<double> s = rayTriangle(rayOrigin, rayDir, mesh.x[tri.v[0]], mesh.x[tri.v[1]], mesh.x[tri.v[2]]);
      if (!s || (best && *s >= best->distance)) continue;  // strict: the lowest ids win ties
      ClothHit hit;
      hit.cloth = c;
      hit.triangle = t;
      hit.distance = *s;
      hit.point = rayOrigin + *s * rayDir;
      hit.vertex = tri.v[0];
      for (int k = 1; k < 3; ++k)
        if ((mesh.x[tri.v[k]] - hit.point).squaredNorm() < (mesh.x[hit.vertex] - hit.point).squaredNorm()) hit.vertex = tri.v[k];
      best = hit;
    }
  }
  return best;
}

std::optional<ObstacleFeatureHit> pickObstacleFeature(const World& world, const Vec3& rayOrigin, const Vec3& rayDir,
                                                      double tolerance) {
  std::optional<ObstacleFeatureHit> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  std::vector<Vec3> bestVertices;
  for (int o = 0; o < world.obstacleCount(); ++o) {
    const std::vector<Vec3> x = world.obstacleVertices(o);
    const CollisionMesh& topology = world.obstacle(o).topology;
    for (int t = 0; t < static_cast<int>(topology.triangles.size()); ++t) {
      const std::array<int, 3>& tri = topology.triangles[t];
      const std::optional<double> s = rayTriangle(rayOrigin, rayDir, x[tri[0]], x[tri[1]], x[tri[2]]);
      if (!s || *s >= bestDistance) continue;
      bestDistance = *s;
      ObstacleFeatureHit hit;
      hit.obstacle = o;
      hit.triangle = t;
      hit.point = rayOrigin + *s * rayDir;
      best = hit;
      bestVertices = x;
    }
  }
  if (!best) return best;
  const CollisionMesh& topology = world.obstacle(best->obstacle).topology;
  double nearestVertex = tolerance;
  for (int v = 0; v < static_cast<int>(bestVertices.size()); ++v) {
    const double d = (bestVertices[v] - best->point).norm();
    if (d <= nearestVertex && (best->vertex == kNone || d < nearestVertex)) {
      nearestVertex = d;
      best->vertex = v;
    }
  }
  double nearestEdge = tolerance;
  for (int e = 0; e < static_cast<int>(topology.edges.size()); ++e) {
    const std::array<int, 2>& edge = topology.edges[e];
    const double d = pointSegmentDistance(best->point, bestVertices[edge[0]], bestVertices[edge[1]]);
    if (d <= nearestEdge && (best->edge == kNone || d < nearestEdge)) {
      nearestEdge = d;
      best->edge = e;
    }
  }
  return best;
}

}  // namespace weft
