#include "collision/material_patches.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

namespace weft {
namespace {

// How far a deformation gradient computed in floating point may lie from the true one (relative
// to its entries, which are about 1): the certificate keeps this much in hand.
constexpr double kGradientSlack = 1e-8;
// Relative rounding allowed when comparing a node's summed areas and boundary with its hull's.
constexpr double kTilingTolerance = 1e-9;
// Largest node (triangles) given the sharper check over its own triangles: beyond it the pass
// costs more than the search it could save, and bends that large rarely certify.
constexpr int kLargestSharpCheck = 512;

// Area and perimeter of the convex hull of `points` (Andrew's monotone chain).
struct Hull {
  double area = 0.0, perimeter = 0.0;
};
Hull convexHull(std::vector<Vec2>& points) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  const int n = static_cast<int>(points.size());
  if (n < 3) return {};
  std::vector<Vec2> chain(2 * static_cast<std::size_t>(n));
  int k = 0;
  for (int i = 0; i < n; ++i) {  // lower hull
    while (k >= 2 && cross2(chain[k - 1] - chain[k - 2], points[i] - chain[k - 2]) <= 0.0) --k;
    chain[k++] = points[i];
  }
  for (int i = n - 2, lower = k + 1; i >= 0; --i) {  // upper hull
    while (k >= lower && cross2(chain[k - 1] - chain[k - 2], points[i] - chain[k - 2]) <= 0.0) --k;
    chain[k++] = points[i];
  }
  Hull hull;
  for (int i = 0; i + 1 < k; ++i) {
    hull.area += 0.5 * cross2(chain[i], chain[i + 1]);
    hull.perimeter += (chain[i + 1] - chain[i]).norm();
  }
  return hull;
}

// A ball in the space of 3 x 2 deformation gradients (Frobenius norm).
using Gradient = Eigen::Matrix<double, 3, 2>;
struct GradientBall {
  Gradient centre = Gradient::Zero();
  double radius = -1.0;  // negative: empty
};

GradientBall merge(const GradientBall& a, const GradientBall& b) {
  if (a.radius < 0.0) return b;
  if (b.radius < 0.0) return a;
  const double d = (b.centre - a.centre).norm();
  if (!std::isfinite(d) || !std::isfinite(a.radius) || !std::isfinite(b.radius)) {
    return {a.centre, std::numeric_limits<double>::infinity()};
  }
  if (d + b.radius <= a.radius) return a;
  if (d + a.radius <= b.radius) return b;
  GradientBall m;
  m.radius = 0.5 * (d + a.radius + b.radius);
  m.centre = a.centre + ((m.radius - a.radius) / d) * (b.centre - a.centre);
  return m;
}

// The smaller singular value of a 3 x 2 matrix.
double smallestSingularValue(const Gradient& c) {
  const double a = c.col(0).squaredNorm(), b = c.col(0).dot(c.col(1)), d = c.col(1).squaredNorm();
  const double half = 0.5 * (a - d);
  const double smallest = 0.5 * (a + d) - std::sqrt(half * half + b * b);
  return std::sqrt(std::max(smallest, 0.0));
}

// The inverse of a rest shape's edge matrix; NaN when the shape is degenerate or inverted.
Mat2 restEdgesInverse(const std::array<Vec2, 3>& r) {
  Mat2 dm;
  dm.col(0) = r[1] - r[0];
  dm.col(1) = r[2] - r[0];
  if (!(dm.determinant() > 0.0)) return Mat2::Constant(std::numeric_limits<double>::quiet_NaN());
  return dm.inverse();
}

// The deformation gradient of a triangle with world corners x: Ds Dm^-1, as the membrane
// elements compute it.
Gradient deformationGradient(const std::array<int, 3>& corners, const Mat2& restInverse, const std::vector<Vec3>& x) {
  Gradient ds;
  ds.col(0) = x[corners[1]] - x[corners[0]];
  ds.col(1) = x[corners[2]] - x[corners[0]];
  return ds * restInverse;
}

}  // namespace

std::vector<Aabb> materialBoxes(const RestCorners& rest) {
  std::vector<Aabb> boxes(rest.size());
  for (std::size_t t = 0; t < rest.size(); ++t) {
    for (const Vec2& r : rest[t]) boxes[t].grow(Vec3(r.x(), r.y(), 0.0));
  }
  return boxes;
}

