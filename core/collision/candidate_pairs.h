#pragma once
// Broad phase: the primitive pairs (vertex-face and edge-edge) whose swept boxes overlap, found
// through the triangle BVHs of two meshes (or of one mesh against itself) and emitted once each
// through feature ownership (collision_mesh.h). The narrow phase (ccd.h, closest_points.h) then
// tests each pair exactly.
#include <array>
#include <vector>

#include "collision/bvh.h"
#include "collision/collision_mesh.h"
#include "collision/material_patches.h"
#include "collision/triangle_runs.h"

namespace weft {

// The vertices or the edges of a mesh grouped by the triangle that owns them (collision_mesh.h),
// with their swept boxes: a triangle pair reads its candidates from two short contiguous runs.
struct OwnedFeatures {
  TriangleRuns<int> ids;    // vertex or edge ids, in runs per owning triangle
  std::vector<Aabb> boxes;  // of every slot of ids.items; swept over the step, not grown (the query adds its margin)
};

// What updateSweptMesh derives for findCandidatePairs and findSelfCandidatePairs: from the topology
// when the BVH is built (or patched after a tear, patchSweptMesh), and the feature boxes every step.
struct SweptFeatures {
  std::vector<std::array<int, 3>> triangles;  // the triangles the BVH and all below were built for
  OwnedFeatures vertices;
  OwnedFeatures edges;
  // Self-collision candidates between triangles that share a corner. Their boxes always overlap,
  // so a BVH would report these triangle pairs every step; listing their feature pairs once per
  // topology is much cheaper than rediscovering them. Triangle i's runs hold the candidates of
  // its pairs (i, j > i). Entries index the slots above:
  TriangleRuns<std::array<int, 2>> neighbourVertexFace;  // (slot in vertices, face)
  TriangleRuns<std::array<int, 2>> neighbourEdgeEdge;    // (slot in edges, slot in edges)
  // For a cloth (SweptMesh::rest set): what each BVH node's triangles tile in material space, so
  // that findSelfCandidatePairs can skip the nodes too little deformed to touch themselves.
  MaterialPatches patches;
};

// The broad phase grows every box by half the margin: two boxes so grown overlap exactly when
// they are within the margin of each other along every axis, as the boxes of any two features
// within the margin are. (Halving is exact, and rounding lo - g and hi + g is monotonic, so no
// pair within the margin is lost to rounding. Growing each box by the whole margin, as this
// search once did, let through pairs up to twice the margin apart.)
inline double boxGrowth(double margin) { return 0.5 * margin; }

// The plane of a triangle that does not move over the step (a static obstacle's, or any triangle
// when x0 and x1 are the same positions, as for the start-of-step pairs). A feature lying in that
// plane cannot come within a distance d of points that stay farther than d on one side of it:
// the exact culling findCandidatePairs applies after the box tests.
// A triangle that moves, or is degenerate, has no plane: all zero, so every point is at distance
// 0 from it and nothing is culled.
struct FixedPlane {
  Vec3 normal = Vec3::Zero();  // unit
  double offset = 0.0;         // normal . x on the plane
  double slack = 0.0;          // m: how far the triangle's own corners lie off the computed plane
};

// Positions of a mesh at the start (x0) and end (x1) of the step, with its triangle boxes and BVH.
struct SweptMesh {
  const CollisionMesh* mesh = nullptr;
  const std::vector<Vec3>* x0 = nullptr;
  const std::vector<Vec3>* x1 = nullptr;
  std::vector<Aabb> triangleBoxes;  // swept over the step, grown by boxGrowth(margin)
  std::vector<FixedPlane> planes;   // of each triangle (all zero where it moves over the step)
  bool hasFixedPlanes = false;      // some triangle has a plane
  Bvh bvh;
  SweptFeatures features;  // maintained by updateSweptMesh
  // A cloth's material-space triangle corners (null for an obstacle): its BVH is then split along
  // material-space cuts, and self-collision searches skip certified nodes (material_patches.h).
  const RestCorners* rest = nullptr;
  // What the boxes and planes were last computed from (updateSweptMesh): updateSweptMeshAround
  // patches them only for the same margin and position arrays.
  double boxesMargin = -1.0;
  const std::vector<Vec3>* boxesX0 = nullptr;
  const std::vector<Vec3>* boxesX1 = nullptr;
};

// The box the vertices `ids` of `m` sweep over the step (x0 to x1), not grown.
template <std::size_t N>
Aabb sweptBox(const SweptMesh& m, const std::array<int, N>& ids) {
  Aabb box;
  for (int v : ids) {
    box.grow((*m.x0)[v]);
    box.grow((*m.x1)[v]);
  }
  return box;
}

// Box `a` grown by `growA` overlaps box `b` grown by `growB` (as 0 or 1, without a branch: about
// half of the tests in a search pass, which no branch predictor can learn). Computed as
// (lo - grow) and (hi + grow), exactly what Aabb::inflate does.
inline int grownOverlap(const Aabb& a, double growA, const Aabb& b, double growB) {
  return ((a.lo.x() - growA) <= (b.hi.x() + growB)) & ((b.lo.x() - growB) <= (a.hi.x() + growA)) &
         ((a.lo.y() - growA) <= (b.hi.y() + growB)) & ((b.lo.y() - growB) <= (a.hi.y() + growA)) &
         ((a.lo.z() - growA) <= (b.hi.z() + growB)) & ((b.lo.z() - growB) <= (a.hi.z() + growA));
}

// Recomputes the triangle boxes (x0, x1, grown by boxGrowth(margin)), the feature boxes and the fixed
// planes. Builds the BVH
// and the topology-derived features if the mesh's triangles differ from those they were built for
// (first use, a change nobody patched with patchSweptMesh, or one after which the patch policy
// asked for a fresh build; about 2 ms for an 8k-triangle mesh), and refits the BVH otherwise.
void updateSweptMesh(SweptMesh& swept, double margin);

// What updateSweptMesh(swept, margin) would compute, when only the vertices flagged in `moved`
// have moved since the last updateSweptMesh with this margin (as between two iterations of pass
// 2, where only the vertices an impulse moved are flagged): the boxes and planes around them are
// recomputed and the BVH refitted, at a cost in proportion to the flagged vertices plus the refit.
// The caller vouches that nothing else moved and that the topology is the same; a last update for
// another margin, other position arrays or other triangle counts makes it a full updateSweptMesh.
void updateSweptMeshAround(SweptMesh& swept, double margin, const std::vector<char>& moved);

// After editCollisionMesh changed swept.mesh: patches what updateSweptMesh built from the topology
// for the triangles the edit touched, so that the next updateSweptMesh only refits.
//   - The BVH: each appended triangle joins the leaf of the lowest older triangle sharing a
//     corner with it (the one it was split from, or a neighbour); the next refit fixes the boxes.
//     The tree is rebuilt instead (at the next updateSweptMesh) once it has drifted too far from
//     a fresh build (Bvh::needsRebuild), or when the runs below hold more stale slots than live.
//   - The owned-feature runs of the changed and regrouped triangles.
//   - The neighbour candidates of every triangle around a corner (old or new) of those.
// Does nothing when nothing was built yet (updateSweptMesh then builds from scratch).
void patchSweptMesh(SweptMesh& swept, const CollisionMeshChange& change);

struct VertexFacePair {
  int vertex;  // vertex of the first mesh of the pair list
  int face;    // triangle of the second mesh
};
struct EdgeEdgePair {
  int edgeA;  // edge of mesh A
  int edgeB;  // edge of mesh B
};

// Between two meshes A and B: vertices of A against faces of B (vfAB), vertices of B against faces
// of A (vfBA), edges of A against edges of B. A pair is kept when its own features' swept boxes
// (grown by boxGrowth(margin)) overlap, unless a fixed plane proves it never comes within `margin`: the
// plane of a face, or of the triangle owning a vertex or an edge (which lies in it), with the
// other feature's start and end positions all farther than `margin` on one side. Every pair that
// comes within `margin` during the step is kept. Sorted, no repeats: the order never depends on
// threads.
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
// For a cloth with rest corners, pairs inside a node certified for the margin over the step
// (material_patches.h) are left out: they provably never come within the margin.
void findSelfCandidatePairs(const SweptMesh& a, double margin, CandidatePairs& out);

}  // namespace weft
