// The headless renderer: EGL surfaceless + llvmpipe, pinned by GALLIUM_DRIVER so pixels are
// reproducible. Skipped (with the reason) on a machine where EGL cannot start.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "headless_gl_context.h"
#include "offscreen_framebuffer.h"
#include "scene/scene_json.h"
#include "scene_renderer.h"
#include "sim/cloth.h"
#include "sim/world.h"
#include "support/test_scenes.h"

namespace weft::ui {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
  const std::uint8_t* at(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

class SceneRendererTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    try {
      context_ = std::make_unique<HeadlessGlContext>();
    } catch (const GlContextError& e) {
      skipReason_ = std::string("headless OpenGL (EGL surfaceless) cannot start here: ") + e.what();
    }
  }
  static void TearDownTestSuite() { context_.reset(); }

  void SetUp() override {
    if (!context_) GTEST_SKIP() << skipReason_;
  }

  static Image render(const RenderView& view, const OrbitCamera& camera, int width, int height,
                      const RenderSettings& settings = RenderSettings{}) {
    OffscreenFramebuffer framebuffer(width, height, 4);
    SceneRenderer renderer(settings);
    framebuffer.bind();
    renderer.draw(view, camera, width, height);
    return Image{width, height, framebuffer.readPixels()};
  }

  static Image renderDefaultFraming(const RenderView& view, int width, int height,
                                    const RenderSettings& settings = RenderSettings{}) {
    Vec3 lo, hi;
    actionBox(view, lo, hi);
    return render(view, frameBox(lo, hi, static_cast<double>(width) / height), width, height, settings);
  }

  static inline std::unique_ptr<HeadlessGlContext> context_;
  static inline std::string skipReason_;
};

bool isBackground(const std::uint8_t* p, const RenderSettings& settings) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(p[c] - std::lround(settings.background[c] * 255.0f)) > 3) return false;
  }
  return true;
}

// Reddish cloth of the default tint: red clearly above green and blue.
bool isClothColoured(const std::uint8_t* p) { return p[0] > p[1] + 20 && p[0] > p[2] + 20; }

bool isEdgeRed(const std::uint8_t* p) { return p[0] > 170 && p[1] < 60 && p[2] < 60; }

TEST_F(SceneRendererTest, ContextReportsARenderer) {
  EXPECT_FALSE(context_->glRenderer().empty());
  RecordProperty("gl_renderer", context_->glRenderer());
}

TEST_F(SceneRendererTest, CaptureIsDeterministic) {
  const Scene scene = loadScene(std::string(WEFT_SOURCE_DIR) + "/presets/scenes/sword-into-sheet.json", {});
  World world(scene);
  for (int s = 0; s < 3; ++s) world.step();
  const Image a = renderDefaultFraming(renderViewOf(world), 160, 120);
  const Image b = renderDefaultFraming(renderViewOf(world), 160, 120);
  ASSERT_EQ(a.rgba.size(), 160u * 120u * 4u);
  EXPECT_TRUE(a.rgba == b.rgba);
}

TEST_F(SceneRendererTest, DefaultSceneIsFramedWithClothInTheMiddle) {
  const Scene scene = loadScene(std::string(WEFT_SOURCE_DIR) + "/presets/scenes/hanging-sheet.json", {});
  World world(scene);
  const RenderSettings settings;
  // The camera frames the start (a flat sheet about to fall); the picture is taken once it hangs.
  Vec3 lo, hi;
  actionBox(renderViewOf(world), lo, hi);
  const OrbitCamera camera = frameBox(lo, hi, 200.0 / 150.0);
  for (int s = 0; s < 90; ++s) world.step();
  const Image image = render(renderViewOf(world), camera, 200, 150, settings);
  // The middle region (the central third) is mostly cloth; the image border is background.
  int cloth = 0, middle = 0;
  for (int y = image.height / 3; y < 2 * image.height / 3; ++y) {
    for (int x = image.width / 3; x < 2 * image.width / 3; ++x) {
      ++middle;
      if (isClothColoured(image.at(x, y))) ++cloth;
    }
  }
  EXPECT_GT(cloth, middle / 3) << cloth << " of " << middle << " middle pixels are cloth";
  int border = 0, background = 0;
  for (int x = 0; x < image.width; ++x) {
    for (int y : {0, 1, image.height - 2, image.height - 1}) {
      ++border;
      if (isBackground(image.at(x, y), settings)) ++background;
    }
  }
  EXPECT_EQ(background, border) << "the cloth touches the image border: the framing is too tight";
}

// A flat 0.4 m sheet in the world x-y plane, facing the camera (+z), as a bare mesh.
ClothMesh flatSheet(int resolution, double size = 0.4) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(), resolution, 0.01);
  scene.cloths[0].grid->width = size;
  scene.cloths[0].grid->height = size;
  scene.cloths[0].placement.translate = Vec3(-size / 2, -size / 2, 0);
  return buildCloth(scene.cloths[0], "test", 0).mesh;
}

OrbitCamera facingCamera(double distance) {
  OrbitCamera camera;
  camera.yawDeg = 0.0;
  camera.pitchDeg = 0.0;
  camera.distance = distance;
  camera.target = Vec3::Zero();
  return camera;
}

