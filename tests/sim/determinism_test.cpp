// Same scene, same binary: the same state, whatever the number of threads.
#include <gtest/gtest.h>

#include "sim/world.h"
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

TEST(Determinism, HashChangesWhenTheStateChanges) {
  const Material royal = loadMaterialFile(test::presetPath("royal-target"));
  Scene scene = test::hangingSheet(royal, 8, 1.0 / 60);
  EXPECT_NE(runHash(scene, 1, 3), runHash(scene, 1, 4));
}

}  // namespace
}  // namespace weft
