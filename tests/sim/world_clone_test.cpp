// World::clone (issue 21, item 7): the editor's timeline resumes from a cached frame's copy of
// the world, so a copy must step on exactly as the original does, through contact, tearing, a
// grab and BDF2's history, and stepping it must leave the original alone.
#include <gtest/gtest.h>

#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "scene/scene_json.h"
#include "sim/world.h"
#include "support/test_scenes.h"

namespace weft {
namespace {

Scene presetScene(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return loadScene(std::string(WEFT_SOURCE_DIR) + "/presets/scenes/" + name + ".json", overrides);
}

double largestDistance(const World& a, const World& b) {
  double largest = 0.0;
  for (int c = 0; c < a.clothCount(); ++c) {
    const ClothMesh& x = a.cloth(c);
    const ClothMesh& y = b.cloth(c);
    if (x.vertexCount() != y.vertexCount()) return 1e30;
    for (int i = 0; i < x.vertexCount(); ++i) largest = std::max(largest, (x.x[i] - y.x[i]).norm());
  }
  return largest;
}

// Steps `original` `before` steps, copies it, then steps both `after` steps, comparing the state
// hash after every step. Returns the tears made while the two ran side by side.
long long expectCopyStepsAsOriginal(const Scene& scene, int before, int after) {
  World original(scene);
  for (int s = 0; s < before; ++s) original.step();
  const std::unique_ptr<World> copy = original.clone();
  EXPECT_EQ(copy->stateHash(), original.stateHash());
  EXPECT_EQ(copy->stepCount(), original.stepCount());
  EXPECT_EQ(copy->time(), original.time());
  const long long tearsBefore = original.tearStats().tears;
  for (int s = 0; s < after; ++s) {
    original.step();
    copy->step();
    EXPECT_EQ(copy->stateHash(), original.stateHash()) << "after " << before + s + 1 << " steps";
    if (copy->stateHash() != original.stateHash()) break;
  }
  EXPECT_EQ(copy->tearLog().size(), original.tearLog().size());
  EXPECT_EQ(copy->tearStats().tears, original.tearStats().tears);
  EXPECT_EQ(copy->time(), original.time());
  return original.tearStats().tears - tearsBefore;
}

TEST(WorldClone, CopyThroughContactAndTearingStepsBitForBitWithBlockJacobi) {
  Scene scene = presetScene("ball-into-sheet-table4.1-cloth2", {"cloths.0.mesh.grid.resolution=[20,20]"});
  scene.solver.linearPreconditioner = PreconditionerKind::BlockJacobi;
  const long long tears = expectCopyStepsAsOriginal(scene, 30, 60);
  EXPECT_GT(tears, 0) << "the comparison should cover tearing";
}

TEST(WorldClone, CopyOfACutBySharpToolStepsBitForBit) {
  Scene scene = presetScene("sword-into-sheet", {"cloths.0.mesh.grid.resolution=[20,20]"});
  scene.solver.linearSolver = LinearSolverKind::Cholmod;
  expectCopyStepsAsOriginal(scene, 40, 60);
}

TEST(WorldClone, Bdf2HistoryAndGrabAreCopied) {
  Scene scene = test::hangingSheet(test::isotropicMaterial(), 12, 1.0 / 60);
  scene.solver.integrator = IntegratorKind::Bdf2;
  scene.solver.linearPreconditioner = PreconditionerKind::BlockJacobi;
  World original(scene);
  for (int s = 0; s < 5; ++s) original.step();
  original.grab(0, 0, original.cloth(0).x[0] + Vec3(0.0, 0.0, 0.2), 50.0);
  original.step();
  const std::unique_ptr<World> copy = original.clone();
  ASSERT_TRUE(copy->grabState());
  const long long restarts = original.solverStats().bdf2Restarts;
  for (int s = 0; s < 10; ++s) {
    original.step();
    copy->step();
  }
  EXPECT_EQ(copy->stateHash(), original.stateHash());
  // A copy that lost the history would restart BDF2 with a backward Euler step.
  EXPECT_EQ(copy->solverStats().bdf2Restarts, original.solverStats().bdf2Restarts);
  EXPECT_EQ(original.solverStats().bdf2Restarts, restarts);
}

TEST(WorldClone, DefaultLaggedCholeskyCopyAgreesWithinTheSolverTolerance) {
  const Scene scene = presetScene("ball-into-sheet-table4.1-cloth2", {"cloths.0.mesh.grid.resolution=[20,20]"});
  World original(scene);
  for (int s = 0; s < 20; ++s) original.step();
  const std::unique_ptr<World> copy = original.clone();
  for (int s = 0; s < 10; ++s) {
    original.step();
    copy->step();
  }
  EXPECT_LT(largestDistance(original, *copy), 1e-4);  // m
}

TEST(WorldClone, SteppingTheCopyLeavesTheOriginalAlone) {
  const Scene scene = presetScene("ball-into-sheet-table4.1-cloth2", {"cloths.0.mesh.grid.resolution=[16,16]"});
  World original(scene);
  for (int s = 0; s < 10; ++s) original.step();
  const std::uint64_t hash = original.stateHash();
  const std::size_t tears = original.tearLog().size();
  {
    const std::unique_ptr<World> copy = original.clone();
    for (int s = 0; s < 40; ++s) copy->step();
    EXPECT_NE(copy->stateHash(), hash);
  }
  EXPECT_EQ(original.stateHash(), hash);
  EXPECT_EQ(original.tearLog().size(), tears);
  EXPECT_EQ(original.stepCount(), 10);
  original.step();  // and it still steps, its contact bodies pointing at its own cloths
  EXPECT_EQ(original.stepCount(), 11);
}

// World::approximateBytes is what the timeline's budget counts for each cached frame's copy: it
// must be close to the heap the copy really takes (glibc's count of bytes in use, around the
// copy, blocks in the heap and those mapped on their own; the test is single-threaded, so
// nothing else allocates meanwhile).
TEST(WorldMemory, ACopysEstimateIsCloseToTheHeapItTakes) {
  for (const char* name : {"ball-into-sheet-table4.1-cloth2", "sword-into-sheet", "sheet-folds-on-ground", "hanging-sheet"}) {
    World world(presetScene(name));
    for (int s = 0; s < 30; ++s) world.step();
    const auto inUse = [] {
      const struct mallinfo2 m = mallinfo2();
      return m.uordblks + m.hblkhd;
    };
    const std::size_t before = inUse();
    const std::unique_ptr<World> copy = world.clone();
    const std::size_t taken = inUse() - before;
    const double ratio = static_cast<double>(copy->approximateBytes()) / static_cast<double>(taken);
    std::printf("%s: a copy takes %.2f MB, estimated %.2f MB\n", name, taken / 1e6, copy->approximateBytes() / 1e6);
    EXPECT_GT(ratio, 0.8) << name;
    EXPECT_LT(ratio, 1.2) << name;
  }
}

}  // namespace
}  // namespace weft
