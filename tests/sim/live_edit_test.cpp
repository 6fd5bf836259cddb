// Live edits between steps: an edit at t = 0 followed by steps gives exactly the state of a world
// built from the edited scene (the edit refreshes everything derived from the value), edits keep
// the state, and needsReset tells live edits from rebuilds.
#include <gtest/gtest.h>

#include "sim/live_edit.h"
#include "sim/world.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

std::uint64_t hashAfter(World& world, int steps) {
  for (int s = 0; s < steps; ++s) world.step();
  EXPECT_TRUE(world.metrics().finite);
  return world.stateHash();
}

std::uint64_t freshHash(const Scene& scene, int steps) {
  World world(scene);
  return hashAfter(world, steps);
}

Scene sheet() { return test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-5), 8, 1.0 / 60); }

Material denim() { return loadMaterialFile(test::presetPath("11oz-black-denim")); }

TEST(LiveEdit, MaterialAtStartMatchesFreshWorld) {
  const Scene original = sheet();
  Scene edited = original;
  Material& m = edited.cloths[0].material;
  m.elasticity.youngModulus = 800.0;
  m.areaDensity = 0.45;  // the masses change
  m.bending.stiffness = 4e-5;

  World world(original);
  world.setClothMaterial(0, m);
  EXPECT_EQ(world.scene(), edited);
  const std::uint64_t live = hashAfter(world, 30);
  EXPECT_EQ(live, freshHash(edited, 30));
  EXPECT_NE(live, freshHash(original, 30));  // the edit matters
}

TEST(LiveEdit, BendingModelChangeAtStartMatchesFreshWorld) {
  Scene original = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 0.0), 8, 1.0 / 60);  // no hinges
  Scene edited = original;
  edited.cloths[0].material = denim();  // measured bending: hinges appear, the pattern grows
  World world(original);
  world.setClothMaterial(0, edited.cloths[0].material);
  const std::uint64_t live = hashAfter(world, 20);
  EXPECT_EQ(live, freshHash(edited, 20));
  EXPECT_NE(live, freshHash(original, 20));
}

TEST(LiveEdit, WeftAngleAtStartMatchesFreshWorld) {
  Scene original = sheet();
  original.cloths[0].material = denim();
  Scene edited = original;
  edited.cloths[0].weftAngleDeg = 30.0;
  World world(original);
  world.setClothWeftAngle(0, 30.0);
  EXPECT_EQ(world.scene(), edited);
  const std::uint64_t live = hashAfter(world, 30);
  EXPECT_EQ(live, freshHash(edited, 30));
  EXPECT_NE(live, freshHash(original, 30));
}

// A sheet pulled apart along all four edges (tearing_world_test.cpp's biaxial sheet, small).
Scene pulledSheet() {
  Scene scene = test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-5), 10, 1.0 / 240);
  const double e = 0.5 / 9, in = 1.5 / 9, pull = 0.12;
  auto edge = [](Vec2 lo, Vec2 hi, Vec3 by) {
    PinGroup g;
    g.restBox = std::pair(lo, hi);
    g.script = {{0.0, Vec3::Zero()}, {1.0, by}};
    return g;
  };
  scene.cloths[0].pins = {edge({-e, in}, {e, 1 - in}, {-pull, 0, 0}), edge({1 - e, in}, {1 + e, 1 - in}, {pull, 0, 0}),
                          edge({in, -e}, {1 - in, e}, {0, -pull, 0}), edge({in, 1 - e}, {1 - in, 1 + e}, {0, pull, 0})};
  scene.forces.gravity = Vec3::Zero();
  scene.forces.damping.mass = 0.5;
  return scene;
}

TEST(LiveEdit, TearTableAtStartMatchesFreshWorld) {
  const Scene original = pulledSheet();  // no tear table: tearing does not run
  Scene edited = original;
  TearTable weak;
  weak.strength = {1.0};
  weak.unitNPerM = 1e-3;
  edited.cloths[0].material.tearTable = weak;

  World world(original);
  EXPECT_FALSE(world.tearingRuns());
  world.setClothMaterial(0, edited.cloths[0].material);
  EXPECT_TRUE(world.tearingRuns());
  const std::uint64_t live = hashAfter(world, 40);
  EXPECT_GT(world.tearLog().size(), 0u);  // it tore

  World fresh(edited);
  EXPECT_EQ(live, hashAfter(fresh, 40));
  EXPECT_EQ(world.tearLog().size(), fresh.tearLog().size());

  world.setClothMaterial(0, original.cloths[0].material);  // removing the table stops tearing
  EXPECT_FALSE(world.tearingRuns());
  const std::size_t tears = world.tearLog().size();
  hashAfter(world, 10);
  EXPECT_EQ(world.tearLog().size(), tears);
}

