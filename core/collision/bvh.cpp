#include "collision/bvh.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace weft {

namespace {

// Most boxes a leaf holds. Bigger leaves mean fewer nodes to walk but more box pairs to test
// inside a leaf pair; 4 was the fastest of 1, 2, 4 and 8 for a 64 x 64 cloth against itself.
constexpr int kMaxLeafSize = 4;

inline int overlapFlag(const Aabb& a, const Aabb& b) { return Bvh::overlapsBox(a, b) ? 1 : 0; }

// The traversal's stack of node pairs. It stays in the inline array for any balanced tree (the
// median split bounds the depth by log2 of the leaf count, and a pair traversal holds a few
// entries per level), so a query does not allocate; deeper stacks spill to the heap.
class NodePairStack {
 public:
  bool empty() const { return size_ == 0; }
  void push(int a, int b) {
    if (size_ < kInline) {
      inline_[size_] = {a, b};
    } else {
      spill_.emplace_back(a, b);
    }
    ++size_;
  }
  // push(a, b) when `condition` holds, decided without a branch while the stack is inline.
  void pushIf(bool condition, int a, int b) {
    if (size_ < kInline) {
      inline_[size_] = {a, b};
      size_ += condition ? 1 : 0;
    } else if (condition) {
      spill_.emplace_back(a, b);
      ++size_;
    }
  }
  std::pair<int, int> pop() {
    --size_;
    if (size_ < kInline) return inline_[size_];
    const std::pair<int, int> top = spill_.back();
    spill_.pop_back();
    return top;
  }

 private:
  static constexpr int kInline = 128;
  std::array<std::pair<int, int>, kInline> inline_;
  std::vector<std::pair<int, int>> spill_;
  int size_ = 0;
};

}  // namespace

void Bvh::build(const std::vector<Aabb>& boxes) { buildWith(boxes, nullptr); }

void Bvh::build(const std::vector<Aabb>& boxes, const std::vector<Aabb>& splitBoxes) {
  assert(splitBoxes.size() == boxes.size());
  buildWith(boxes, &splitBoxes);
}

namespace {

// Where to split the sorted slot range [begin, end) between two groups whose split boxes do not
// overlap along `axis` (every box before the cut ends at or before every box after it starts):
// the cut nearest the middle within the middle half, or -1 when there is none.
int cleanCut(const std::vector<int>& order, int begin, int end, const std::vector<Aabb>& splitBoxes, int axis) {
  const int count = end - begin;
  std::vector<double> suffixLow(static_cast<std::size_t>(count) + 1, std::numeric_limits<double>::infinity());
  for (int k = count - 1; k >= 0; --k) suffixLow[k] = std::min(suffixLow[k + 1], splitBoxes[order[begin + k]].lo[axis]);
  const int middle = count / 2;
  int best = -1;
  double prefixHigh = -std::numeric_limits<double>::infinity();
  for (int k = 1; k < count; ++k) {
    prefixHigh = std::max(prefixHigh, splitBoxes[order[begin + k - 1]].hi[axis]);
    if (4 * k < count || 4 * k > 3 * count || !(prefixHigh <= suffixLow[k])) continue;
    if (best < 0 || std::abs(k - middle) < std::abs(best - middle)) best = k;
  }
  return best < 0 ? -1 : begin + best;
}

}  // namespace

