#include "tearing/separate_vertex.h"

#include <algorithm>
#include <cmath>

#include "tearing/vertex_fan.h"

namespace weft {

int openEdge(ClothMesh& mesh, int edgeId, TopologyChange& change) {
  const int copyId = mesh.edgeCount();
  Edge copy = mesh.edges[edgeId];
  const int movedTriangle = copy.tri[1];
  copy.tri = {movedTriangle, kNone};
  copy.torn = true;
  mesh.edges.push_back(copy);

  Edge& kept = mesh.edges[edgeId];
  kept.tri[1] = kNone;
  kept.torn = true;
  for (int& e : mesh.tris[movedTriangle].edge) {
    if (e == edgeId) e = copyId;
  }

  change.newEdges.push_back(copyId);
  change.changedEdges.push_back(edgeId);
  change.tornEdges.push_back(edgeId);
  change.tornEdges.push_back(copyId);
  return copyId;
}

namespace {

// Replaces `vertex` by `copy` in one edge, keeping v[0] < v[1].
void renameEndpoint(Edge& edge, int vertex, int copy) {
  for (int& id : edge.v) {
    if (id == vertex) id = copy;
  }
  if (edge.v[0] > edge.v[1]) std::swap(edge.v[0], edge.v[1]);
}

}  // namespace

std::vector<int> separateFans(ClothMesh& mesh, int vertex, std::vector<int> incidentTriangles, double areaDensity,
                              TopologyChange& change) {
  std::sort(incidentTriangles.begin(), incidentTriangles.end());
  std::vector<int> copies;
  std::vector<char> placed(incidentTriangles.size(), 0);
  auto markPlaced = [&](int t) {
    const auto it = std::lower_bound(incidentTriangles.begin(), incidentTriangles.end(), t);
    if (it != incidentTriangles.end() && *it == t) placed[it - incidentTriangles.begin()] = 1;
  };

  bool firstFan = true;
  for (size_t i = 0; i < incidentTriangles.size(); ++i) {
    if (placed[i]) continue;
    const VertexFan fan = walkFan(mesh, vertex, incidentTriangles[i]);
    for (int t : fan.triangles) markPlaced(t);
    if (firstFan) {  // the fan with the lowest triangle id keeps the vertex
      firstFan = false;
      continue;
    }

    const int copy = mesh.addVertex(mesh.x[vertex]);
    mesh.v[copy] = mesh.v[vertex];
    mesh.pinned[copy] = mesh.pinned[vertex];
    double fanMass = 0.0;
    for (size_t j = 0; j < fan.triangles.size(); ++j) {
      Triangle& t = mesh.tris[fan.triangles[j]];
      const int k = fan.corners[j];
      fanMass += areaDensity * std::abs(restArea(t)) / 3.0;
      t.v[k] = copy;
      renameEndpoint(mesh.edges[t.edge[k]], vertex, copy);
      renameEndpoint(mesh.edges[t.edge[(k + 2) % 3]], vertex, copy);
      change.changedTriangles.push_back(fan.triangles[j]);
      change.changedEdges.push_back(t.edge[k]);
      change.changedEdges.push_back(t.edge[(k + 2) % 3]);
    }
    // The copy's mass is its fan's share, taken from the original: the masses still sum to the
    // old one, and with the same velocity on both, so does the momentum.
    mesh.mass[copy] = fanMass;
    mesh.mass[vertex] -= fanMass;

    copies.push_back(copy);
    change.newVertices.push_back(copy);
    change.vertexCopies.emplace_back(vertex, copy);
    change.massChangedVertices.push_back(vertex);
    change.massChangedVertices.push_back(copy);
  }
  return copies;
}

}  // namespace weft
