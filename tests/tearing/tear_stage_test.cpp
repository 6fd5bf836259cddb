// The tearing stage's choices within one step: no stall when the mesh refuses a line, and crack
// tips that need less than intact cloth (initiation against propagation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "support/tear_scenes.h"
#include "support/test_scenes.h"
#include "tearing/tear_mesh.h"
#include "tearing/tear_stage.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

constexpr double kDt = 1.0 / 240;

// An 11 x 11 sheet (0.1 m cells) of the isotropic test material. These tests read single steps
// of the stage: in the one-pass mode a line tears in the step it is found, by its own fan's
// stress (the default's incubation would hold every start for 0.06 s).
Scene sheetScene(const TearTable& tears) {
  Scene scene = test::inOnePassMode(test::hangingSheet(test::isotropicMaterial(2000.0, 0.3, 1e-5), 11, kDt));
  scene.cloths[0].material.tearTable = tears;
  scene.cloths[0].pins.clear();
  return scene;
}

// Positions from the rest shape stretched by `stretch` in both directions, plus a bulge of extra
// stretch `bump` around `centre` (material space), so that the vertex there is the most loaded.
void prestress(Cloth& cloth, double stretch, double bump = 0.0, Vec2 centre = Vec2(0.5, 0.5)) {
  for (const Triangle& t : cloth.mesh.tris) {
    for (int k = 0; k < 3; ++k) {
      const Vec2 r = t.rest[k];
      const Vec2 d = r - centre;
      const Vec2 p = (1.0 + stretch) * r + bump * std::exp(-d.squaredNorm() / 0.02) * d;
      cloth.mesh.x[t.v[k]] = Vec3(p.x(), p.y(), 0.0);
    }
  }
}

// The separation strength of the most loaded line of the cloth (a table that tears at anything).
double largestSeparation(const Cloth& cloth) {
  Scene scene = sheetScene(test::tearTable({1.0}, 1e-6));
  Cloth probe = cloth;
  probe.material.tearTable = scene.cloths[0].material.tearTable;
  TearStage stage(scene);
  std::vector<Cloth> cloths{probe};
  StageProfile profile;
  stage.run(cloths, 0.0, kDt, profile);
  return stage.log().empty() ? 0.0 : stage.log().front().separation;
}

int vertexAt(const ClothMesh& mesh, const Vec2& rest) {
  for (const Triangle& t : mesh.tris) {
    for (int k = 0; k < 3; ++k) {
      if ((t.rest[k] - rest).norm() < 1e-9) return t.v[k];
    }
  }
  return kNone;
}

// Cuts a notch from the bottom border's middle, three cells up; returns its tip.
int cutNotch(Cloth& cloth) {
  int tip = vertexAt(cloth.mesh, Vec2(0.5, 0.0));
  for (int k = 0; k < 3; ++k) {
    TopologyChange change;
    EXPECT_TRUE(tearThroughVertex(cloth.mesh, tip, Vec2(0, 1), TearGuards{}, cloth.material.areaDensity, change));
    applyTopologyChange(cloth, change);
    tip = change.crackEnds.at(0);
  }
  return tip;
}

