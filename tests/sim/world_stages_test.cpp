// A scene runs only the stages it needs, and the profile times exactly those.
#include <algorithm>

#include <gtest/gtest.h>

#include "sim/world.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::vector<std::string> profiledStages(Scene scene) {
  World world(scene);
  for (int s = 0; s < 2; ++s) world.step();
  EXPECT_EQ(world.profile().names.size(), world.stagesRun().size());
  for (const std::string& name : world.profile().names) EXPECT_TRUE(contains(world.stagesRun(), name)) << name;
  return world.stagesRun();
}

TEST(WorldStages, NoBendingStageWithoutBendingStiffness) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(1000.0, 0.3, 0.0), 6, 1.0 / 60);
  const auto stages = profiledStages(scene);
  EXPECT_FALSE(contains(stages, "bending"));
  EXPECT_FALSE(contains(stages, "wind"));
  EXPECT_TRUE(contains(stages, "membrane"));
}

TEST(WorldStages, BendingAndWindRunWhenPresent) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(1000.0, 0.3, 1e-5), 6, 1.0 / 60);
  scene.forces.wind.velocity = Vec3(3.0, 0.0, 0.0);
  const auto stages = profiledStages(scene);
  EXPECT_TRUE(contains(stages, "bending"));
  EXPECT_TRUE(contains(stages, "wind"));
}

TEST(WorldStages, StageSwitchesTurnStagesOff) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(1000.0, 0.3, 1e-5), 6, 1.0 / 60);
  scene.forces.wind.velocity = Vec3(3.0, 0.0, 0.0);
  scene.stages.wind = false;
  scene.stages.bending = false;
  scene.stages.gravity = false;
  const auto stages = profiledStages(scene);
  EXPECT_FALSE(contains(stages, "bending"));
  EXPECT_FALSE(contains(stages, "wind"));
  EXPECT_FALSE(contains(stages, "gravity"));
}

TEST(WorldStages, ExplicitIntegratorRunsNoLinearSolve) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(1000.0, 0.3, 0.0), 6, 1.0 / 2000);
  scene.solver.integrator = IntegratorKind::SymplecticEuler;
  const auto stages = profiledStages(scene);
  EXPECT_FALSE(contains(stages, "linear_solve"));
}

}  // namespace
}  // namespace weft
