#pragma once
// The stress a tear reads: each triangle's tensile stress averaged over the cloth around it, within
// a material radius (a nonlocal stress, as nonlocal damage models regularize softening: Pijaudier-
// Cabot & Bazant 1987; the average stress criterion of Whitney & Nuismer 1974 for notched sheets).
//
// Why: the stress at a crack tip or a clamp's corner is singular, so a single triangle reads more
// of it the smaller it is, and whether and where a tear starts or runs on then depends on the
// mesh's resolution. Averaged over a fixed material disc, the stress converges as the mesh is
// refined, so first tears, crack speeds and side cracks do not depend on the element size; under
// a uniform load the average is the load itself, so the direction a fabric tears along is unchanged.
//
// Two kernels of the same second moment and nearly the same height at the centre, so that both
// read a load as the same average to second order. Where the cloth lies all round a triangle:
// the lattice's (stress_kernel.h), separable, reaching 1.05 r along each axis for an averaging
// length r, read from a lattice (stress_lattice.h: every triangle's stress spread onto its nodes,
// blurred, read back), whose cost per triangle does not grow with the reach. Where a crack's lips
// lie within that reach (or the cloth's own border hides part of it, below): the bell
// (1 - (d/r)^2)^2 over a disc of radius r, weighted by rest area, over a list of the triangles
// found by walking across shared edges from the triangle, keeping those whose centroids lie within
// the disc, so the average goes through the cloth, not across its cracks: the lips of a crack do
// not average with each other except around its tip. The lattice would read across the crack. The
// lists are what a crack tip reads, and the bell is round and centred on each triangle, while the
// lattice's kernel widens a little between its nodes. Near the cloth's own border a triangle reads
// the lattice when a walk within the lattice kernel's reach finds all that the lattice reads there
// (a straight edge), a list otherwise (a notch, a hole). Both are smooth, so a crack tip stepping by
// one element changes the average little.
//
// A lip's triangles (those with a torn border edge) are left out of every average. What they read
// is the lip's own stretch, not a load the cloth carries: a crack's lips open during the step while
// its tip stands, and the first triangle behind the tip is stretched along the lip by the opening
// (Green strain counts a lip that slid sideways by d over an element of height h as a stretch of
// about (d/h)^2 / 2 along it), so it reads a stress along the crack that grows as the elements
// shrink (measured on the pulled denim sheet at 64^2: 6,800 N/m along the lip against 400 N/m
// across the crack ahead). Averaged in, it turned the tips of a straight mode I crack sideways by
// up to 70 degrees at the start of a step, on some meshes and not others.
//
// Cost: an average is needed only where the cloth could tear. The average of tensile stresses is
// no larger (in its largest principal value) than the largest of them, so only a triangle whose
// reach holds one whose own stress could reach `threshold` is averaged; elsewhere the local
// stress is kept (it is below the threshold too). A step costs one pass over the triangles and
// the lattice, plus, along the cracks, one pass over the lists there. The lists and whether a
// triangle needs one depend on the mesh alone, so they are kept from step to step and redone
// around a step's tears (`patch`). A list holds at most 256 triangles: on a mesh much finer than
// the reach the outer part is read at a coarser spacing (nonlocal_stress.cpp, kMaxNeighbours), so
// memory and time per triangle stay bounded at any resolution.
#include <array>
#include <cstddef>
#include <vector>

#include "mesh/cloth_mesh.h"
#include "tearing/box_counts.h"
#include "tearing/points_near.h"
#include "tearing/stress_kernel.h"
#include "tearing/stress_lattice.h"
#include "util/scratch.h"
#include "util/types.h"

namespace weft {

class NonlocalStress {
 public:
  // One triangle of a neighbourhood and its share of the average (rest area times the kernel).
  struct Neighbour {
    int triangle = 0;
    double weight = 0.0;
  };

  std::size_t heapBytes() const;  // util/heap_bytes.h (defined in sim/world_memory.cpp)
  // `local` (per triangle sigma+, material frame) averaged into `out` over the averaging length
  // `radius` (m; stress_kernel.h), where
  // some triangle within reach has a largest principal stress of at least `threshold` (N/m).
  // The neighbourhoods are those of the last call or patch, unless the radius or the triangle
  // count changed since: between two calls a mesh must change only through tears that `patch`
  // was told of (as the tear stage's other caches assume), so one object serves one mesh.
  // `threads`: the averages are computed on that many threads (each triangle's alone, so the
  // result does not depend on it).
  void average(const ClothMesh& mesh, const std::vector<Mat2>& local, double radius, double threshold,
               std::vector<Mat2>& out, int threads = 1);
  // After a tear changed the listed triangles (their local stress is already updated; triangles
  // the tear added need not be listed; every other triangle's local stress is as the last call
  // read it): their own neighbourhoods and averages on the new mesh, now; the neighbourhoods of the
  // triangles round them that read them, at the next `average` call, once for all of a step's
  // tears (a crack running ten elements in a step changed each list near it ten times: rebuilding
  // them after every tear was most of a tearing step's stage). Until then those triangles keep the
  // step's averages, as every triangle keeps the step's stress until the next solve moves the
  // cloth. Returns the triangles whose average was recomputed (the changed and added ones),
  // increasing. Follows an `average` call on the same mesh.
  std::vector<int> patch(const ClothMesh& mesh, const std::vector<Mat2>& local, const std::vector<int>& changed,
                         std::vector<Mat2>& out);