// The most loaded vertex's only line runs 10 degrees from its edges (a sliver to cross) and every
// neighbour is pinned (nothing to move onto the line): the mesh refuses it. The stage then tries
// the next vertex in the same step instead of stalling (the old stage tore nothing that step, and
// in some runs never again).
TEST(TearStage, ALineTheMeshRefusesIsPassedOverForTheNextVertexInTheSameStep) {
  // Weak only along the warp, which runs at 80 degrees in material space (weft at -10).
  const Scene scene = sheetScene(test::tearTable({1.0, 3.0, 3.0, 3.0}, 1.0));
  Cloth cloth = buildCloth(scene.cloths[0], "test", 0);
  cloth.weftAngleRad = degToRad(-10.0);
  rebuildElements(cloth);
  prestress(cloth, 0.05, 0.03);
  const int loaded = vertexAt(cloth.mesh, Vec2(0.5, 0.5));
  // The most loaded line along the weak direction, read with the same table scaled down to nothing.
  Scene probe = scene;
  probe.cloths[0].material.tearTable = test::tearTable({1.0, 3.0, 3.0, 3.0}, 1e-6);
  cloth.material.tearTable = probe.cloths[0].material.tearTable;
  double zeta = 0.0;
  {
    TearStage stage(probe);
    std::vector<Cloth> cloths{cloth};
    StageProfile profile;
    stage.run(cloths, 0.0, kDt, profile);
    ASSERT_FALSE(stage.log().empty());
    zeta = stage.log()[0].separation;
  }
  ASSERT_GT(zeta, 10.0);
  Scene tearing = scene;
  tearing.cloths[0].material.tearTable = test::tearTable({1.0, 3.0, 3.0, 3.0}, 0.8 * zeta);
  cloth.material.tearTable = tearing.cloths[0].material.tearTable;

  // Without the pins the most loaded vertex tears first...
  {
    TearStage stage(tearing);
    std::vector<Cloth> cloths{cloth};
    StageProfile profile;
    stage.run(cloths, 0.0, kDt, profile);
    ASSERT_EQ(stage.log().size(), 1u);
    EXPECT_EQ(stage.log()[0].vertex, loaded);
    EXPECT_NEAR(stage.log()[0].angleDeg, 80.0, 1.0);
  }
  // ...with them it is refused, and another vertex tears in the same step.
  const VertexFan fan = walkFan(cloth.mesh, loaded, findTriangleAt(cloth.mesh, loaded));
  for (int t : fan.triangles) {
    for (int v : cloth.mesh.tris[t].v) cloth.mesh.pinned[v] = v != loaded;
  }
  TearStage stage(tearing);
  std::vector<Cloth> cloths{cloth};
  StageProfile profile;
  stage.run(cloths, 0.0, kDt, profile);
  EXPECT_GE(stage.stats().refused, 1);
  ASSERT_EQ(stage.log().size(), 1u);
  EXPECT_NE(stage.log()[0].vertex, loaded);
  EXPECT_GT(stage.log()[0].ratio, 1.0);
}

// Initiation against propagation: under the same load, an intact sheet holds, and a notched one
// tears on from the notch's tip, which needs only the table's propagation factor times its
// strength. With a factor of 1 (today's presets) the notch holds too. (A tip's zeta is twice the
// uniform traction across its ray: an open fan is scaled as a straight border is, as in ARCSim,
// which acts as a stress concentration of 2 at every crack tip; the intact sheet is loaded to 40%
// of its strength so that the tip is at 80% of it.)
TEST(TearStage, ANotchRunsWhereAnIntactSheetHoldsWhenTipsNeedLessStrength) {
  const Scene scene = sheetScene(test::tearTable({1.0}, 1.0));
  const Cloth intact = buildCloth(scene.cloths[0], "test", 0);
  Cloth notched = intact;
  const int tip = cutNotch(notched);  // three cells up from the bottom border's middle
  Cloth loaded = intact;
  prestress(loaded, 0.05);
  const double zeta = largestSeparation(loaded);
  ASSERT_GT(zeta, 10.0);

  for (const double factor : {0.5, 1.0}) {
    TearTable table = test::tearTable({1.0}, zeta / 0.4);  // the intact sheet is at 40% of its strength
    table.propagationFactor = factor;
    Scene tearing = scene;
    tearing.cloths[0].material.tearTable = table;
    for (const bool withNotch : {false, true}) {
      Cloth cloth = withNotch ? notched : intact;
      cloth.material.tearTable = table;
      prestress(cloth, 0.05);
      TearStage stage(tearing);
      std::vector<Cloth> cloths{cloth};
      StageProfile profile;
      stage.run(cloths, 0.0, kDt, profile);
      if (withNotch && factor < 1.0) {
        ASSERT_EQ(stage.log().size(), 1u) << "the notch should run on";
        EXPECT_EQ(stage.log()[0].vertex, tip);
        EXPECT_NEAR(stage.log()[0].ratio, 0.8 / factor, 0.05);  // 2 x 40% / factor
        EXPECT_NEAR(std::fmod(stage.log()[0].angleDeg + 360.0, 180.0), 90.0, 1.0);  // on, across the load
      } else {
        EXPECT_TRUE(stage.log().empty()) << (withNotch ? "notched" : "intact") << ", factor " << factor;
      }
    }
  }
}

