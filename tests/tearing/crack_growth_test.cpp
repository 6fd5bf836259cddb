// Crack growth against resolution (the tearing issue's goal 4): the same scene at 32^2, 48^2 and
// 64^2 must start tearing at the same time and have torn the same length after a fixed time, within
// 10%; and tears per metre of crack may grow only as the element count does.
//
// Measured in the mode built for it: cracks run on within a step (propagate), the stress is read
// averaged over 6.5 cm (stress_length_m), lips left out of it, and a new crack starts only after
// 0.06 s above its strength (incubation_s): the default since issue 17, stated here in full so the
// test keeps measuring it. Both scenes meet the goal there; the table in docs/tearing.md shows how near its
// edge that is (other lengths and delays fail on one of the two scenes). WEFT_CRACK_GROWTH_SETS
// adds --set overrides (';'-separated, e.g. "tearing.incubation_s=0"; the one-pass rows are
// "tearing.propagate=false;tearing.stress_length_m=0;tearing.incubation_s=0"), and
// WEFT_CRACK_GROWTH_SVG names a folder for each run's torn edges in material space (SVG).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene/scene_json.h"
#include "sim/world.h"
#include "support/tear_measures.h"

namespace weft {
namespace {

struct Growth {
  int resolution = 0;
  double firstTear = -1.0;  // s
  double tornLength = 0.0;  // m, material space, each crack once
  long long tears = 0;
};

Growth grow(const std::string& sceneName, int resolution, double seconds, const std::vector<std::string>& sets) {
  std::vector<std::string> all = sets;
  if (const char* extra = std::getenv("WEFT_CRACK_GROWTH_SETS")) {
    const std::string list = extra;
    for (std::size_t from = 0; from < list.size();) {
      const std::size_t end = std::min(list.find(';', from), list.size());
      all.push_back(list.substr(from, end - from));
      from = end + 1;
    }
  }
  all.push_back("cloths.0.mesh.grid.resolution=[" + std::to_string(resolution) + "," + std::to_string(resolution) + "]");
  World world(loadScene(std::string(WEFT_SOURCE_DIR) + "/presets/scenes/" + sceneName + ".json", all));
  Growth g;
  g.resolution = resolution;
  while (world.time() < seconds - 1e-9) {
    world.step();
    if (g.firstTear < 0.0 && !world.tearLog().empty()) g.firstTear = world.tearLog().front().time;
  }
  EXPECT_TRUE(world.metrics().finite) << sceneName << " at " << resolution;
  g.tornLength = test::tornLength(test::tornSegments(world.cloth(0)));
  if (const char* folder = std::getenv("WEFT_CRACK_GROWTH_SVG")) {
    const std::string path = std::string(folder) + "/" + sceneName + "-" + std::to_string(resolution) + ".svg";
    FILE* f = std::fopen(path.c_str(), "w");
    if (f == nullptr) {
      ADD_FAILURE() << "cannot write " << path;
      return g;
    }
    // Material space, y up.
    std::fprintf(f, "<svg xmlns='http://www.w3.org/2000/svg' width='400' height='400' viewBox='-0.02 -0.02 1.04 1.04'>"
                    "<rect x='-0.02' y='-0.02' width='1.04' height='1.04' fill='white'/>"
                    "<g transform='matrix(1 0 0 -1 0 1)' stroke='red' stroke-width='0.004'>");
    for (const test::TornSegment& s : test::tornSegments(world.cloth(0))) {
      std::fprintf(f, "<line x1='%g' y1='%g' x2='%g' y2='%g'/>", s.a.x(), s.a.y(), s.b.x(), s.b.y());
    }
    std::fprintf(f, "</g></svg>");
    std::fclose(f);
  }
  g.tears = world.tearStats().tears;
  return g;
}

std::vector<Growth> growAtThreeResolutions(const std::string& sceneName, double seconds,
                                           const std::vector<std::string>& sets) {
  std::vector<Growth> runs;
  for (int n : {32, 48, 64}) runs.push_back(grow(sceneName, n, seconds, sets));
  std::printf("%s after %.2f s:\n  n   first tear (s)  torn (m)  tears  tears/m  tears/m per element/m\n",
              sceneName.c_str(), seconds);
  for (const Growth& g : runs) {
    const double perMetre = g.tornLength > 0.0 ? g.tears / g.tornLength : 0.0;
    std::printf("  %2d  %14.4f  %8.3f  %5lld  %7.1f  %7.2f\n", g.resolution, g.firstTear, g.tornLength, g.tears,
                perMetre, perMetre / g.resolution);
  }
  return runs;
}

// Largest relative spread of a quantity over the runs: (max - min) / max.
template <typename Get>
double spread(const std::vector<Growth>& runs, Get get) {
  double lo = get(runs.front()), hi = lo;
  for (const Growth& g : runs) {
    lo = std::min(lo, get(g));
    hi = std::max(hi, get(g));
  }
  return hi > 0.0 ? (hi - lo) / hi : 0.0;
}

void expectResolutionIndependent(const std::vector<Growth>& runs) {
  for (const Growth& g : runs) ASSERT_GT(g.firstTear, 0.0) << "no tear at " << g.resolution;
  EXPECT_LE(spread(runs, [](const Growth& g) { return g.firstTear; }), 0.10);
  EXPECT_LE(spread(runs, [](const Growth& g) { return g.tornLength; }), 0.10);
  // Tears per metre grow at most as the elements per metre do (about one tear per element crossed).
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const double perElement0 = runs[0].tears / runs[0].tornLength / runs[0].resolution;
    const double perElement = runs[k].tears / runs[k].tornLength / runs[k].resolution;
    EXPECT_LE(perElement, 1.25 * perElement0) << "at " << runs[k].resolution;
  }
}

// The mode under test (see the top of the file).
const std::vector<std::string> kGrowthMode = {"tearing.propagate=true", "tearing.stress_length_m=0.065",
                                              "tearing.incubation_s=0.06"};

std::vector<std::string> with(std::vector<std::string> sets, const std::vector<std::string>& more) {
  sets.insert(sets.end(), more.begin(), more.end());
  return sets;
}

TEST(CrackGrowth, APulledSheetTearsTheSameAtEveryResolution) {
  expectResolutionIndependent(growAtThreeResolutions("sheet-pulled-apart", 1.6, kGrowthMode));
}

// The clamps are the vertices within 6.5 cm of each corner: about 6.4 cm at each of the three
// resolutions (the scene's 6 cm box holds 3.2 / 4.3 / 4.8 cm of cloth at 32 / 48 / 64^2).
const std::vector<std::string> kSameClamps = {
    "cloths.0.pins.0.rest_box.max=[0.065,0.065]", "cloths.0.pins.1.rest_box.min=[0.935,0]",
    "cloths.0.pins.1.rest_box.max=[1,0.065]",     "cloths.0.pins.2.rest_box.min=[0,0.935]",
    "cloths.0.pins.2.rest_box.max=[0.065,1]",     "cloths.0.pins.3.rest_box.min=[0.935,0.935]"};

TEST(CrackGrowth, ABallTearsTheSameAtEveryResolution) {
  expectResolutionIndependent(
      growAtThreeResolutions("ball-into-sheet-table4.1-cloth1", 0.5, with(kGrowthMode, kSameClamps)));
}

// The mechanism the tests above need: without the incubation, the spikes of stress the ball's
// impact and its first slits send through the sheet start cracks of their own, differently on each
// mesh (measured: 2.10 / 2.72 / 2.85 m torn at 32 / 48 / 64^2, against 1.32 / 1.35 / 1.32 m with
// it). The pulled sheet alone no longer shows it: since its stress is averaged on the lattice
// (nonlocal_stress.h) it tears 1.31 / 1.25 / 1.32 m without the incubation, within 5%.
TEST(CrackGrowth, WithoutIncubationTheBallTearsDifferentlyOnEachMesh) {
  const auto runs = growAtThreeResolutions("ball-into-sheet-table4.1-cloth1", 0.5,
                                           with(with(kGrowthMode, kSameClamps), {"tearing.incubation_s=0"}));
  EXPECT_GT(spread(runs, [](const Growth& g) { return g.tornLength; }), 0.10);
}

}  // namespace
}  // namespace weft
