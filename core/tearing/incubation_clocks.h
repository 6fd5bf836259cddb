#pragma once
// The vertices of one cloth that are overloaded as crack starts, each with when its omega went
// above 1 and its last line above 1: the incubation's clocks (tear_stage.h). A table by vertex
// beside the list of the vertices in it, so that setting, finding and clearing cost the vertices
// touched and allocate nothing once grown. Why not a hash map: it was rebuilt every step, a node
// per vertex, and on a loaded sheet thousands of vertices wait at once.
#include <cstddef>
#include <vector>

namespace weft {

// A vertex whose omega is above 1, waiting out the incubation before it may start a crack.
struct Incubating {
  double since = 0.0;  // when its omega went above 1 (s); kept while it stays above 1
  double angle = 0.0;  // its last line above 1 (rad, material space): tried first next step
};

class IncubationClocks {
 public:
  // The vertex's clock, or none.
  const Incubating* find(int vertex) const {
    return vertex >= 0 && vertex < static_cast<int>(has_.size()) && has_[vertex] ? &at_[vertex] : nullptr;
  }
  // Sets the vertex's clock, replacing any.
  void set(int vertex, const Incubating& clock);
  // Sets the vertex's clock unless it has one.
  void add(int vertex, const Incubating& clock) {
    if (find(vertex) == nullptr) set(vertex, clock);
  }
  // The vertices with a clock, in the order they got it.
  const std::vector<int>& vertices() const { return vertices_; }
  const Incubating& at(int vertex) const { return at_[vertex]; }
  // No clocks (the table keeps its size).
  void clear();
  std::size_t heapBytes() const;

 private:
  std::vector<Incubating> at_;
  std::vector<char> has_;
  std::vector<int> vertices_;
};

inline std::size_t heapBytes(const IncubationClocks& clocks) { return clocks.heapBytes(); }

}  // namespace weft
