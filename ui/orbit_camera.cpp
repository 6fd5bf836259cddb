#include "orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace weft::ui {
namespace {
constexpr double kPi = 3.14159265358979323846;
double radians(double degrees) { return degrees * kPi / 180.0; }
}  // namespace

Vec3 OrbitCamera::eye() const {
  const double yaw = radians(yawDeg), pitch = radians(pitchDeg);
  // At yaw 0 and pitch 0 the eye is on +z of the target, looking along -z.
  const Vec3 back(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  return target + distance * back;
}

Eigen::Matrix4f OrbitCamera::view() const {
  const Vec3 e = eye();
  const Vec3 f = (target - e).normalized();
  Vec3 up(0, 1, 0);
  if (std::abs(f.dot(up)) > 0.999) up = Vec3(0, 0, -1);  // looking straight down or up
  const Vec3 s = f.cross(up).normalized();
  const Vec3 u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(e);
  m(1, 3) = -u.dot(e);
  m(2, 3) = f.dot(e);
  return m.cast<float>();
}

Eigen::Matrix4f OrbitCamera::projection(double aspect) const {
  const double t = 1.0 / std::tan(radians(fovYDeg) / 2.0);
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = t / aspect;
  p(1, 1) = t;
  p(2, 2) = (farPlane + nearPlane) / (nearPlane - farPlane);
  p(2, 3) = 2.0 * farPlane * nearPlane / (nearPlane - farPlane);
  p(3, 2) = -1.0;
  return p.cast<float>();
}

void cameraRay(const OrbitCamera& camera, double x, double y, int width, int height, Vec3& outOrigin, Vec3& outDir) {
  const Eigen::Matrix4d view = camera.view().cast<double>();
  const Vec3 side = view.block<1, 3>(0, 0).transpose();
  const Vec3 up = view.block<1, 3>(1, 0).transpose();
  const Vec3 forward = -view.block<1, 3>(2, 0).transpose();
  const double tanY = std::tan(radians(camera.fovYDeg) / 2.0);
  const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;
  // Normalized device coordinates, y up.
  const double ndcX = 2.0 * x / std::max(width, 1) - 1.0;
  const double ndcY = 1.0 - 2.0 * y / std::max(height, 1);
  outOrigin = camera.eye();
  outDir = (forward + ndcX * tanY * aspect * side + ndcY * tanY * up).normalized();
}

double pixelsPerMetreAt(const OrbitCamera& camera, const Vec3& p, int height) {
  const Eigen::Matrix4d view = camera.view().cast<double>();
  const Vec3 forward = -view.block<1, 3>(2, 0).transpose();
  const double depth = (p - camera.eye()).dot(forward);
  if (!(depth > 0.0)) return 0.0;
  // The image's height spans 2 depth tan(fovY / 2) metres at that depth.
  return std::max(height, 1) / (2.0 * depth * std::tan(radians(camera.fovYDeg) / 2.0));
}

OrbitCamera frameBox(const Vec3& boxMin, const Vec3& boxMax, double aspect, double yawDeg, double pitchDeg) {
  OrbitCamera camera;
  camera.yawDeg = yawDeg;
  camera.pitchDeg = pitchDeg;
  camera.target = 0.5 * (boxMin + boxMax);
  camera.distance = 1.0;
  // The camera's axes at the default yaw and pitch (they do not depend on the distance).
  const Eigen::Matrix4f view = camera.view();
  const Vec3 side = view.block<1, 3>(0, 0).transpose().cast<double>();
  const Vec3 up = view.block<1, 3>(1, 0).transpose().cast<double>();
  const Vec3 back = view.block<1, 3>(2, 0).transpose().cast<double>();
  const double tanY = std::tan(radians(camera.fovYDeg) / 2.0);
  const double tanX = tanY * aspect;
  // Every corner of the box inside the view frustum: with the corner at depth
  // (distance - back offset), |side offset| <= depth * tanX and |up offset| <= depth * tanY.
  double distance = 0.05;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? boxMax.x() : boxMin.x(), (corner & 2) ? boxMax.y() : boxMin.y(),
                 (corner & 4) ? boxMax.z() : boxMin.z());
    const Vec3 d = p - camera.target;
    distance = std::max(distance, d.dot(back) + std::abs(d.dot(side)) / tanX);
    distance = std::max(distance, d.dot(back) + std::abs(d.dot(up)) / tanY);
  }
  camera.distance = 1.08 * distance;  // a margin around the action
  camera.nearPlane = std::max(0.001, 0.01 * camera.distance);
  camera.farPlane = 50.0 * camera.distance;
  return camera;
}

}  // namespace weft::ui