// Where the torn edges of a cloth lie: the highest rest y any of them reaches, and how many join
// two pinned vertices.
struct TornEdges {
  int count = 0;
  int bothEndsPinned = 0;
  double highestRestY = -1.0;
};
TornEdges tornEdges(const ClothMesh& mesh) {
  TornEdges torn;
  for (const Edge& edge : mesh.edges) {
    if (!edge.torn) continue;
    ++torn.count;
    torn.bothEndsPinned += mesh.pinned[edge.v[0]] && mesh.pinned[edge.v[1]];
    const Triangle& t = mesh.tris[edge.tri[0]];
    for (int v : edge.v) torn.highestRestY = std::max(torn.highestRestY, t.rest[cornerOf(t, v)].y());
  }
  return torn;
}

// A line whose two ends are pinned never tears: cloth held in a clamp's jaws cannot open. The
// sheet is stretched and then clamped along its top four rows (rest y >= 0.7: the jaws hold it
// stretched, so the triangles between pinned vertices carry the same load as the free ones); a
// notch runs up from the bottom border, step after step, as in the test above. It tears right up
// to the clamp's edge (the first pinned row) and stops there: no torn edge joins two pinned
// vertices. (Without the rule it runs on through the jaws to the top border.)
TEST(TearStage, ACrackRunsUpToAClampsEdgeAndNotIntoTheJaws) {
  Scene scene = sheetScene(test::tearTable({1.0}, 1.0));
  const double e = 0.01;
  PinGroup clamp;
  clamp.restBox = std::pair(Vec2(-e, 0.7 - e), Vec2(1.0 + e, 1.0 + e));
  scene.cloths[0].pins = {clamp};
  Cloth cloth = buildCloth(scene.cloths[0], "test", 0);
  ASSERT_EQ(cloth.pins.size(), 1u);
  ASSERT_EQ(cloth.pins[0].vertices.size(), 44u);  // four rows of eleven
  const int tip = cutNotch(cloth);  // three cells up from the bottom border's middle
  Cloth intact = buildCloth(sheetScene(test::tearTable({1.0}, 1.0)).cloths[0], "test", 0);
  prestress(intact, 0.05);
  const double zeta = largestSeparation(intact);
  ASSERT_GT(zeta, 10.0);
  Cloth loaded = cloth;
  prestress(loaded, 0.05);
  TearTable table = test::tearTable({1.0}, zeta / 0.4);  // the intact sheet is at 40% of its strength
  table.propagationFactor = 0.5;                         // the notch's tip at 160%
  scene.cloths[0].material.tearTable = table;
  loaded.material.tearTable = table;

  TearStage stage(scene);
  std::vector<Cloth> cloths{loaded};
  StageProfile profile;
  for (int step = 0; step < 30; ++step) {
    const std::size_t before = stage.log().size();
    stage.run(cloths, step * kDt, kDt, profile);
    if (stage.log().size() == before) break;
  }
  const TornEdges torn = tornEdges(cloths[0].mesh);
  ASSERT_GE(stage.log().size(), 4u);  // 0.3 -> 0.4 -> 0.5 -> 0.6 -> 0.7
  EXPECT_EQ(torn.bothEndsPinned, 0) << torn.count << " torn edges, up to rest y " << torn.highestRestY;
  EXPECT_NEAR(torn.highestRestY, 0.7, 1e-9);  // up to the first pinned row, not a row short of it
  EXPECT_GE(stage.stats().refused, 1);        // the lines into the jaws, refused
  EXPECT_TRUE(std::all_of(stage.log().begin(), stage.log().end(), [](const TearRecord& r) { return r.ratio > 1.0; }));
}

