#pragma once
// Items grouped by triangle, each triangle's in one contiguous run, so that a triangle pair reads
// its items from two short runs and a topology change rewrites only the runs of the triangles it
// touched (candidate_pairs.h keeps owned features and neighbour candidates this way).
//
// A full build lays the runs out back to back in triangle order. An update rewrites a run in
// place when the new items fit in it and appends it at the end otherwise; the slots it leaves
// behind belong to no run (they keep their old items, so a pass over every slot stays valid, but
// no query reads them) until the next full build. liveCount() tells how much is still in use.
#include <algorithm>
#include <cassert>
#include <vector>

namespace weft {

template <class Item>
struct TriangleRuns {
  std::vector<int> begin;   // triangle t's items are items[begin[t] .. end[t])
  std::vector<int> end;
  std::vector<Item> items;  // in runs, and slots left by updates
  int live = 0;             // items in runs

  void clear(int triangleCount) {
    begin.assign(triangleCount, 0);
    end.assign(triangleCount, 0);
    items.clear();
    live = 0;
  }
  // Full build: call for triangles 0, 1, 2, ... in order.
  void appendRun(int t, const std::vector<Item>& newItems) {
    begin[t] = static_cast<int>(items.size());
    items.insert(items.end(), newItems.begin(), newItems.end());
    end[t] = static_cast<int>(items.size());
    live += end[t] - begin[t];
  }
  // Grows the number of triangles; the new ones have empty runs.
  void resize(int triangleCount) {
    begin.resize(triangleCount, 0);
    end.resize(triangleCount, 0);
  }
  // Replaces triangle t's run by `newItems`.
  void replace(int t, const std::vector<Item>& newItems) {
    const int count = static_cast<int>(newItems.size());
    live += count - (end[t] - begin[t]);
    if (count > end[t] - begin[t]) {
      // At the end already: grow in place. Else move to the end.
      if (end[t] != static_cast<int>(items.size())) begin[t] = static_cast<int>(items.size());
      items.resize(begin[t] + count);
    }
    std::copy(newItems.begin(), newItems.end(), items.begin() + begin[t]);
    end[t] = begin[t] + count;
    assert(live >= 0);
  }
  // The storage holds more than twice what the runs use: time for a full build.
  bool sparse() const { return static_cast<int>(items.size()) > 2 * live + 64; }
};

}  // namespace weft
