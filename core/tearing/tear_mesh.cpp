#include "tearing/tear_mesh.h"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "tearing/cut_ray.h"
#include "tearing/flip_edge.h"
#include "tearing/move_vertex.h"
#include "tearing/restore_quality.h"
#include "tearing/separate_vertex.h"
#include "tearing/split_edge.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

void sortUnique(std::vector<int>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

// Sorts the lists and adds the edges of every changed triangle to changedEdges (their hinges
// depend on the triangles), and the new edges, as topology_change.h promises (an opened edge's
// copy may belong to a triangle that kept its corners: only its edge id changed).
void finish(const ClothMesh& mesh, TopologyChange& change) {
  sortUnique(change.changedTriangles);
  for (int t : change.changedTriangles) {
    for (int e : mesh.tris[t].edge) change.changedEdges.push_back(e);
  }
  change.changedEdges.insert(change.changedEdges.end(), change.newEdges.begin(), change.newEdges.end());
  sortUnique(change.changedEdges);
  sortUnique(change.newEdges);
  sortUnique(change.tornEdges);
  sortUnique(change.massChangedVertices);
  sortUnique(change.movedVertices);
}

// A split whose neighbour piece is thin, then flips around the split point until every triangle
// there keeps the guards; failing that (or straight away with `atVertex`, RayCut::repairAtVertex),
// the guards restored over the split point's and the vertex's fans by flips and splits
// (restore_quality.h). When they cannot be, the mesh and the change are put back as they were
// (kept whole: the repair is rare, and a copy is simpler than undoing flips) and kNone is returned;
// else the cut edge from the vertex to the split point.
int splitAndRepair(ClothMesh& mesh, int vertex, const EdgeSplitPoint& at, const TearGuards& guards, double areaDensity,
                   std::vector<int> keepEdges, bool atVertex, TopologyChange& change) {
  const ClothMesh meshBefore = mesh;
  const TopologyChange changeBefore = change;
  // The split on the ray, and the cut edge from the vertex to it (kept by every repair).
  const auto split = [&](int& splitPoint) {
    splitPoint = splitEdge(mesh, at, areaDensity, change);
    keepEdges.push_back(edgeJoining(mesh, at.triangle, vertex, splitPoint));
    return keepEdges.back();
  };
  int splitPoint = kNone;
  if (!atVertex) {
    const int cutEdge = split(splitPoint);
    TopologyChange flips;
    improveByFlips(mesh, walkFan(mesh, splitPoint, at.triangle).triangles, keepEdges, areaDensity, flips);
    bool sound = true;
    for (int t : flips.changedTriangles) sound = sound && smallestRestAngle(mesh.tris[t]) >= degToRad(guards.minAngleDeg);
    for (int t : walkFan(mesh, splitPoint, mesh.edges[cutEdge].tri[0]).triangles) {
      sound = sound && smallestRestAngle(mesh.tris[t]) >= degToRad(guards.minAngleDeg);
    }
    if (sound) {
      appendFlips(change, flips);
      return cutEdge;
    }
    mesh = meshBefore;
    change = changeBefore;
    keepEdges.pop_back();
  }
  const int cutEdge = split(splitPoint);
  std::vector<int> region = walkFan(mesh, splitPoint, at.triangle).triangles;
  const std::vector<int> fan = walkFan(mesh, vertex, at.triangle).triangles;
  region.insert(region.end(), fan.begin(), fan.end());
  if (restoreQuality(mesh, region, keepEdges, guards, areaDensity, change)) return cutEdge;
  mesh = meshBefore;
  change = changeBefore;
  return kNone;
}

// Whether the far end of a planned cut is pinned: the spoke's other end (a vertex that moves onto
// the line first is never pinned, move_vertex.h), or the split point, which is pinned when both
// ends of the side it splits are (split_edge.h).
bool farEndPinned(const ClothMesh& mesh, int vertex, const RayCut& cut) {
  if (cut.followsEdge()) {
    const Edge& spoke = mesh.edges[cut.spoke];
    return mesh.pinned[spoke.v[0] == vertex ? spoke.v[1] : spoke.v[0]];
  }
  const Triangle& t = mesh.tris[cut.split.triangle];
  return mesh.pinned[t.v[cut.split.side]] && mesh.pinned[t.v[(cut.split.side + 1) % 3]];
}

}  // namespace

