#pragma once
// A bounding volume hierarchy over axis-aligned boxes (the swept boxes of a mesh's triangles over
// a step: start and end positions, grown by the contact thickness). Built once per topology,
// refitted every step, and grown locally after a tear (insert). Queries report overlapping leaf
// pairs in a deterministic order.
//
// Growth policy: an inserted box joins an existing leaf (the caller names a box next to it), so
// the tree keeps its shape and the next refit fixes the boxes; leaves may grow past the build
// size. A grown leaf's slots move to the end of the slot array unless they are there already
// (the slots left behind stay valid but unused). needsRebuild() says when the tree has drifted
// too far from a fresh build: a leaf above kMaxGrownLeafSize boxes, more boxes inserted than a
// quarter of those built with, or more unused slots than boxes.
#include <functional>
#include <limits>
#include <vector>

#include "util/types.h"

namespace weft {

struct Aabb {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  void grow(const Vec3& p) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
  void grow(const Aabb& b) { lo = lo.cwiseMin(b.lo); hi = hi.cwiseMax(b.hi); }
  void inflate(double r) { lo.array() -= r; hi.array() += r; }
  bool overlaps(const Aabb& b) const { return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all(); }
};

class Bvh {
 public:
  // Builds the tree over the boxes (leaf i = box i). Deterministic (no randomness, stable splits).
  void build(const std::vector<Aabb>& boxes);
  // The same tree shape rules, but each range is split between two groups of `splitBoxes` (one
  // per box: where it lies in another space, e.g. a cloth triangle's material-space box) that do
  // not overlap along the split axis, as near the median as such a cut exists (the median where
  // none does within the middle half). A cloth grid then splits along its grid lines, so every
  // node holds a rectangle of whole cells (material_patches.h needs convex nodes).
  void build(const std::vector<Aabb>& boxes, const std::vector<Aabb>& splitBoxes);
  // Same number of boxes, new extents: updates the tree bottom-up without changing its shape.
  void refit(const std::vector<Aabb>& boxes);
  // Adds box leafCount() to the leaf holding box `nearBox` (the tree must not be empty). Its
  // extent comes with the next refit.
  void insert(int nearBox);
  bool needsRebuild() const;
  static constexpr int kMaxGrownLeafSize = 16;
  // Aabb::overlaps with all six comparisons made, no early exit: the traversals' box tests pass
  // about half the time in a cloth, which no branch predictor learns.
  static bool overlapsBox(const Aabb& a, const Aabb& b) {
    return (a.lo.x() <= b.hi.x()) & (b.lo.x() <= a.hi.x()) & (a.lo.y() <= b.hi.y()) & (b.lo.y() <= a.hi.y()) &
           (a.lo.z() <= b.hi.z()) & (b.lo.z() <= a.hi.z());
  }  // boxes in a leaf beyond which needsRebuild()
  int leafCount() const { return boxCount_; }
  std::size_t heapBytes() const;  // util/heap_bytes.h (defined in sim/world_memory.cpp)
  bool empty() const { return leafCount() == 0; }
  const Aabb& bounds() const;  // box of the whole tree (empty box when the tree is empty)

  // Every pair (i, j), i a leaf of this tree and j a leaf of `other`, whose boxes overlap.
  void overlappingPairs(const Bvh& other, const std::function<void(int, int)>& visit) const;
  // Every pair (i, j), i < j, of leaves of this tree whose boxes overlap. With `skipInside`
  // (a flag per node), no pair with both leaves under one flagged node is visited.
  void selfOverlappingPairs(const std::function<void(int, int)>& visit,
                            const std::vector<char>* skipInside = nullptr) const;

  // The tree's nodes, for structures that follow its shape (material_patches.h). Node 0 is the
  // root; children come after their parent; an internal node's left child is the next node.
  int nodeCount() const { return static_cast<int>(nodes_.size()); }
  bool isLeafNode(int node) const { return nodes_[node].isLeaf(); }
  int rightChild(int node) const { return nodes_[node].first; }
  // The boxes held by a leaf node.
  template <class Visit>
  void forEachBoxOfLeaf(int node, Visit&& visit) const {
    const Node& n = nodes_[node];
    for (int s = n.first; s < n.first + n.count; ++s) visit(leafOrder_[s]);
  }
  int leafOf(int box) const { return leafOfBox_[box]; }
  // Every leaf i whose box overlaps `box`, in the tree's order. (A template: it runs for a few
  // boxes at a time, where the call through a std::function would be a large share.)
  template <class Visit>
  void overlapping(const Aabb& box, Visit&& visit) const {
    if (nodes_.empty() || !overlapsBox(nodes_[0].box, box)) return;
    // Children are tested before they are entered, and only the right one of two overlapping
    // children waits on the stack: a query from a leaf's neighbourhood (the pair cache's, tens of
    // thousands a step) descends with few pushes. A median split halves each range, so the depth
    // never exceeds log2 of the box count: the stack cannot overflow.
    int stack[64];
    int size = 0;
    int node = 0;
    while (true) {
      const Node& n = nodes_[node];
      if (n.isLeaf()) {
        for (int s = n.first; s < n.first + n.count; ++s) {
          if (overlapsBox(slotBoxes_[s], box)) visit(leafOrder_[s]);
        }
      } else {
        const int left = node + 1, right = n.first;
        const bool intoLeft = overlapsBox(nodes_[left].box, box);
        const bool intoRight = overlapsBox(nodes_[right].box, box);
        if (intoLeft) {
          if (intoRight) stack[size++] = right;
          node = left;
          continue;
        }
        if (intoRight) {
          node = right;
          continue;
        }
      }
      if (size == 0) return;
      node = stack[--size];
    }
  }

 private:
  // A node of the tree. Nodes are stored depth first: an internal node's left child is the next
  // node, so a node's descendants always come after it and a backwards sweep refits bottom-up.
  struct Node {
    Aabb box;
    int first = 0;  // leaf: first slot of its boxes in leafOrder_; internal: index of the right child
    int count = 0;  // leaf: number of boxes (> 0); internal: 0
    bool isLeaf() const { return count > 0; }
  };

  void refitNodes();
  // Both queries: a simultaneous descent of this tree and `other` (itself when selfQuery, then
  // reporting each unordered pair once, as (smaller id, larger id)).
  void traverse(const Bvh& other, bool selfQuery, const std::function<void(int, int)>& visit,
                const std::vector<char>* skipInside = nullptr) const;
  void buildWith(const std::vector<Aabb>& boxes, const std::vector<Aabb>* splitBoxes);

  std::vector<Node> nodes_;      // nodes_[0] is the root (empty vector: empty tree)
  std::vector<int> leafOrder_;   // box id in each leaf slot; a leaf's boxes are contiguous slots
  std::vector<Aabb> slotBoxes_;  // the box of each slot (box leafOrder_[s]), contiguous per leaf
  std::vector<int> leafOfBox_;   // the leaf node holding each box
  int boxCount_ = 0;
  int builtBoxCount_ = 0;        // boxes at the last build
  int largestLeaf_ = 0;          // boxes in the largest leaf
};

}  // namespace weft