void buildMaterialPatches(const Bvh& tree, const CollisionMesh& mesh, const RestCorners& rest,
                          MaterialPatches& patches) {
  const int nodes = tree.nodeCount();
  const int triangles = static_cast<int>(mesh.triangles.size());
  patches.tilesConvexRegion.assign(static_cast<std::size_t>(nodes), 0);
  patches.smallestAltitude.assign(static_cast<std::size_t>(nodes), 0.0);
  patches.parent.assign(static_cast<std::size_t>(nodes), -1);
  if (nodes == 0 || static_cast<int>(rest.size()) != triangles) return;

  // A vertex whose corners disagree on its material position (a seam) breaks any tiling it is in.
  std::vector<Vec2> position(static_cast<std::size_t>(mesh.vertexCount), Vec2::Zero());
  std::vector<char> seen(static_cast<std::size_t>(mesh.vertexCount), 0), seam(seen);
  for (int t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (!seen[v]) {
        seen[v] = 1;
        position[v] = rest[t][k];
      } else if (position[v] != rest[t][k]) {
        seam[v] = 1;
      }
    }
  }
  patches.restInverse.resize(static_cast<std::size_t>(triangles));
  for (int t = 0; t < triangles; ++t) patches.restInverse[t] = restEdgesInverse(rest[t]);
  std::vector<char> usable(static_cast<std::size_t>(triangles), 0);
  std::vector<double> area(static_cast<std::size_t>(triangles), 0.0), altitude(area);
  for (int t = 0; t < triangles; ++t) {
    const auto& r = rest[t];
    area[t] = 0.5 * cross2(r[1] - r[0], r[2] - r[0]);
    const double longest = std::max({(r[1] - r[0]).norm(), (r[2] - r[1]).norm(), (r[0] - r[2]).norm()});
    altitude[t] = longest > 0.0 ? 2.0 * area[t] / longest : 0.0;
    const auto& c = mesh.triangles[t];
    usable[t] = area[t] > 0.0 && !seam[c[0]] && !seam[c[1]] && !seam[c[2]];
  }

  // Leaves in tree order: each node's triangles are one run of `order` (nodes are depth first).
  std::vector<int>& order = patches.triangles;
  std::vector<int>& begin = patches.first;
  std::vector<int>& end = patches.last;
  order.clear();
  begin.assign(static_cast<std::size_t>(nodes), 0);
  end.assign(static_cast<std::size_t>(nodes), 0);
  for (int n = 0; n < nodes; ++n) {
    if (!tree.isLeafNode(n)) {
      patches.parent[n + 1] = patches.parent[tree.rightChild(n)] = n;
      continue;
    }
    begin[n] = static_cast<int>(order.size());
    tree.forEachBoxOfLeaf(n, [&](int t) { order.push_back(t); });
    end[n] = static_cast<int>(order.size());
  }
  for (int n = nodes - 1; n >= 0; --n) {
    if (tree.isLeafNode(n)) continue;
    begin[n] = begin[n + 1];
    end[n] = end[tree.rightChild(n)];
  }

  std::vector<int> edgeUses(mesh.edges.size(), 0), touchedEdges;
  std::vector<int> vertexStamp(static_cast<std::size_t>(mesh.vertexCount), -1);
  std::vector<Vec2> points;
  for (int n = 0; n < nodes; ++n) {
    double areaSum = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    bool usableAll = true;
    touchedEdges.clear();
    points.clear();
    for (int s = begin[n]; s < end[n]; ++s) {
      const int t = order[s];
      usableAll = usableAll && usable[t];
      areaSum += area[t];
      smallest = std::min(smallest, altitude[t]);
      for (int e : mesh.triangleEdges[t]) {
        if (edgeUses[e]++ == 0) touchedEdges.push_back(e);
      }
      for (int v : mesh.triangles[t]) {
        if (vertexStamp[v] == n) continue;
        vertexStamp[v] = n;
        points.push_back(position[v]);
      }
    }
    double boundary = 0.0;
    bool manifold = true;
    for (int e : touchedEdges) {
      manifold = manifold && edgeUses[e] <= 2;
      if (edgeUses[e] == 1) boundary += (position[mesh.edges[e][1]] - position[mesh.edges[e][0]]).norm();
      edgeUses[e] = 0;
    }
    patches.smallestAltitude[n] = smallest;
    if (!usableAll || !manifold) continue;
    // Triangles of one orientation whose areas add up to their hull's, bounded by its perimeter
    // alone (a slit or a notch would add boundary), tile the hull.
    const Hull hull = convexHull(points);
    patches.tilesConvexRegion[n] = hull.area > 0.0 &&
                                   std::abs(areaSum - hull.area) <= kTilingTolerance * hull.area &&
                                   std::abs(boundary - hull.perimeter) <= kTilingTolerance * hull.perimeter;
  }
}

