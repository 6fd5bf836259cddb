#include "rigid/triangle_mesh.h"

#include <algorithm>
#include <utility>

namespace weft {

std::vector<std::array<int, 2>> undirectedEdges(const TriangleMesh& mesh) {
  std::vector<std::array<int, 2>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const std::array<int, 3>& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace weft