void Bvh::buildWith(const std::vector<Aabb>& boxes, const std::vector<Aabb>* splitBoxes) {
  const int n = static_cast<int>(boxes.size());
  nodes_.clear();
  boxCount_ = builtBoxCount_ = n;
  largestLeaf_ = std::min(n, kMaxLeafSize);
  leafOfBox_.resize(n);
  leafOrder_.resize(n);
  std::iota(leafOrder_.begin(), leafOrder_.end(), 0);
  slotBoxes_.resize(n);
  if (n == 0) return;

  // Split positions come from the box centres. An empty or non-finite box has no meaningful
  // centre; placing it at the origin keeps the ordering below a strict weak order.
  std::vector<Vec3> centres(n);
  for (int i = 0; i < n; ++i) {
    const Aabb& b = splitBoxes ? (*splitBoxes)[i] : boxes[i];
    const Vec3 c = 0.5 * (b.lo + b.hi);
    centres[i] = c.allFinite() ? c : Vec3::Zero();
  }

  // Top-down median split with an explicit stack. A task is a slot range [begin, end); `rightOf`
  // is the node whose right child it becomes (-1 for the root and for left children, which are
  // always created right after their parent).
  struct Task {
    int begin, end, rightOf;
  };
  std::vector<Task> tasks{{0, n, -1}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    const int index = static_cast<int>(nodes_.size());
    if (task.rightOf >= 0) nodes_[task.rightOf].first = index;
    nodes_.emplace_back();
    const int count = task.end - task.begin;
    if (count <= kMaxLeafSize) {
      nodes_[index].first = task.begin;
      nodes_[index].count = count;
      for (int s = task.begin; s < task.end; ++s) leafOfBox_[leafOrder_[s]] = index;
      continue;
    }
    Aabb centreBounds;
    for (int s = task.begin; s < task.end; ++s) centreBounds.grow(centres[leafOrder_[s]]);
    int axis = 0;
    (centreBounds.hi - centreBounds.lo).maxCoeff(&axis);  // first of equal extents: deterministic
    // Ties between equal centres go by box id: a strict total order, so which boxes fall on each
    // side of the median depends on the boxes alone.
    int mid = task.begin + count / 2;
    auto byCentre = [&](int i, int j) {
      const double ci = centres[i][axis], cj = centres[j][axis];
      return ci < cj || (ci == cj && i < j);
    };
    if (splitBoxes) {
      std::sort(leafOrder_.begin() + task.begin, leafOrder_.begin() + task.end, byCentre);
      const int cut = cleanCut(leafOrder_, task.begin, task.end, *splitBoxes, axis);
      if (cut >= 0) mid = cut;
    } else {
      std::nth_element(leafOrder_.begin() + task.begin, leafOrder_.begin() + mid, leafOrder_.begin() + task.end,
                       byCentre);
    }
    tasks.push_back({mid, task.end, index});  // popped after the whole left subtree
    tasks.push_back({task.begin, mid, -1});   // popped next: becomes node index + 1
  }
  refit(boxes);
}

void Bvh::refit(const std::vector<Aabb>& boxes) {
  assert(static_cast<int>(boxes.size()) == boxCount_ && "refit needs the box count of the tree");
  // Every slot, unused ones too (they hold valid box ids): one plain loop.
  const int n = static_cast<int>(leafOrder_.size());
  for (int s = 0; s < n; ++s) slotBoxes_[s] = boxes[leafOrder_[s]];
  refitNodes();
}

void Bvh::insert(int nearBox) {
  assert(!nodes_.empty() && nearBox >= 0 && nearBox < boxCount_);
  const int box = boxCount_++;
  const int leaf = leafOfBox_[nearBox];
  Node& node = nodes_[leaf];
  const int slots = static_cast<int>(leafOrder_.size());
  if (node.first + node.count != slots) {
    for (int s = node.first; s < node.first + node.count; ++s) leafOrder_.push_back(leafOrder_[s]);
    node.first = slots;
  }
  leafOrder_.push_back(box);
  ++node.count;
  slotBoxes_.resize(leafOrder_.size());
  leafOfBox_.push_back(leaf);
  largestLeaf_ = std::max(largestLeaf_, node.count);
}

bool Bvh::needsRebuild() const {
  return largestLeaf_ > kMaxGrownLeafSize || 4 * (boxCount_ - builtBoxCount_) > builtBoxCount_ ||
         static_cast<int>(leafOrder_.size()) > 2 * boxCount_;
}

void Bvh::refitNodes() {
  // Children come after their parent, so walking backwards visits every child before its parent.
  for (int i = static_cast<int>(nodes_.size()) - 1; i >= 0; --i) {
    Node& node = nodes_[i];
    Aabb box;
    if (node.isLeaf()) {
      for (int s = node.first; s < node.first + node.count; ++s) box.grow(slotBoxes_[s]);
    } else {
      box = nodes_[i + 1].box;
      box.grow(nodes_[node.first].box);
    }
    node.box = box;
  }
}

const Aabb& Bvh::bounds() const {
  static const Aabb kEmpty;  // immutable: the empty box every empty tree reports
  return nodes_.empty() ? kEmpty : nodes_[0].box;
}

void Bvh::overlappingPairs(const Bvh& other, const std::function<void(int, int)>& visit) const {
  traverse(other, false, visit);
}

void Bvh::selfOverlappingPairs(const std::function<void(int, int)>& visit, const std::vector<char>* skipInside) const {
  traverse(*this, true, visit, skipInside);
}