void forgetPatchesAbove(const Bvh& tree, int triangle, MaterialPatches& patches) {
  if (patches.empty() || triangle >= tree.leafCount()) return;
  for (int n = tree.leafOf(triangle); n >= 0; n = patches.parent[n]) patches.tilesConvexRegion[n] = 0;
}

void certifyPatches(const MaterialPatches& patches, const Bvh& tree, const CollisionMesh& mesh,
                    const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, double margin,
                    std::vector<char>& certified) {
  const int nodes = tree.nodeCount();
  certified.assign(static_cast<std::size_t>(nodes), 0);
  if (patches.empty() || static_cast<int>(patches.parent.size()) != nodes) return;
  const bool oneInstant = &x1 == &x0;
  const std::size_t triangleCount = mesh.triangles.size();
  std::vector<Gradient> start(triangleCount), finish(oneInstant ? 0 : triangleCount);
  const std::size_t built = std::min(triangleCount, patches.restInverse.size());
  for (std::size_t t = 0; t < built; ++t) {
    start[t] = deformationGradient(mesh.triangles[t], patches.restInverse[t], x0);
    if (!oneInstant) finish[t] = deformationGradient(mesh.triangles[t], patches.restInverse[t], x1);
  }
  for (std::size_t t = built; t < triangleCount; ++t) {  // added since the build: only in forgotten nodes
    start[t] = Gradient::Constant(std::numeric_limits<double>::quiet_NaN());
    if (!oneInstant) finish[t] = start[t];
  }
  // The sharper bound's deviation of triangle t from C, in C's column space (both ends of the step).
  auto deviation = [&](const Eigen::Matrix<double, 2, 3>& qt, const Gradient& c, int t) {
    const double d = (qt * (start[t] - c)).norm();
    return oneInstant ? d : std::max(d, (qt * (finish[t] - c)).norm());
  };
  std::vector<GradientBall> balls(static_cast<std::size_t>(nodes));
  // Children come after their parent: a backwards sweep meets both children first.
  for (int n = nodes - 1; n >= 0; --n) {
    GradientBall ball;
    const bool leaf = tree.isLeafNode(n);
    if (leaf) {
      tree.forEachBoxOfLeaf(n, [&](int t) {
        ball = merge(ball, oneInstant ? GradientBall{start[t], 0.0}
                                      : GradientBall{0.5 * (start[t] + finish[t]), 0.5 * (finish[t] - start[t]).norm()});
      });
      // (A NaN gradient, from a degenerate rest shape or position, leaves a NaN radius: never certified.)
    } else {
      ball = merge(balls[n + 1], balls[tree.rightChild(n)]);
    }
    balls[n] = ball;
    if (!patches.tilesConvexRegion[n]) continue;
    const double smallest = smallestSingularValue(ball.centre);
    const double needed = margin / patches.smallestAltitude[n] + kGradientSlack;  // of the stretch bound
    if (smallest - ball.radius > needed) {
      certified[n] = 1;
      continue;
    }
    const int size = patches.last[n] - patches.first[n];
    if (size > kLargestSharpCheck || !(smallest > needed) ||
        (!leaf && !(certified[n + 1] && certified[tree.rightChild(n)]))) {
      continue;
    }
    // Q^T: the orthonormal basis of C's columns (Gram-Schmidt), as rows.
    Eigen::Matrix<double, 2, 3> qt;
    qt.row(0) = ball.centre.col(0).normalized().transpose();
    qt.row(1) = (ball.centre.col(1) - qt.row(0).dot(ball.centre.col(1)) * qt.row(0).transpose()).normalized().transpose();
    double largest = 0.0;
    for (int k = patches.first[n]; k < patches.last[n] && smallest - largest > needed; ++k) {
      largest = std::max(largest, deviation(qt, ball.centre, patches.triangles[k]));
    }
    certified[n] = smallest - largest > needed;  // (false for NaN)
  }
}

}  // namespace weft
