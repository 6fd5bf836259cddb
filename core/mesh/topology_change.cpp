#include "mesh/topology_change.h"

#include <algorithm>
#include <iterator>

namespace weft {
namespace {

void mergeSorted(std::vector<int>& into, const std::vector<int>& next) {
  std::vector<int> merged;
  merged.reserve(into.size() + next.size());
  std::set_union(into.begin(), into.end(), next.begin(), next.end(), std::back_inserter(merged));
  into = std::move(merged);
}

template <class T>
void append(std::vector<T>& into, const std::vector<T>& next) {
  into.insert(into.end(), next.begin(), next.end());
}

}  // namespace

void accumulateTopologyChange(TopologyChange& into, const TopologyChange& next) {
  mergeSorted(into.newVertices, next.newVertices);
  append(into.vertexCopies, next.vertexCopies);
  append(into.pinnedSplits, next.pinnedSplits);
  mergeSorted(into.changedTriangles, next.changedTriangles);
  mergeSorted(into.newTriangles, next.newTriangles);
  mergeSorted(into.changedEdges, next.changedEdges);
  mergeSorted(into.newEdges, next.newEdges);
  mergeSorted(into.tornEdges, next.tornEdges);
  append(into.crackEnds, next.crackEnds);
  mergeSorted(into.massChangedVertices, next.massChangedVertices);
  mergeSorted(into.movedVertices, next.movedVertices);
}

}  // namespace weft
