#pragma once
// What the tear stage reports to the world and its users: one record per tear (metrics.json's tear
// log) and the running statistics. Apart from the stage itself, so that the world's interface does
// not carry the stage's caches.
#include "util/types.h"

namespace weft {

// One tear, as the tear log of metrics.json lists it.
struct TearRecord {
  double time = 0.0;        // s, end of the step that tore
  int cloth = 0;
  int vertex = kNone;       // the vertex the line went through (before the split)
  Vec3 position = Vec3::Zero();  // world position of that vertex (m)
  Vec2 restPosition = Vec2::Zero();  // its material-space position (m)
  double angleDeg = 0.0;    // the line's direction in material space, degrees from material x
  double alphaDeg = 0.0;    // from the warp direction V (Eq. 3.1-3.3)
  bool ray = false;         // opened from a border or an earlier tear (one side only)
  double separation = 0.0;  // zeta (N/m)
  double required = 0.0;    // R(alpha) (N/m)
  double ratio = 0.0;       // omega
};

// The candidate search's work.
struct TearSearchCounts {
  long long vertices = 0;       // vertices looked at
  long long skipped = 0;        // of which skipped by the bound
  long long linesEvaluated = 0;  // zeta evaluations
};

struct TearStats {
  long long tears = 0;
  long long refused = 0;     // lines the mesh guards refused (the next line or vertex was tried)
  long long stoppedBySpeed = 0;  // crack tips that could have run on but reached crack_speed * dt
  TearSearchCounts search;
};

}  // namespace weft
