// Golden image snapshots of every preset scene at a few fixed frames, rendered headless through
// EGL with llvmpipe, and the proof that the comparison catches what it must: a moved cloth, a
// changed colour and a moved camera each fail the golden.
//
// Goldens: tests/ui/snapshots/<scene>/frame_NNNN.png, with tests/ui/snapshots/RENDERER.txt
// recording the GL_RENDERER and settings they were drawn with. Metric (tests/support/snapshot.h):
// a pixel differs when a channel differs by more than 8/255; at most 0.2% of the pixels may.
// Regenerate with scripts/bless_snapshots.sh, then look at the images before committing them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "headless_gl_context.h"
#include "offscreen_framebuffer.h"
#include "scene/scene.h"
#include "scene/scene_json.h"
#include "scene_renderer.h"
#include "sim/world.h"
#include "support/snapshot.h"

namespace weft::ui {
namespace {

namespace fs = std::filesystem;

// Small images keep the suite fast; 4x MSAA keeps edges stable under sub-pixel motion.
constexpr int kWidth = 240;
constexpr int kHeight = 180;

// Frames captured per scene: the start, early motion and the action a second in. Later frames of
// the tearing scenes depend on individual tear decisions, which a different libm could flip.
const std::vector<int> kFrames{0, 6, 24};

fs::path snapshotDir() { return fs::path(WEFT_SOURCE_DIR) / "tests" / "ui" / "snapshots"; }
fs::path sceneDir() { return fs::path(WEFT_SOURCE_DIR) / "presets" / "scenes"; }

std::vector<std::string> presetSceneNames() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(sceneDir())) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class SceneSnapshotTest : public ::testing::TestWithParam<std::string> {
 protected:
  static void SetUpTestSuite() {
    // llvmpipe at a fixed vector width draws the same pixels on every x86-64 CPU, with or without
    // AVX; softpipe or a GPU would draw others.
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    setenv("LP_NATIVE_VECTOR_WIDTH", "128", 1);
    try {
      context_ = std::make_unique<HeadlessGlContext>();
      renderer_ = std::make_unique<SceneRenderer>();
    } catch (const GlContextError& e) {
      skipReason_ = std::string("headless OpenGL (EGL surfaceless) cannot start here: ") + e.what();
    }
  }
  static void TearDownTestSuite() {
    renderer_.reset();
    context_.reset();
  }
  void SetUp() override {
    if (!context_) GTEST_SKIP() << skipReason_;
  }

  // The default framing is fixed at frame 0, as `weft run --png` fixes it, so that a golden also
  // catches a camera that moved.
  static OrbitCamera defaultCamera(const World& world) {
    return ui::defaultCamera(renderViewOf(world), world.scene().output.camera, static_cast<double>(kWidth) / kHeight);
  }

  static test::RgbaImage render(const World& world, const OrbitCamera& camera) {
    OffscreenFramebuffer framebuffer(kWidth, kHeight, 4);
    framebuffer.bind();
    renderer_->draw(renderViewOf(world), camera, kWidth, kHeight);
    return test::RgbaImage{kWidth, kHeight, framebuffer.readPixels()};
  }

  static void advanceToFrame(World& world, int frame) {
    const long long steps = static_cast<long long>(frame) * stepsPerFrame(world.scene());
    while (world.stepCount() < steps) world.step();
  }

  static fs::path golden(const std::string& scene, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    return snapshotDir() / scene / name;
  }

  static inline std::unique_ptr<HeadlessGlContext> context_;
  static inline std::unique_ptr<SceneRenderer> renderer_;
  static inline std::string skipReason_;
};

TEST_P(SceneSnapshotTest, PresetSceneMatchesItsGoldens) {
  const std::string name = GetParam();
  World world(loadScene(sceneDir() / (name + ".json")));
  const OrbitCamera camera = defaultCamera(world);
  for (int frame : kFrames) {
    advanceToFrame(world, frame);
    const std::string problem = test::checkSnapshot(render(world, camera), golden(name, frame));
    EXPECT_EQ(problem, "") << name << " frame " << frame << " (drawn by " << context_->glRenderer()
                           << "; goldens by the renderer in " << (snapshotDir() / "RENDERER.txt").string() << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(PresetScenes, SceneSnapshotTest, ::testing::ValuesIn(presetSceneNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string id = info.param;
                           std::replace_if(id.begin(), id.end(), [](char c) { return !std::isalnum(c); }, '_');
                           return id;
                         });

// The goldens' provenance, rewritten with them: a mismatch on another machine can then be told
// apart from a change in the code.
TEST_F(SceneSnapshotTest, SnapshotRendererIsRecorded) {
  const fs::path sidecar = snapshotDir() / "RENDERER.txt";
  const std::string current = "GL_RENDERER: " + context_->glRenderer() +
                              "\nGALLIUM_DRIVER=llvmpipe LP_NATIVE_VECTOR_WIDTH=128\nsize: " +
                              std::to_string(kWidth) + "x" + std::to_string(kHeight) + ", 4x MSAA\n";
  if (test::blessing()) {
    fs::create_directories(snapshotDir());
    std::ofstream(sidecar) << current;
  }
  std::ifstream in(sidecar);
  ASSERT_TRUE(in) << "no " << sidecar << "; run scripts/bless_snapshots.sh";
  const std::string recorded((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(recorded.find("llvmpipe"), std::string::npos) << "goldens must be drawn by llvmpipe: " << recorded;
  if (recorded != current) {
    std::cout << "note: goldens were drawn by\n" << recorded << "this machine draws with\n" << current;
  }
}

// An altered scene must fail the same comparison the goldens pass. Compared in memory: nothing
// is written beside the goldens.
class AlteredSceneTest : public SceneSnapshotTest {
 protected:
  static test::ImageDifference differenceFromGolden(const std::vector<std::string>& overrides,
                                                    double extraYawDeg = 0.0) {
    const std::string name = "hanging-sheet";
    const int frame = kFrames[1];
    World original(loadScene(sceneDir() / (name + ".json")));
    OrbitCamera camera = defaultCamera(original);  // the golden's camera, from the unaltered scene
    camera.yawDeg += extraYawDeg;
    World altered(loadScene(sceneDir() / (name + ".json"), overrides));
    advanceToFrame(altered, frame);
    const test::RgbaImage goldenImage = test::readPng(golden(name, frame));
    EXPECT_FALSE(goldenImage.empty()) << "no golden " << golden(name, frame);
    return test::compareImages(goldenImage, render(altered, camera), test::SnapshotTolerance{}.channelThreshold);
  }

  static void expectFails(const test::ImageDifference& d) {
    ASSERT_TRUE(d.sameSize);
    EXPECT_GT(d.differingFraction, test::SnapshotTolerance{}.maxDifferingFraction);
  }
};

TEST_F(AlteredSceneTest, UnalteredSceneMatches) {
  if (test::blessing()) GTEST_SKIP() << "blessing";
  const test::ImageDifference d = differenceFromGolden({});
  ASSERT_TRUE(d.sameSize);
  EXPECT_LE(d.differingFraction, test::SnapshotTolerance{}.maxDifferingFraction);
}

TEST_F(AlteredSceneTest, MovedClothFailsItsSnapshot) {
  if (test::blessing()) GTEST_SKIP() << "blessing";
  const test::ImageDifference d = differenceFromGolden({"cloths.0.placement.translate=[-0.45,1.0,0.5]"});  // 5 cm
  expectFails(d);
  std::cout << "cloth moved 5 cm: " << 100.0 * d.differingFraction << "% of the pixels differ\n";
}

TEST_F(AlteredSceneTest, RecolouredClothFailsItsSnapshot) {
  if (test::blessing()) GTEST_SKIP() << "blessing";
  const test::ImageDifference d = differenceFromGolden({"cloths.0.appearance.color=[0.22,0.40,0.70]"});
  expectFails(d);
  std::cout << "cloth recoloured: " << 100.0 * d.differingFraction << "% of the pixels differ\n";
}

TEST_F(AlteredSceneTest, TurnedCameraFailsItsSnapshot) {
  if (test::blessing()) GTEST_SKIP() << "blessing";
  const test::ImageDifference d = differenceFromGolden({}, 3.0);
  expectFails(d);
  std::cout << "camera turned 3 degrees: " << 100.0 * d.differingFraction << "% of the pixels differ\n";
}

TEST_F(AlteredSceneTest, MissingClothFailsItsSnapshot) {
  if (test::blessing()) GTEST_SKIP() << "blessing";
  // The cloth far outside the view: the image shows only the background.
  const test::ImageDifference d = differenceFromGolden({"cloths.0.placement.translate=[100,1.0,0.5]"});
  expectFails(d);
}

}  // namespace
}  // namespace weft::ui
