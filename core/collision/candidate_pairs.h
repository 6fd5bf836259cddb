#pragma once
// Broad phase: the primitive pairs (vertex-face and edge-edge) whose swept boxes overlap, found
// through the triangle BVHs of two meshes (or of one mesh against itself) and emitted once each
// through feature ownership (collision_mesh.h). The narrow phase (ccd.h, closest_points.h) then
// tests each pair exactly.
#include <vector>

#include "collision/bvh.h"
#include "collision/collision_mesh.h"

namespace weft {

// Positions of a mesh at the start (x0) and end (x1) of the step, with its triangle boxes and BVH.
struct SweptMesh {
  const CollisionMesh* mesh = nullptr;
  const std::vector<Vec3>* x0 = nullptr;
  const std::vector<Vec3>* x1 = nullptr;
  std::vector<Aabb> triangleBoxes;  // swept over the step, grown by the margin
  Bvh bvh;
};

// Recomputes the triangle boxes (x0, x1, grown by `margin`), then builds the BVH if its leaf count
// changed (first use or new topology) and refits it otherwise.
void updateSweptMesh(SweptMesh& swept, double margin);

struct VertexFacePair {
  int vertex;  // vertex of the first mesh of the pair list
  int face;    // triangle of the second mesh
};
struct EdgeEdgePair {
  int edgeA;  // edge of mesh A
  int edgeB;  // edge of mesh B
};

// Between two meshes A and B: vertices of A against faces of B (vfAB), vertices of B against faces
// of A (vfBA), edges of A against edges of B. A pair is kept only when its own features' swept
// boxes (grown by `margin`) overlap. Sorted, no repeats: the order never depends on threads.
struct CandidatePairs {
  std::vector<VertexFacePair> vfAB;
  std::vector<VertexFacePair> vfBA;
  std::vector<EdgeEdgePair> ee;
  void clear() { vfAB.clear(); vfBA.clear(); ee.clear(); }
  size_t size() const { return vfAB.size() + vfBA.size() + ee.size(); }
};
void findCandidatePairs(const SweptMesh& a, const SweptMesh& b, double margin, CandidatePairs& out);

// Within one mesh: vertex-face pairs where the vertex is not a corner of the face, and edge-edge
// pairs of edges that share no vertex (in vfAB and ee; vfBA stays empty; ee has edgeA < edgeB).
void findSelfCandidatePairs(const SweptMesh& a, double margin, CandidatePairs& out);

}  // namespace weft