 private:
  // Where `patch` changed the mesh (pending_, pendingPlaces_) into changedPlaces_, for
  // resolveReadings to look at again.
  void collectChangedPlaces();
  // The lattice from this call's local stresses (every triangle but the lips); false when the
  // cloth's material extent would need too many nodes (then every triangle reads a list).
  bool buildLattice(const std::vector<Mat2>& local, int threads, StressLattice& lattice) const;
  // Every triangle not yet checked since the mesh changed near it: whether it reads the lattice or
  // needs a list (the header comment). `lattice`: this call's, or none when it is unusable (then
  // every triangle reads a list).
  void resolveReadings(const ClothMesh& mesh, const StressLattice* lattice);
  // The cache from scratch: every triangle's centroid, area, lip flag and neighbourhood.
  void rebuild(const ClothMesh& mesh, double radius);
  // The triangles that `within` accepts, connected to triangle t through shared edges between
  // accepted triangles (t first), into `region_`.
  template <typename Within>
  void gather(int t, const Within& within);
  // The sum of the kernel's weights over the triangles a walk from t finds within its reach (lips
  // left out): what the lattice reads at t when the walk finds all it reads.
  double walkedKernelWeight(int t);
  // Triangle t's list: the triangles a walk finds within the averaging length, weighted by the
  // bell (the header comment), lips left out, into `neighbours_[t]`.
  void buildNeighbours(int t);
  // A neighbourhood of triangle t longer than the cap, read at fewer points (nonlocal_stress.cpp).
  void thin(int t, std::vector<Neighbour>& list);
  // `local`'s distinct components into packed_, which averageAt reads.
  void pack(const std::vector<Mat2>& local);
  Mat2 averageAt(const std::vector<Mat2>& local, int t) const;
  void updateCentroids(const ClothMesh& mesh, const std::vector<int>& triangles);
  // Triangle t's entry of `across_`, from the mesh's edges.
  void updateAcross(const ClothMesh& mesh, int t);

  double radius_ = 0.0;
  StressKernel kernel_;
  // Per triangle: how its average is read.
  enum class ReadsFrom : char { Unchecked, Lattice, List };
  std::vector<ReadsFrom> readsFrom_;
  // Per triangle that reads the lattice, this call: its average (or its local stress where the
  // lattice weighs nothing there), read once for both of average's passes (util/scratch.h).
  Scratch<std::vector<Mat2>> latticeAverage_;
  Scratch<StressLattice> lattice_;  // the averages of the last call (util/scratch.h: not copied)
  double largestSize_ = 0.0;  // the longest rest edge of any triangle the cache has seen (m)
  std::vector<Vec2> changedPlaces_;  // where tears changed the mesh since the last resolveReadings
  std::size_t cachedTriangles_ = 0;  // the triangle count the cache was built or last patched for
  bool built_ = false;
  std::vector<int> pending_;          // triangles patched since the last average, in order first patched
  std::vector<Vec2> pendingPlaces_;   // where those that existed before were then
  std::vector<char> pendingMark_;     // per triangle: in pending_
  std::vector<Vec2> centroid_;   // material space, per triangle
  std::vector<StressKernel::Place> place_;  // per triangle, its centroid on the lattice
  std::vector<double> area_;     // rest area, per triangle
  std::vector<char> lip_;        // per triangle: it has a torn border edge (left out of the averages)
  // Per triangle, the triangle across each of its edges (kNone on a border): the walks read this
  // rather than the mesh's triangles and edges, a quarter of the memory a step of a walk touches.
  std::vector<std::array<int, 3>> across_;
  // Per triangle that reads a list, its neighbourhood in gather order (so a cached average sums
  // exactly as a fresh one); empty for the others. A vector each rather than one packed array: a tear rebuilds a few hundred lists of new
  // lengths, which a packed array could only take by moving all the others.
  std::vector<std::vector<Neighbour>> neighbours_;
  std::vector<double> scale_;    // per triangle: 1 / the sum of its list's weights (0: no list, local kept)
  std::vector<int> stamp_;       // per triangle: the gather that last visited it
  int currentStamp_ = 0;
  std::vector<int> region_;      // the last gather, t first
  std::vector<int> cellOf_;      // thin's scratch: per list entry its cell, and per cell its sums
  std::vector<double> cellWeight_;
  std::vector<Vec2> cellMiddle_;
  std::vector<int> cellReader_;
  using Double2 = double __attribute__((vector_size(16)));  // GCC's vector extension (SSE2 on x86-64)
  // xx and yy side by side, so that one vector multiply and add take both (nonlocal_stress.cpp).
  struct PackedStress {
    Double2 xxyy;
    double xy, unused;
  };
  static PackedStress packed(const Mat2& stress);
  std::vector<PackedStress> packed_;  // the local stresses the averages read (see averageAt)
  std::vector<char> hot_;        // per triangle, this call: its local stress reaches the threshold
  std::vector<char> needed_;     // per triangle, this call: its average could reach the threshold
  std::vector<char> vertexNeeded_;  // per vertex, this call: it has a needed triangle
};

// The largest principal value of a symmetric 2x2 tensor.
double largestPrincipal(const Mat2& s);

// util/heap_bytes.h, for the tear stage's per-cloth vector of these.
inline std::size_t heapBytes(const NonlocalStress& nonlocal) { return nonlocal.heapBytes(); }

}  // namespace weft