void Bvh::traverse(const Bvh& other, bool selfQuery, const std::function<void(int, int)>& visit,
                   const std::vector<char>* skipInside) const {
  if (nodes_.empty() || other.nodes_.empty()) return;
  NodePairStack stack;
  // Invariant: a pair on the stack is either a node with itself (self query only) or two nodes
  // whose boxes overlap. In a self query the two sides of a pair are disjoint subtrees, so each
  // unordered leaf pair is met exactly once.
  if (selfQuery || overlapsBox(nodes_[0].box, other.nodes_[0].box)) stack.push(0, 0);
  // The box pairs of a leaf pair are tested first and the overlapping ones visited after: about
  // half of them overlap in a cloth, a coin flip no branch predictor can learn, so the tests
  // write every candidate and only advance past the overlapping ones. A leaf grown by insertions
  // may hold more pairs than the buffer: it is emptied when full (a branch never taken for leaves
  // of the build size, so the predictor learns it).
  std::array<std::pair<int, int>, kMaxGrownLeafSize * kMaxGrownLeafSize> found;
  int count = 0;
  auto flush = [&] {
    for (int k = 0; k < count; ++k) visit(found[k].first, found[k].second);
    count = 0;
  };
  while (!stack.empty()) {
    const auto [a, b] = stack.pop();
    const Node& na = nodes_[a];
    const Node& nb = other.nodes_[b];

    if (selfQuery && a == b) {
      if (skipInside && (*skipInside)[a]) continue;
      if (na.isLeaf()) {
        for (int s = na.first; s < na.first + na.count; ++s) {
          for (int t = s + 1; t < na.first + na.count; ++t) {
            if (count == static_cast<int>(found.size())) flush();
            const int i = leafOrder_[s], j = leafOrder_[t];
            found[count] = {std::min(i, j), std::max(i, j)};
            count += overlapFlag(slotBoxes_[s], slotBoxes_[t]);
          }
        }
        flush();
      } else {
        const int left = a + 1, right = na.first;
        stack.push(right, right);
        stack.pushIf(overlapsBox(nodes_[left].box, nodes_[right].box), left, right);
        stack.push(left, left);
      }
      continue;
    }

    if (na.isLeaf() && nb.isLeaf()) {
      for (int s = na.first; s < na.first + na.count; ++s) {
        const Aabb& boxS = slotBoxes_[s];
        const int i = leafOrder_[s];
        for (int t = nb.first; t < nb.first + nb.count; ++t) {
          if (count == static_cast<int>(found.size())) flush();
          const int j = other.leafOrder_[t];
          found[count] = selfQuery ? std::pair(std::min(i, j), std::max(i, j)) : std::pair(i, j);
          count += overlapFlag(boxS, other.slotBoxes_[t]);
        }
      }
      flush();
      continue;
    }

    // Two internal nodes: open both at once (fewer pairs pass through the stack than opening one
    // side at a time); a leaf against an internal node: open the internal one.
    if (!na.isLeaf() && !nb.isLeaf()) {
      const int leftA = a + 1, rightA = na.first, leftB = b + 1, rightB = nb.first;
      const Aabb& boxLeftA = nodes_[leftA].box;
      const Aabb& boxRightA = nodes_[rightA].box;
      const Aabb& boxLeftB = other.nodes_[leftB].box;
      const Aabb& boxRightB = other.nodes_[rightB].box;
      stack.pushIf(overlapsBox(boxRightA, boxRightB), rightA, rightB);
      stack.pushIf(overlapsBox(boxRightA, boxLeftB), rightA, leftB);
      stack.pushIf(overlapsBox(boxLeftA, boxRightB), leftA, rightB);
      stack.pushIf(overlapsBox(boxLeftA, boxLeftB), leftA, leftB);
    } else if (nb.isLeaf()) {
      const int left = a + 1, right = na.first;
      stack.pushIf(overlapsBox(nodes_[right].box, nb.box), right, b);
      stack.pushIf(overlapsBox(nodes_[left].box, nb.box), left, b);
    } else {
      const int left = b + 1, right = nb.first;
      stack.pushIf(overlapsBox(na.box, other.nodes_[right].box), a, right);
      stack.pushIf(overlapsBox(na.box, other.nodes_[left].box), a, left);
    }
  }
}

}  // namespace weft
