// Mouse drags and the wheel turned into camera changes, with made-up mouse states (no window).
#include <gtest/gtest.h>

#include <cmath>

#include "orbit_controls.h"

namespace weft::ui {
namespace {

constexpr double kPi = 3.14159265358979323846;

MouseState at(double x, double y) {
  MouseState mouse;
  mouse.x = x;
  mouse.y = y;
  return mouse;
}

MouseState held(MouseState mouse, bool left, bool right = false, bool middle = false) {
  mouse.left = left;
  mouse.right = right;
  mouse.middle = middle;
  return mouse;
}

Vec3 viewDirection(const OrbitCamera& camera) { return (camera.target - camera.eye()).normalized(); }

TEST(OrbitControls, LeftDragOrbitsByDegreesPerPixel) {
  OrbitCamera camera;
  const OrbitCamera start = camera;
  OrbitControlSettings settings;
  OrbitControls controls(settings);
  controls.update(camera, held(at(100, 100), true), 800);  // press: no change yet
  EXPECT_DOUBLE_EQ(camera.yawDeg, start.yawDeg);
  controls.update(camera, held(at(150, 80), true), 800);  // 50 px right, 20 px up
  EXPECT_NEAR(camera.yawDeg, start.yawDeg - 50 * settings.degreesPerPixel, 1e-12);
  EXPECT_NEAR(camera.pitchDeg, start.pitchDeg - 20 * settings.degreesPerPixel, 1e-12);
  EXPECT_DOUBLE_EQ(camera.distance, start.distance);
  EXPECT_TRUE(camera.target.isApprox(start.target));
}

TEST(OrbitControls, MovingWithoutAButtonChangesNothing) {
  OrbitCamera camera;
  const OrbitCamera start = camera;
  OrbitControls controls;
  controls.update(camera, at(0, 0), 800);
  controls.update(camera, at(300, 200), 800);
  EXPECT_DOUBLE_EQ(camera.yawDeg, start.yawDeg);
  EXPECT_DOUBLE_EQ(camera.pitchDeg, start.pitchDeg);
  EXPECT_TRUE(camera.target.isApprox(start.target));
}

TEST(OrbitControls, PitchStopsShortOfStraightUpAndDown) {
  OrbitCamera camera;
  OrbitControls controls;
  controls.update(camera, held(at(0, 0), true), 800);
  controls.update(camera, held(at(0, 10000), true), 800);
  EXPECT_DOUBLE_EQ(camera.pitchDeg, 89.0);
  controls.update(camera, held(at(0, -10000), true), 800);
  EXPECT_DOUBLE_EQ(camera.pitchDeg, -89.0);
  EXPECT_TRUE(camera.eye().allFinite());
}

TEST(OrbitControls, RightAndMiddleDragPanPerpendicularToTheViewScaledByDistance) {
  for (const bool middle : {false, true}) {
    SCOPED_TRACE(middle ? "middle" : "right");
    OrbitCamera camera;
    camera.target = Vec3(0.2, 0.5, -0.1);
    const OrbitCamera start = camera;
    OrbitControls controls;
    controls.update(camera, held(at(400, 300), false, !middle, middle), 600);
    controls.update(camera, held(at(460, 330), false, !middle, middle), 600);
    const Vec3 moved = camera.target - start.target;
    EXPECT_GT(moved.norm(), 0.0);
    EXPECT_NEAR(moved.dot(viewDirection(start)), 0.0, 1e-12);
    // A drag of 60 and 30 px on a 600 px tall view spans (60, 30) / 600 of the view's height there.
    const double viewHeight = 2.0 * start.distance * std::tan(start.fovYDeg * kPi / 360.0);
    EXPECT_NEAR(moved.norm(), std::hypot(60.0, 30.0) / 600.0 * viewHeight, 1e-9);
    // The eye moves with the target: same direction and distance.
    EXPECT_NEAR((camera.eye() - camera.target).norm(), start.distance, 1e-12);
    EXPECT_TRUE(viewDirection(camera).isApprox(viewDirection(start), 1e-12));
  }
}

TEST(OrbitControls, PanMovesTheTargetAgainstTheDrag) {
  OrbitCamera camera;
  camera.yawDeg = 0.0;
  camera.pitchDeg = 0.0;  // looking along -z: screen right is +x, screen up is +y
  OrbitControls controls;
  controls.update(camera, held(at(0, 0), false, true), 500);
  controls.update(camera, held(at(10, 0), false, true), 500);  // drag right
  EXPECT_LT(camera.target.x(), 0.0);
  controls.update(camera, held(at(10, 10), false, true), 500);  // drag down (window y grows down)
  EXPECT_GT(camera.target.y(), 0.0);
}

TEST(OrbitControls, PanDistanceGrowsWithCameraDistance) {
  OrbitCamera nearCamera, farCamera;
  farCamera.distance = 4.0 * nearCamera.distance;
  panBy(nearCamera, 20, 0, 500);
  panBy(farCamera, 20, 0, 500);
  EXPECT_GT(nearCamera.target.norm(), 0.0);
  EXPECT_NEAR(farCamera.target.norm(), 4.0 * nearCamera.target.norm(), 1e-12);
}

TEST(OrbitControls, ZoomInThenOutReturnsTheDistance) {
  OrbitCamera camera;
  camera.distance = 2.5;
  OrbitControlSettings settings;
  OrbitControls controls(settings);
  MouseState mouse = at(10, 10);
  mouse.scrollY = 3.0;
  controls.update(camera, mouse, 800);
  EXPECT_NEAR(camera.distance, 2.5 * std::pow(settings.zoomPerClick, 3), 1e-12);
  EXPECT_LT(camera.distance, 2.5);
  mouse.scrollY = -3.0;
  controls.update(camera, mouse, 800);
  EXPECT_NEAR(camera.distance, 2.5, 1e-12);
}

TEST(OrbitControls, ZoomNeverReachesTheTarget) {
  OrbitCamera camera;
  OrbitControlSettings settings;
  zoomBy(camera, 1e6, settings);
  EXPECT_GT(camera.distance, 0.0);
  EXPECT_GE(camera.distance, settings.minDistance);
  EXPECT_LT(camera.nearPlane, camera.distance);
}

}  // namespace
}  // namespace weft::ui