TEST(LiveEdit, MidRunEditKeepsStateAndTopology) {
  Scene scene = pulledSheet();
  TearTable weak;
  weak.strength = {1.0};
  weak.unitNPerM = 1e-3;
  scene.cloths[0].material.tearTable = weak;
  World world(scene);
  hashAfter(world, 40);
  const ClothMesh before = world.cloth(0);
  ASSERT_GT(world.tearLog().size(), 0u);
  Material stiffer = scene.cloths[0].material;
  stiffer.elasticity.youngModulus *= 2.0;
  world.setClothMaterial(0, stiffer);
  world.setClothWeftAngle(0, 15.0);
  EXPECT_EQ(world.cloth(0).x, before.x);
  EXPECT_EQ(world.cloth(0).v, before.v);
  EXPECT_EQ(world.cloth(0).vertexCount(), before.vertexCount());
  EXPECT_EQ(world.cloth(0).triangleCount(), before.triangleCount());
  hashAfter(world, 20);  // and it keeps stepping
}

TEST(LiveEdit, SolverAndForcesAreLive) {
  World world(sheet());
  hashAfter(world, 6);
  const double t = world.time();
  SolverSpec solver = world.scene().solver;
  solver.dt = 1.0 / 120;
  solver.integrator = IntegratorKind::Newton;
  solver.linearTolerance = 1e-8;
  world.setSolver(solver);
  ForcesSpec forces = world.scene().forces;
  forces.gravity = Vec3(0, -5, 0);
  world.setForces(forces);
  EXPECT_EQ(world.scene().solver, solver);
  EXPECT_EQ(world.scene().forces, forces);
  hashAfter(world, 12);
  EXPECT_NEAR(world.time(), t + 12.0 / 120, 1e-12);  // time continues from where it was
}

TEST(LiveEdit, NeedsResetForStructureNotForMaterial) {
  const Scene running = sheet();
  Scene edited = running;
  edited.cloths[0].grid->resolutionX = 12;
  EXPECT_TRUE(needsReset(running, edited));

  edited = running;
  edited.cloths[0].material.elasticity.youngModulus = 500.0;
  edited.cloths[0].material.tearTable = TearTable{"t", "", {5.0}, 1.0};
  edited.cloths[0].weftAngleDeg = 45.0;
  edited.cloths[0].appearance.pattern = WeavePattern::Plain;
  edited.forces.wind.velocity = Vec3(2, 0, 0);
  edited.solver.dt = 1.0 / 30;
  edited.output.camera.yawDeg = 90.0;
  edited.name = "renamed";
  EXPECT_FALSE(needsReset(running, edited));
  edited.file = "/elsewhere/saved-as.json";  // the editor's Save as: the next edit still applies live
  EXPECT_FALSE(needsReset(running, edited));

  const auto resets = [&](auto change) {
    Scene s = running;
    change(s);
    return needsReset(running, s);
  };
  EXPECT_TRUE(resets([](Scene& s) { s.cloths[0].placement.translate.y() = 1.0; }));
  EXPECT_TRUE(resets([](Scene& s) { s.cloths[0].pins.clear(); }));
  EXPECT_TRUE(resets([](Scene& s) { s.obstacles.emplace_back(); }));
  EXPECT_TRUE(resets([](Scene& s) { s.ground.enabled = true; }));
  EXPECT_TRUE(resets([](Scene& s) { s.contact.self = true; }));
  EXPECT_TRUE(resets([](Scene& s) { s.stages.bending = false; }));
  EXPECT_TRUE(resets([](Scene& s) { s.tearing.maxTearsPerStep = 3; }));
  EXPECT_TRUE(resets([](Scene& s) { s.cloths.push_back(s.cloths[0]); }));
}

TEST(LiveEdit, ApplyLiveEditsAppliesEveryDifference) {
  Scene original = sheet();
  original.cloths[0].material = denim();
  Scene edited = original;
  edited.cloths[0].material.areaDensity *= 1.5;
  edited.cloths[0].weftAngleDeg = 20.0;
  edited.cloths[0].appearance.color = Vec3(1, 0, 0);
  edited.forces.damping.mass = 0.2;
  edited.output.camera.pitchDeg = 45.0;
  edited.description = "edited";

  World world(original);
  applyLiveEdits(world, edited);
  EXPECT_EQ(world.scene(), edited);
  EXPECT_EQ(hashAfter(world, 20), freshHash(edited, 20));

  Scene rebuilt = edited;
  rebuilt.cloths[0].grid->resolutionY = 5;
  EXPECT_THROW(applyLiveEdits(world, rebuilt), std::invalid_argument);
}

}  // namespace
}  // namespace weft
