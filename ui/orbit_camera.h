#pragma once
// An orbit camera: it looks at `target` from `distance` away, turned by yaw about world y and
// tilted by pitch. No GL here; the renderer turns it into matrices.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "util/types.h"

namespace weft::ui {

struct OrbitCamera {
  Vec3 target = Vec3::Zero();  // m: the point looked at
  double distance = 3.0;       // m: from the eye to the target
  double yawDeg = 30.0;        // degrees about world +y; 0 looks along -z
  double pitchDeg = 20.0;      // degrees above the horizontal (positive looks down)
  double fovYDeg = 40.0;       // vertical field of view, degrees
  double nearPlane = 0.01;     // m
  double farPlane = 100.0;     // m

  Vec3 eye() const;
  Eigen::Matrix4f view() const;
  Eigen::Matrix4f projection(double aspect) const;  // aspect = width / height
};

// The ray from the eye through the point (x, y) of a width x height image, in pixels from its
// top-left corner (where the mouse is): origin at the eye, unit direction. For picking.
void cameraRay(const OrbitCamera& camera, double x, double y, int width, int height, Vec3& outOrigin, Vec3& outDir);

// How many pixels of a height-pixel image one metre spans at world point p, across the view (a
// length facing the camera at p's depth); 0 for a point at or behind the eye.
double pixelsPerMetreAt(const OrbitCamera& camera, const Vec3& p, int height);

// A camera at the given yaw and pitch that keeps the whole box [boxMin, boxMax] in view (every
// corner inside the view, with a small margin), for an image of the given aspect.
OrbitCamera frameBox(const Vec3& boxMin, const Vec3& boxMax, double aspect, double yawDeg = 30.0,
                     double pitchDeg = 20.0);

}  // namespace weft::ui
