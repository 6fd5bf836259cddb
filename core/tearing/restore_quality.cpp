#include "tearing/restore_quality.h"

#include <algorithm>

#include "tearing/flip_edge.h"
#include "tearing/split_edge.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

// At most this many splits per repair: a region that needs more is not a thin triangle beside a
// crack but a mesh the tear should not cross here (the tear falls back to its next line).
constexpr int kMaxSplits = 4;

void sortUnique(std::vector<int>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

double restEdgeLength(const Triangle& t, int side) { return (t.rest[(side + 1) % 3] - t.rest[side]).norm(); }

}  // namespace

bool keepsGuards(const Triangle& triangle, const TearGuards& guards) {
  if (!(smallestRestAngle(triangle) >= degToRad(guards.minAngleDeg))) return false;
  for (int k = 0; k < 3; ++k) {
    if (!(restEdgeLength(triangle, k) >= guards.minEdgeLength)) return false;
  }
  return true;
}

bool restoreQuality(ClothMesh& mesh, std::vector<int> region, const std::vector<int>& keep, const TearGuards& guards,
                    double areaDensity, TopologyChange& change) {
  for (int splits = 0;; ++splits) {
    TopologyChange flips;
    improveByFlips(mesh, region, keep, areaDensity, flips);
    appendFlips(change, flips);
    region.insert(region.end(), flips.changedTriangles.begin(), flips.changedTriangles.end());
    sortUnique(region);
    // The thinnest triangle that fails the guards (the lowest id on a tie: deterministic).
    int worst = kNone;
    for (int t : region) {
      if (keepsGuards(mesh.tris[t], guards)) continue;
      if (worst == kNone || smallestRestAngle(mesh.tris[t]) < smallestRestAngle(mesh.tris[worst])) worst = t;
    }
    if (worst == kNone) return true;
    if (splits == kMaxSplits) return false;
    const Triangle& t = mesh.tris[worst];
    int side = 0;
    for (int k = 1; k < 3; ++k) {
      if (restEdgeLength(t, k) > restEdgeLength(t, side)) side = k;
    }
    const int edge = t.edge[side];
    const Edge& e = mesh.edges[edge];
    if (e.torn || e.cut || std::find(keep.begin(), keep.end(), edge) != keep.end()) return false;
    if (!(0.5 * restEdgeLength(t, side) >= guards.minEdgeLength)) return false;
    const int midpoint = splitEdge(mesh, EdgeSplitPoint{worst, side, 0.5}, areaDensity, change);
    const std::vector<int> around = walkFan(mesh, midpoint, worst).triangles;
    region.insert(region.end(), around.begin(), around.end());
  }
}

}  // namespace weft
