#include "contact/cloth_collision_mesh.h"

#include <algorithm>

namespace weft {
namespace {

TriangleEdit triangleEdit(const ClothMesh& mesh, int t) { return {t, mesh.tris[t].v, mesh.tris[t].edge}; }
EdgeEdit edgeEdit(const ClothMesh& mesh, int e) { return {e, mesh.edges[e].v}; }

}  // namespace

CollisionMesh makeClothCollisionMesh(const ClothMesh& mesh) {
  // A from-scratch build is one edit of an empty mesh that sets everything.
  std::vector<TriangleEdit> triangles;
  std::vector<EdgeEdit> edges;
  triangles.reserve(mesh.tris.size());
  edges.reserve(mesh.edges.size());
  for (int t = 0; t < mesh.triangleCount(); ++t) triangles.push_back(triangleEdit(mesh, t));
  for (int e = 0; e < mesh.edgeCount(); ++e) edges.push_back(edgeEdit(mesh, e));
  CollisionMesh topology;
  editCollisionMesh(topology, mesh.vertexCount(), triangles, edges);
  return topology;
}

CollisionMeshChange updateClothCollisionMesh(CollisionMesh& topology, const ClothMesh& mesh,
                                             const TopologyChange& change) {
  // An opened edge hands one of its triangles a new edge id without changing its corners, so the
  // triangles of every changed edge are edited too.
  std::vector<int> triangles = change.changedTriangles;
  for (int e : change.changedEdges) {
    for (int t : mesh.edges[e].tri) {
      if (t != kNone) triangles.push_back(t);
    }
  }
  std::sort(triangles.begin(), triangles.end());
  triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
  std::vector<TriangleEdit> triangleEdits;
  std::vector<EdgeEdit> edgeEdits;
  for (int t : triangles) triangleEdits.push_back(triangleEdit(mesh, t));
  for (int e : change.changedEdges) edgeEdits.push_back(edgeEdit(mesh, e));
  return editCollisionMesh(topology, mesh.vertexCount(), triangleEdits, edgeEdits);
}

}  // namespace weft
