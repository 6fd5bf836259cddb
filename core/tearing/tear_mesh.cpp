#include "tearing/tear_mesh.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "tearing/cut_ray.h"
#include "tearing/separate_vertex.h"
#include "tearing/split_edge.h"
#include "tearing/vertex_fan.h"

namespace weft {
namespace {

void sortUnique(std::vector<int>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

// The triangle across a planned split (kNone on a border).
int neighbourAcrossSplit(const ClothMesh& mesh, const RayCut& cut) {
  const Triangle& t = mesh.tris[cut.split.triangle];
  return triangleAcross(mesh.edges[t.edge[cut.split.side]], cut.split.triangle);
}

// The two rays of an interior vertex are planned on the same mesh, so they must not change the
// same element: one edge can be cut once, and a neighbour split by one ray would no longer be the
// triangle the other ray's guards judged (only possible around a vertex of valence three).
bool raysConflict(const ClothMesh& mesh, const RayCut& a, const RayCut& b) {
  if (a.followsEdge() && b.followsEdge()) return a.spoke == b.spoke;
  if (a.followsEdge() || b.followsEdge()) return false;
  const int across = neighbourAcrossSplit(mesh, a);
  return across != kNone && across == neighbourAcrossSplit(mesh, b);
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
}

}  // namespace

bool tearThroughVertex(ClothMesh& mesh, int vertex, const Vec2& direction, const TearGuards& guards,
                       double areaDensity, TopologyChange& outChange) {
  outChange = TopologyChange{};
  if (vertex < 0 || vertex >= mesh.vertexCount() || !direction.allFinite() || direction.squaredNorm() == 0.0) {
    return false;
  }
  const int start = findTriangleAt(mesh, vertex);
  if (start == kNone) return false;
  const Vec2 along = direction.normalized();

  // 1. Plan every ray before changing anything.
  const VertexFan fan = walkFan(mesh, vertex, start);
  std::vector<RayCut> cuts;
  for (const Vec2& ray : fan.closed ? std::vector<Vec2>{along, -along} : std::vector<Vec2>{along}) {
    const std::optional<RayCut> cut = planRayCut(mesh, fan, ray, guards);
    if (!cut) return false;
    cuts.push_back(*cut);
  }
  if (cuts.size() == 2 && raysConflict(mesh, cuts[0], cuts[1])) return false;

  // 2. Split, and name the cut edges. A split keeps the entered triangle's id for the piece that
  // holds the split side's first corner, and that piece also holds the vertex.
  TopologyChange change;
  std::vector<int> cutEdges;
  for (const RayCut& cut : cuts) {
    if (cut.followsEdge()) {
      cutEdges.push_back(cut.spoke);
    } else {
      const int splitPoint = splitEdge(mesh, cut.split, areaDensity, change);
      cutEdges.push_back(edgeJoining(mesh, cut.split.triangle, vertex, splitPoint));
    }
  }

  // 3. Open the cut edges and separate what they disconnect. Each vertex's triangles are
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
