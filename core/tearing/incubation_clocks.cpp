#include "tearing/incubation_clocks.h"

#include "util/heap_bytes.h"

namespace weft {

void IncubationClocks::set(int vertex, const Incubating& clock) {
  if (vertex < 0) return;
  if (vertex >= static_cast<int>(has_.size())) {
    has_.resize(vertex + 1, 0);
    at_.resize(vertex + 1);
  }
  if (!has_[vertex]) vertices_.push_back(vertex);
  has_[vertex] = 1;
  at_[vertex] = clock;
}

void IncubationClocks::clear() {
  for (int vertex : vertices_) has_[vertex] = 0;
  vertices_.clear();
}

std::size_t IncubationClocks::heapBytes() const {
  return weft::heapBytes(at_) + weft::heapBytes(has_) + weft::heapBytes(vertices_);
}

}  // namespace weft