// Sampled initiation (tearing.initiation_every = k): new cracks are looked for every k-th step;
// between samples a cloth that tore in the step before runs its cracks on, and nothing new starts.
// The intact sheet is loaded to 120% of its strength everywhere: with k = 1 it starts a crack in
// the first loaded step; with k = 3 not before the next sample (steps count from the stage's
// first run, a calm step here).
TEST(TearStage, NewCracksAreLookedForOnlyAtSampleSteps) {
  Cloth intact = buildCloth(sheetScene(test::tearTable({1.0}, 1.0)).cloths[0], "test", 0);
  prestress(intact, 0.05);
  const double zeta = largestSeparation(intact);
  ASSERT_GT(zeta, 10.0);
  const TearTable table = test::tearTable({1.0}, zeta / 1.2);
  Cloth calm = buildCloth(sheetScene(table).cloths[0], "test", 0);
  intact.material.tearTable = table;
  for (const int every : {1, 3}) {
    Scene scene = sheetScene(table);
    scene.tearing.initiationEvery = every;
    TearStage stage(scene);
    std::vector<Cloth> cloths{calm};
    StageProfile profile;
    stage.run(cloths, 0.0, kDt, profile);
    ASSERT_TRUE(stage.log().empty());
    cloths[0] = intact;
    int firstTearStep = -1;
    for (int step = 1; step <= 4 && firstTearStep < 0; ++step) {
      stage.run(cloths, step * kDt, kDt, profile);
      if (!stage.log().empty()) firstTearStep = step;
    }
    EXPECT_EQ(firstTearStep, every == 1 ? 1 : 3) << "initiation_every " << every;
  }
}

// Between samples a crack that ran in the step before runs on from its tip, and nothing new
// starts. A notch's tip at 160% of its strength tears in the first step (a sample); before the
// second, a bulge of stretch far from the notch overloads the intact cloth there more than the
// tip. One tear a step: with k = 1 the second step starts a crack at the bulge (the best ratio);
// with k = 4 it is not a sample and the notch runs on instead.
TEST(TearStage, BetweenSamplesARunningCrackRunsOnAndNothingNewStarts) {
  Scene scene = sheetScene(test::tearTable({1.0}, 1.0));
  Cloth notched = buildCloth(scene.cloths[0], "test", 0);
  const int tip = cutNotch(notched);  // three cells up from the bottom border's middle
  Cloth intact = buildCloth(scene.cloths[0], "test", 0);
  prestress(intact, 0.05);
  const double zeta = largestSeparation(intact);
  ASSERT_GT(zeta, 10.0);
  TearTable table = test::tearTable({1.0}, zeta / 0.4);  // the intact sheet at 40% of its strength
  table.propagationFactor = 0.5;                         // the notch's tip at 160%
  scene.cloths[0].material.tearTable = table;
  prestress(notched, 0.05);
  notched.material.tearTable = table;
  const Vec2 bulge(0.2, 0.6);

  for (const int every : {1, 4}) {
    scene.tearing.initiationEvery = every;
    TearStage stage(scene);
    std::vector<Cloth> cloths{notched};
    StageProfile profile;
    stage.run(cloths, 0.0, kDt, profile);
    ASSERT_EQ(stage.log().size(), 1u);
    ASSERT_EQ(stage.log()[0].vertex, tip);
    prestress(cloths[0], 0.05, 0.3, bulge);
    stage.run(cloths, kDt, kDt, profile);
    ASSERT_EQ(stage.log().size(), 2u) << "initiation_every " << every;
    const TearRecord& second = stage.log()[1];
    if (every == 1) {
      EXPECT_LT((second.restPosition - bulge).norm(), 0.15) << "the bulge starts a crack when every step is a sample";
    } else {
      EXPECT_NEAR(second.restPosition.x(), 0.5, 1e-3) << "the notch runs on";
      EXPECT_NEAR(second.restPosition.y(), 0.4, 1e-3);
    }
  }
}

