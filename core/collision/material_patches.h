#pragma once
// Self-collision culling for a cloth: a node of its triangle BVH whose patch of cloth is provably
// too little bent and stretched to come near itself is not searched inside.
//
// The certificate. Let a node's triangles tile a convex region of material space, with no slit
// (a tear or cut inside the region would leave two sides at one material point). Each triangle
// maps material space into the world linearly, with deformation gradient F (3 x 2). If every F of
// the node lies within r (Frobenius norm, which bounds the operator norm) of one matrix C, then
// for two material points p, q of the region, integrating F along the straight segment between
// them (it stays in the region) gives
//     |x(p) - x(q)| >= (sigma_min(C) - r) |p - q|,
// where sigma_min is C's smaller singular value. Two features of the node that share no vertex
// are at least the smallest altitude of the node's triangles apart in material space (the
// segment between them must leave the star of a vertex through the side opposite it). So when
// (sigma_min(C) - r) * smallestAltitude exceeds the margin, no such pair of the node comes within
// the margin. Over a step, positions move linearly, so each F does too: a ball holding F at the
// start and end of the step holds it all along, and nothing in the node collides during the step.
// (The same bi-Lipschitz reasoning underlies energy-based self-collision culling, Zheng & James
// 2012; this form needs no contour test, as the region is convex.)
//
// The ball bound is loose where a patch bends (a rotation moves F far in every direction), so a
// node the ball cannot certify, whose children are certified, is checked once more with a
// sharper bound over its own triangles: with Q an orthonormal basis of C's columns, and n = Cu/|Cu|
// for a material direction u, n . (M u) >= |Cu| - max |Q^T (F - C)| for any average M of the
// node's F, so (sigma_min(C) - max_t |Q^T (F_t - C)|) bounds the stretch instead. Bending moves F
// out of C's column space, which this bound barely sees.
//
// The tiling is checked once per tree build (MaterialPatches), the bounds every search (certify).
#include <array>
#include <vector>

#include "collision/bvh.h"
#include "collision/collision_mesh.h"
#include "util/types.h"

namespace weft {

// Material-space corners of each triangle (m), id for id with the collision mesh's triangles.
using RestCorners = std::vector<std::array<Vec2, 3>>;

// Per node of a cloth's BVH: what its triangles tile, from the topology and rest shape.
struct MaterialPatches {
  std::vector<char> tilesConvexRegion;   // its triangles tile a convex region with no slit
  std::vector<double> smallestAltitude;  // of its triangles, in material space (m)
  std::vector<int> parent;               // -1 for the root
  // The node's triangles: triangles[first[n] .. last[n]) (as built; a node a topology edit has
  // since touched no longer tiles, so its run is never read).
  std::vector<int> triangles, first, last;
  // Per triangle as built: the inverse of its rest edge matrix [r1 - r0, r2 - r0] (NaN when
  // degenerate). A triangle a later edit changed or added may be read stale or not at all: every
  // node holding it was forgotten, so no certificate depends on it.
  std::vector<Mat2> restInverse;
  bool empty() const { return parent.empty(); }
};

// The material-space box of each triangle (z = 0): what Bvh::build splits a cloth's tree by.
std::vector<Aabb> materialBoxes(const RestCorners& rest);

// Checks every node of `tree` (freshly built over the mesh's triangles, so that each node's
// leaves are one contiguous run) for a convex, slit-free tiling.
void buildMaterialPatches(const Bvh& tree, const CollisionMesh& mesh, const RestCorners& rest,
                          MaterialPatches& patches);

// After a topology edit: every node above a changed triangle's leaf can no longer vouch for its
// tiling (a split vertex may have opened a slit in it).
void forgetPatchesAbove(const Bvh& tree, int triangle, MaterialPatches& patches);

// Flags, per node, those whose certificate holds for every position between x0 and x1 with
// `margin` to spare. A flagged node has no pair of features sharing no vertex within `margin`
// of each other during the step.
void certifyPatches(const MaterialPatches& patches, const Bvh& tree, const CollisionMesh& mesh,
                    const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, double margin,
                    std::vector<char>& certified);

}  // namespace weft