bool tearThroughVertex(ClothMesh& mesh, int vertex, const Vec2& direction, const TearGuards& guards,
                       double areaDensity, TopologyChange& outChange) {
  outChange = TopologyChange{};
  if (vertex < 0 || vertex >= mesh.vertexCount() || !direction.allFinite() || direction.squaredNorm() == 0.0) {
    return false;
  }
  int start = findTriangleAt(mesh, vertex);
  if (start == kNone) return false;
  const Vec2 along = direction.normalized();

  // 1. Each ray in turn, planned on the mesh as the rays before it left it, and carried out at
  // once. An interior vertex needs both rays (one alone would leave a slit whose ends are not
  // separated); when its second ray is refused, the mesh is put back as it was before the first
  // (a copy: the second ray is rarely refused once the first passed).
  const bool closed = walkFan(mesh, vertex, start).closed;
  std::optional<ClothMesh> before;
  if (closed) before = mesh;
  TopologyChange change;
  std::vector<int> cutEdges;
  std::vector<int> keep{vertex};
  for (const Vec2& ray : closed ? std::vector<Vec2>{along, -along} : std::vector<Vec2>{along}) {
    if (cornerOf(mesh.tris[start], vertex) == kNone) start = findTriangleAt(mesh, vertex);  // flipped away
    const std::optional<RayCut> cut = planRayCut(mesh, walkFan(mesh, vertex, start), ray, guards, keep);
    // A line whose two ends are pinned never tears: cloth held in a clamp's jaws cannot open. The
    // stress read at a pinned vertex comes from its free triangles below the clamp, while the
    // triangles between pinned vertices carry no strain, so without this a crack runs on into the
    // clamp (docs/tearing.md). Refused like any other ray: the stage falls back to the next line.
    if (cut && mesh.pinned[vertex] && farEndPinned(mesh, vertex, *cut)) {
      if (before && !cutEdges.empty()) mesh = std::move(*before);
      return false;
    }
    if (!cut) {
      if (before && !cutEdges.empty()) mesh = std::move(*before);
      return false;
    }
    int cutEdge = kNone;
    if (cut->followsEdge()) {
      if (cut->move) moveVertex(mesh, *cut->move, areaDensity, change);
      cutEdge = cut->spoke;
    } else if (!cut->repair) {
      const int splitPoint = splitEdge(mesh, cut->split, areaDensity, change);
      cutEdge = edgeJoining(mesh, cut->split.triangle, vertex, splitPoint);
    } else {
      cutEdge = splitAndRepair(mesh, vertex, cut->split, guards, areaDensity, cutEdges, cut->repairAtVertex, change);
      if (cutEdge == kNone) {
        if (before && !cutEdges.empty()) mesh = std::move(*before);
        return false;
      }
    }
    cutEdges.push_back(cutEdge);
    const Edge& edge = mesh.edges[cutEdge];
    keep.push_back(edge.v[0] == vertex ? edge.v[1] : edge.v[0]);
  }

  // 2. Open the cut edges and separate what they disconnect. Each vertex's triangles are
  // gathered before opening, while its fan is still whole.
  std::vector<int> ends{vertex};
  for (int e : cutEdges) {
    const Edge& edge = mesh.edges[e];
    ends.push_back(edge.v[0] == vertex ? edge.v[1] : edge.v[0]);
    change.crackEnds.push_back(ends.back());
  }
  std::vector<std::vector<int>> trianglesAtEnd;
  for (size_t i = 0; i < ends.size(); ++i) {
    const int throughCut = mesh.edges[cutEdges[i == 0 ? 0 : i - 1]].tri[0];
    trianglesAtEnd.push_back(walkFan(mesh, ends[i], throughCut).triangles);
  }
  for (int e : cutEdges) openEdge(mesh, e, change);
  for (size_t i = 0; i < ends.size(); ++i) separateFans(mesh, ends[i], trianglesAtEnd[i], areaDensity, change);

  finish(mesh, change);
  outChange = std::move(change);
  return true;
}

}  // namespace weft
