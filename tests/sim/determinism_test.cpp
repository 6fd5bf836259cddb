// Same scene, same binary: the same state, whatever the number of threads.
#include <gtest/gtest.h>

#include "sim/world.h"
#include "support/tear_scenes.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

std::uint64_t runHash(Scene scene, int threads, int steps) {
  scene.solver.threads = threads;
  World world(scene);
  for (int s = 0; s < steps; ++s) world.step();
  return world.stateHash();
}

TEST(Determinism, StateHashDoesNotDependOnThreadCountOrRun) {
  const Material royal = loadMaterialFile(test::presetPath("royal-target"));
  Scene scene = test::hangingSheet(royal, 16, 1.0 / 60);
  scene.forces.wind.velocity = Vec3(2.0, 0.0, 1.0);
  for (IntegratorKind kind : {IntegratorKind::LinearizedBackwardEuler, IntegratorKind::Newton}) {
    scene.solver.integrator = kind;
    const std::uint64_t reference = runHash(scene, 1, 20);
    EXPECT_EQ(runHash(scene, 1, 20), reference);
    EXPECT_EQ(runHash(scene, 2, 20), reference);
    EXPECT_EQ(runHash(scene, 4, 20), reference);
  }
}

// Tearing too: its averaged stress is computed on the step's threads (tear_stage.h), and the
// membrane evaluated ahead for it (forces/membrane_ahead.h) as well.
TEST(Determinism, ATearingSheetTearsTheSameWhateverTheThreadCount) {
  const Scene scene = test::biaxialSheet(24, test::tearTable({1.0, 2.0, 2.0, 2.0}, 300.0), 30.0, true);
  std::vector<std::vector<TearRecord>> logs;
  std::vector<std::uint64_t> hashes;
  for (int threads : {1, 2, 4}) {
    Scene threaded = scene;
    threaded.solver.threads = threads;
    World world(threaded);
    for (int s = 0; s < 70; ++s) world.step();
    logs.push_back(world.tearLog());
    hashes.push_back(world.stateHash());
  }
  ASSERT_FALSE(logs[0].empty()) << "the sheet should tear in this time";
  for (std::size_t k = 1; k < logs.size(); ++k) {
    EXPECT_EQ(hashes[k], hashes[0]) << k;
    ASSERT_EQ(logs[k].size(), logs[0].size()) << k;
    for (std::size_t i = 0; i < logs[0].size(); ++i) {
      EXPECT_EQ(logs[k][i].vertex, logs[0][i].vertex);
      EXPECT_EQ(logs[k][i].ratio, logs[0][i].ratio);
    }
  }
}

TEST(Determinism, HashChangesWhenTheStateChanges) {
  const Material royal = loadMaterialFile(test::presetPath("royal-target"));
  Scene scene = test::hangingSheet(royal, 8, 1.0 / 60);
  EXPECT_NE(runHash(scene, 1, 3), runHash(scene, 1, 4));
}

}  // namespace
}  // namespace weft
