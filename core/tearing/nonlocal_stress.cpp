#include "tearing/nonlocal_stress.h"

#include <algorithm>
#include <cmath>

namespace weft {

namespace {

// A triangle whose average depends on a changed one may lie a little beyond the radius from it
// when the walk to it bends around a crack's end: the patch looks this much further.
constexpr double kPatchReach = 1.25;

}  // namespace

double largestPrincipal(const Mat2& s) {
  const double mean = 0.5 * (s(0, 0) + s(1, 1));
  const double half = 0.5 * (s(0, 0) - s(1, 1));
  return mean + std::sqrt(half * half + s(0, 1) * s(0, 1));
}

void NonlocalStress::updateCentroids(const ClothMesh& mesh, const std::vector<int>& triangles) {
  const std::size_t count = mesh.tris.size();
  centroid_.resize(count, Vec2::Zero());
  area_.resize(count, 0.0);
  lip_.resize(count, 0);
  stamp_.resize(count, 0);
  for (int t : triangles) {
    const Triangle& tri = mesh.tris[t];
    centroid_[t] = (tri.rest[0] + tri.rest[1] + tri.rest[2]) / 3.0;
    area_[t] = std::abs(restArea(tri));
    lip_[t] = 0;
    for (int e : tri.edge) lip_[t] = lip_[t] || (mesh.edges[e].torn && mesh.edges[e].isBoundary());
  }
}

void NonlocalStress::gather(const ClothMesh& mesh, int t, double reach) {
  ++currentStamp_;
  region_.clear();
  region_.push_back(t);
  stamp_[t] = currentStamp_;
  const Vec2 centre = centroid_[t];
  const double reach2 = reach * reach;
  for (std::size_t next = 0; next < region_.size(); ++next) {
    const Triangle& tri = mesh.tris[region_[next]];
    for (int e : tri.edge) {
      const Edge& edge = mesh.edges[e];
      const int other = edge.tri[0] == region_[next] ? edge.tri[1] : edge.tri[0];
      if (other == kNone || stamp_[other] == currentStamp_) continue;
      stamp_[other] = currentStamp_;
      if ((centroid_[other] - centre).squaredNorm() <= reach2) region_.push_back(other);
    }
  }
}

Mat2 NonlocalStress::averageAt(const ClothMesh& mesh, const std::vector<Mat2>& local, int t) {
  gather(mesh, t, radius_);
  Mat2 sum = Mat2::Zero();
  double weights = 0.0;
  const double inverseRadius2 = 1.0 / (radius_ * radius_);
  for (int u : region_) {
    if (lip_[u]) continue;
    const double d2 = (centroid_[u] - centroid_[t]).squaredNorm() * inverseRadius2;
    const double bell = (1.0 - d2) * (1.0 - d2);
    const double w = area_[u] * bell;
    sum += w * local[u];
    weights += w;
  }
  return weights > 0.0 ? Mat2(sum / weights) : local[t];
}

void NonlocalStress::average(const ClothMesh& mesh, const std::vector<Mat2>& local, double radius, double threshold,
                             std::vector<Mat2>& out) {
  radius_ = radius;
  threshold_ = threshold;
  centroid_.clear();
  area_.clear();
  lip_.clear();
  stamp_.assign(mesh.tris.size(), 0);
  currentStamp_ = 0;
  std::vector<int> all(mesh.tris.size());
  for (int t = 0; t < mesh.triangleCount(); ++t) all[t] = t;
  updateCentroids(mesh, all);
  out = local;
  // The triangles within reach of a hot one, plus their vertex neighbours (a fan that holds one
  // of them reads its neighbours' averages too): marked, then averaged.
  std::vector<char> needed(mesh.tris.size(), 0);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    if (largestPrincipal(local[t]) < threshold) continue;
    gather(mesh, t, kPatchReach * radius);
    for (int u : region_) needed[u] = 1;
  }
  std::vector<char> vertexNeeded(mesh.x.size(), 0);
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    if (!needed[t]) continue;
    for (int v : mesh.tris[t].v) vertexNeeded[v] = 1;
  }
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    const Triangle& tri = mesh.tris[t];
    if (needed[t] || vertexNeeded[tri.v[0]] || vertexNeeded[tri.v[1]] || vertexNeeded[tri.v[2]]) {
      out[t] = averageAt(mesh, local, t);
    }
  }
}

std::vector<int> NonlocalStress::patch(const ClothMesh& mesh, const std::vector<Mat2>& local,
                                       const std::vector<int>& changed, std::vector<Mat2>& out) {
  out.resize(mesh.tris.size(), Mat2::Zero());
  updateCentroids(mesh, changed);
  std::vector<int> dirty;
  for (int t : changed) {
    gather(mesh, t, kPatchReach * radius_);
    dirty.insert(dirty.end(), region_.begin(), region_.end());
  }
  std::sort(dirty.begin(), dirty.end());
  dirty.erase(std::unique(dirty.begin(), dirty.end()), dirty.end());
  for (int t : dirty) out[t] = averageAt(mesh, local, t);
  return dirty;
}

}  // namespace weft
