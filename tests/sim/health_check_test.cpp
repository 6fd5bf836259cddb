// The health check: a run that stays finite but stops being a simulation of cloth is caught at
// the step it happens, with the check and the stage named; a sound run passes every check.
#include "sim/health_check.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "material/material.h"
#include "scene/scene_json.h"
#include "sim/finite_state.h"
#include "sim/world.h"
#include "support/temp_dir.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

// Steps `world` until the check fails or `steps` are done; returns the steps taken.
std::int64_t run(World& world, HealthCheck& health, int steps) {
  for (int s = 0; s < steps; ++s) {
    world.step();
    if (!health.afterStep(world)) break;
  }
  return world.stepCount();
}

TEST(HealthCheck, ASoundRunPassesEveryCheck) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(), 12, 1.0 / 60);
  World world(scene);
  HealthCheck health(world, 2);
  EXPECT_EQ(run(world, health, 120), 120);
  EXPECT_TRUE(health.checkNow(world));
  EXPECT_TRUE(health.healthy());
}

TEST(HealthCheck, StrainFarPastAnyFabricFailsAtTheFirstFrame) {
  // The 1 m OBJ sheet with its UVs read as millimetres (uv_scale 1e-3): rest shapes a thousand
  // times smaller than the sheet, a Green strain of 5e5 from the start, finite all along.
  Scene scene = test::hangingSheet(test::isotropicMaterial(), 8, 1.0 / 60);
  scene.cloths[0].grid.reset();
  ObjSpec obj;
  obj.path = std::string(WEFT_SOURCE_DIR) + "/assets/meshes/square_sheet.obj";
  obj.uvScale = 1.0;
  scene.cloths[0].obj = obj;
  World sound(scene);
  HealthCheck unscaled(sound, 2);
  EXPECT_EQ(run(sound, unscaled, 4), 4);
  EXPECT_TRUE(unscaled.healthy()) << "the sheet itself is sound";

  scene.cloths[0].obj->uvScale = 1e-3;
  World world(scene);
  HealthCheck health(world, 2);
  run(world, health, 20);
  ASSERT_FALSE(health.healthy());
  EXPECT_EQ(health.failure()->check, "strain");
  EXPECT_EQ(health.failure()->stage, "membrane");
  EXPECT_EQ(health.failure()->step, 2);
  EXPECT_GT(health.failure()->value, 1e5);
  EXPECT_NE(health.failure()->message.find("solver.dt"), std::string::npos);
  EXPECT_TRUE(stateIsFinite(world));
}

TEST(HealthCheck, LinearSolvesThatAllFailAreCaught) {
  // One CG iteration against a tolerance no solve reaches: every solve fails, the run still looks
  // finite and calm (the cloth barely moves).
  Scene scene = test::hangingSheet(test::isotropicMaterial(), 12, 1.0 / 60);
  scene.solver.linearMaxIterations = 1;
  scene.solver.linearTolerance = 1e-14;
  World world(scene);
  HealthCheck health(world, 2);
  EXPECT_EQ(run(world, health, 20), 3);
  ASSERT_FALSE(health.healthy());
  EXPECT_EQ(health.failure()->check, "linear-solve");
  EXPECT_TRUE(stateIsFinite(world));
}

TEST(HealthCheck, NewtonStoppedFarFromConvergenceIsCaught) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(), 12, 1.0 / 60);
  scene.solver.integrator = IntegratorKind::Newton;
  scene.solver.newtonMaxIterations = 1;
  scene.solver.newtonTolerance = 1e-9;
  World world(scene);
  HealthCheck health(world, 2);
  EXPECT_EQ(run(world, health, 20), 3);
  ASSERT_FALSE(health.healthy());
  EXPECT_EQ(health.failure()->check, "newton");
  EXPECT_GT(health.failure()->value, health.failure()->limit);

  // Converged Newton on the same scene passes.
  scene.solver.newtonMaxIterations = 20;
  scene.solver.newtonTolerance = 1e-6;
  World converged(scene);
  HealthCheck fine(converged, 2);
  EXPECT_EQ(run(converged, fine, 20), 20);
}

TEST(HealthCheck, AnUnstableExplicitRunIsCaughtBeforeItIsNonFinite) {
  // Symplectic Euler far past its stability limit: energy and strain grow without bound and the
  // state turns NaN some steps later. The check must stop it while it is still finite.
  Scene scene = test::hangingSheet(test::isotropicMaterial(2e5, 0.3, 0.0), 16, 1.0 / 60);
  scene.solver.integrator = IntegratorKind::SymplecticEuler;
  World world(scene);
  HealthCheck health(world, 1);
  run(world, health, 400);
  ASSERT_FALSE(health.healthy()) << "ran 400 steps unnoticed";
  EXPECT_TRUE(stateIsFinite(world)) << "caught only once non-finite, by " << health.failure()->check;
  const std::string check = health.failure()->check;
  EXPECT_TRUE(check == "energy" || check == "strain" || check == "speed") << check;
  char limit[32];
  std::snprintf(limit, sizeof limit, "%.3g", health.failure()->limit);
  EXPECT_NE(health.failure()->message.find(limit), std::string::npos)
      << "the message states the limit: " << health.failure()->message;
}


TEST(HealthCheck, ADynamicTetrahedronFlungAwayIsCaught) {
  // Issue 19's case: ball-on-pinned-sheet with its ball replaced by a valid 10 cm tetrahedron of
  // 0.2 kg. From about 0.75 s the contact with the sheet pumps energy into it (strain in the
  // millions, the body 60 km away by the end) while everything stays finite.
  test::TempDir dir;
  dir.write("tet.obj", "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  std::ifstream preset(std::string(WEFT_SOURCE_DIR) + "/presets/scenes/ball-on-pinned-sheet.json");
  nlohmann::json scene = nlohmann::json::parse(preset);
  scene["name"] = "tetrahedron-on-pinned-sheet";
  scene["obstacles"][0]["shape"] = {{"mesh", {{"path", (dir.path() / "tet.obj").string()}}}};
  World world(loadScene(dir.write("scene.json", scene.dump())));
  HealthCheck health(world, stepsPerFrame(world.scene()));  // checked per frame, as weft run does
  run(world, health, 120);
  ASSERT_FALSE(health.healthy()) << "120 steps (1 s) unnoticed";
  EXPECT_LT(health.failure()->time, 0.9);
  EXPECT_EQ(health.failure()->check, "energy") << health.failure()->message;
  EXPECT_TRUE(stateIsFinite(world));
}

}  // namespace
}  // namespace weft