// Crack speed is a tip's: a crack started through an interior vertex runs from both its tips at
// once, each up to crack_speed * dt a step (the speed a crack from the border runs its one tip
// at). The sheet is stretched across its vertical lines, most at its centre, so a crack starts
// there, vertically, and its tips then run on through cloth at 60-70% of its strength (a tip reads
// about twice the far field: the run-on ratio 0.5 is passed). Each tip may run 0.25 m in the step:
// two and a half cells, so it tears three (its third starts within the budget), 0.3 m each way.
// (With one budget shared by the two tips, 0.2 m each way.)
TEST(TearStage, EachTipOfACrackStartedInsideTheSheetRunsAtTheCrackSpeed) {
  const auto stretchAcross = [](Cloth& cloth, double bump) {
    const Vec2 centre(0.5, 0.5);
    for (const Triangle& t : cloth.mesh.tris) {
      for (int k = 0; k < 3; ++k) {
        const Vec2 r = t.rest[k];
        const Vec2 d = r - centre;
        const double x = 1.05 * r.x() + bump * std::exp(-d.squaredNorm() / 0.02) * d.x();
        cloth.mesh.x[t.v[k]] = Vec3(x, r.y(), 0.0);
      }
    }
  };
  Cloth uniform = buildCloth(sheetScene(test::tearTable({1.0}, 1.0)).cloths[0], "test", 0);
  Cloth bumped = uniform;
  stretchAcross(uniform, 0.0);
  stretchAcross(bumped, 0.03);
  const double farField = largestSeparation(uniform), centre = largestSeparation(bumped);
  ASSERT_GT(farField, 10.0);
  const TearTable table = test::tearTable({1.0}, centre / 1.2);  // the centre at 120% of its strength
  ASSERT_GT(farField / weakestStrength(table), 0.3);  // a tip at twice the far field reads at least 0.6
  Scene scene = sheetScene(table);
  scene.tearing.propagate = true;
  scene.tearing.crackSpeed = 0.25 / kDt;
  bumped.material.tearTable = table;

  TearStage stage(scene);
  std::vector<Cloth> cloths{bumped};
  StageProfile profile;
  stage.run(cloths, 0.0, kDt, profile);
  ASSERT_FALSE(stage.log().empty());
  EXPECT_NEAR(stage.log()[0].restPosition.x(), 0.5, 1e-9);
  EXPECT_NEAR(stage.log()[0].restPosition.y(), 0.5, 1e-9);
  double lowest = 1.0, highest = 0.0;
  for (const Edge& edge : cloths[0].mesh.edges) {
    if (!edge.torn) continue;
    const Triangle& t = cloths[0].mesh.tris[edge.tri[0]];
    for (int v : edge.v) {
      const Vec2 rest = t.rest[cornerOf(t, v)];
      EXPECT_NEAR(rest.x(), 0.5, 1e-5);  // one vertical crack (the surgery may move a vertex onto it)
      lowest = std::min(lowest, rest.y());
      highest = std::max(highest, rest.y());
    }
  }
  EXPECT_NEAR(highest - 0.5, 0.3, 1e-6) << stage.log().size() << " tears";
  EXPECT_NEAR(0.5 - lowest, 0.3, 1e-6) << stage.log().size() << " tears";
}

}  // namespace
}  // namespace weft