TEST_F(SceneRendererTest, TornEdgeIsDrawnRedAndCutEdgeGreen) {
  ClothMesh mesh = flatSheet(9);
  RenderView view;
  view.cloths.push_back(ClothView{&mesh, 0.0, clothTint(0)});
  const OrbitCamera camera = facingCamera(1.0);
  const Image before = render(view, camera, 160, 160);

  // Mark the edges along the horizontal middle line (y = 0) as torn.
  int marked = 0;
  for (Edge& e : mesh.edges) {
    if (std::abs(mesh.x[e.v[0]].y()) < 1e-9 && std::abs(mesh.x[e.v[1]].y()) < 1e-9) {
      e.torn = true;
      ++marked;
    }
  }
  ASSERT_EQ(marked, 8);
  const Image after = render(view, camera, 160, 160);

  auto redPixels = [](const Image& image, int rowFrom, int rowTo) {
    int n = 0;
    for (int y = rowFrom; y <= rowTo; ++y) {
      for (int x = 0; x < image.width; ++x) n += isEdgeRed(image.at(x, y)) ? 1 : 0;
    }
    return n;
  };
  const int mid = 80;  // y = 0 projects onto the middle row
  EXPECT_EQ(redPixels(before, 0, 159), 0);
  // The sheet spans 0.4 m at 1 m with a 40 degree field of view: about 87 px wide.
  EXPECT_GT(redPixels(after, mid - 3, mid + 3), 70);
  EXPECT_EQ(redPixels(after, 0, mid - 6) + redPixels(after, mid + 6, 159), 0) << "red away from the tear";

  // A cut edge is green: the vertical middle line (x = 0), cut instead.
  for (Edge& e : mesh.edges) {
    e.torn = false;
    if (std::abs(mesh.x[e.v[0]].x()) < 1e-9 && std::abs(mesh.x[e.v[1]].x()) < 1e-9) e.cut = true;
  }
  const Image cut = render(view, camera, 160, 160);
  int green = 0, greenAway = 0;
  for (int y = 0; y < cut.height; ++y) {
    for (int x = 0; x < cut.width; ++x) {
      const std::uint8_t* p = cut.at(x, y);
      if (p[1] > 140 && p[0] < 60 && p[2] < 60) ++(std::abs(x - mid) <= 3 ? green : greenAway);
    }
  }
  EXPECT_GT(green, 70);
  EXPECT_EQ(greenAway, 0);
  EXPECT_EQ(redPixels(cut, 0, 159), 0);
}

// Dominant stripe orientation (degrees in [0, 90)): the peak of a histogram of luminance
// gradient angles folded modulo 90 degrees (the weft and warp thread sets are perpendicular),
// weighted by the squared gradient magnitude and smoothed over a few degrees.
double stripeOrientationDeg(const Image& image, int x0, int y0, int x1, int y1) {
  auto lum = [&](int x, int y) {
    const std::uint8_t* p = image.at(x, y);
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
  };
  std::vector<double> histogram(90, 0.0);
  for (int y = y0 + 1; y < y1 - 1; ++y) {
    for (int x = x0 + 1; x < x1 - 1; ++x) {
      // Sobel gradients: less biased towards the pixel axes than central differences.
      const double gx = (lum(x + 1, y - 1) + 2 * lum(x + 1, y) + lum(x + 1, y + 1)) -
                        (lum(x - 1, y - 1) + 2 * lum(x - 1, y) + lum(x - 1, y + 1));
      const double gy = -((lum(x - 1, y + 1) + 2 * lum(x, y + 1) + lum(x + 1, y + 1)) -
                          (lum(x - 1, y - 1) + 2 * lum(x, y - 1) + lum(x + 1, y - 1)));  // rows go down
      double deg = std::atan2(gy, gx) * 180.0 / kPi;
      deg = std::fmod(deg + 360.0, 90.0);
      histogram[static_cast<std::size_t>(deg) % 90] += gx * gx + gy * gy;
    }
  }
  int best = 0;
  double bestValue = -1.0;
  for (int k = 0; k < 90; ++k) {
    double value = 0.0;
    for (int d = -3; d <= 3; ++d) value += histogram[static_cast<std::size_t>((k + d + 90) % 90)];
    if (value > bestValue) {
      bestValue = value;
      best = k;
    }
  }
  return best + 0.5;
}

TEST_F(SceneRendererTest, WovenStripesFollowTheWeftAngle) {
  const ClothMesh mesh = flatSheet(5);
  const OrbitCamera camera = facingCamera(0.9);
  auto orientation = [&](double weftDeg) {
    RenderView view;
    ClothView cloth{&mesh, weftDeg * kPi / 180.0, clothTint(0)};
    cloth.threadPitch = 0.02;  // coarse: about 9 px per thread in a 200 px image of the sheet
    view.cloths.push_back(cloth);
    const Image image = render(view, camera, 256, 256);
    // A window well inside the sheet.
    return stripeOrientationDeg(image, 78, 78, 178, 178);
  };
  const double at0 = orientation(0.0);
  const double at30 = orientation(30.0);
  double turned = at30 - at0;
  if (turned < 0) turned += 90.0;
  if (turned > 75.0) turned -= 90.0;
  RecordProperty("stripe_deg_weft0", std::to_string(at0));
  RecordProperty("stripe_deg_weft30", std::to_string(at30));
  EXPECT_NEAR(turned, 30.0, 5.0) << "weft 0: " << at0 << " deg, weft 30: " << at30 << " deg";
  EXPECT_TRUE(at0 < 5.0 || at0 > 85.0) << "weft 0 stripes should be axis-aligned, got " << at0;
}

}  // namespace
}  // namespace weft::ui
