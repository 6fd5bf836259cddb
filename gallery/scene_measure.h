#pragma once
// What `weft gallery` measures at the end of a run: the torn length by direction in material
// space (the tests' measure, tear_measures.h), the tear and cut counts, and where the ball ended.
#include <optional>

#include <nlohmann/json.hpp>

#include "gallery/direction_histogram.h"
#include "gallery/tear_measures.h"
#include "sim/world.h"
#include "util/types.h"

namespace weft::gallery {

struct SceneMeasure {
  double time = 0.0;             // s simulated
  long long tears = 0;           // lines torn (TearStats::tears)
  long long cutEdges = 0;        // edges tagged cut, each lip counted (0 until cutting exists)
  DirectionHistogram directions;  // m of torn and cut length per direction bin, every cloth
  double shareNearX = 0.0;       // of the torn length within 22.5 degrees of material x (horizontal here)
  double shareNearY = 0.0;       // within 22.5 degrees of material y (vertical here)
  FlapMeasure flap;              // Figure 4.5's two vertical tears and the join between them
  std::optional<Vec3> ballEnd;   // m: world position of the followed obstacle at the end
};

// `ball`: the obstacle whose end position is reported, or -1 for none.
SceneMeasure measureScene(const World& world, int ball);

nlohmann::json sceneMeasureJson(const SceneMeasure& measure);

}  // namespace weft::gallery
