#include "sharp_tag_edits.h"

#include <algorithm>
#include <stdexcept>

#include "contact/obstacle.h"
#include "rigid/triangle_mesh.h"

namespace weft::editor {

using nlohmann::json;

SharpTags withVertexToggled(SharpTags tags, int vertex) {
  auto it = std::lower_bound(tags.vertices.begin(), tags.vertices.end(), vertex);
  if (it != tags.vertices.end() && *it == vertex) {
    tags.vertices.erase(it);
  } else {
    tags.vertices.insert(it, vertex);
  }
  return tags;
}

SharpTags withEdgeToggled(SharpTags tags, std::array<int, 2> edge) {
  if (edge[0] > edge[1]) std::swap(edge[0], edge[1]);
  auto it = std::lower_bound(tags.edges.begin(), tags.edges.end(), edge);
  if (it != tags.edges.end() && *it == edge) {
    tags.edges.erase(it);
  } else {
    tags.edges.insert(it, edge);
  }
  return tags;
}

json sharpTagsJson(const SharpTags& tags) {
  json edges = json::array();
  for (const auto& e : tags.edges) edges.push_back(json::array({e[0], e[1]}));
  return json{{"sharp_edges", edges}, {"sharp_vertices", tags.vertices}};
}

SharpTags sharpTagsFromJson(const json& j) {
  SharpTags tags;
  for (const auto& e : j.value("sharp_edges", json::array())) tags.edges.push_back({e.at(0).get<int>(), e.at(1).get<int>()});
  tags.vertices = j.value("sharp_vertices", std::vector<int>{});
  return tags;
}

std::optional<std::filesystem::path> sharpTagsFileOf(const ObstacleSpec& spec) {
  if (!spec.shape.sharpTagsPath.empty()) return spec.shape.sharpTagsPath;
  if (spec.shape.kind == ShapeKind::Mesh) return sharpTagsPathFor(spec.shape.meshPath);
  return std::nullopt;
}

namespace {

JsonDocument openTags(const EditorSession& session, int obstacle) {
  const auto& obstacles = session.scene().obstacles;
  if (obstacle < 0 || obstacle >= static_cast<int>(obstacles.size())) throw std::out_of_range("no such obstacle");
  const ObstacleSpec& spec = obstacles[static_cast<std::size_t>(obstacle)];
  const std::optional<std::filesystem::path> file = sharpTagsFileOf(spec);
  if (!file) throw std::invalid_argument(spec.name + " is a generated shape: sharp tags need a mesh file to sit beside");
  // The world's obstacle holds what the file held when the scene was built (or what this editor
  // set since): start from it, so the document and the highlights agree.
  const Obstacle& o = session.world().obstacle(obstacle);
  SharpTags tags;
  for (int v = 0; v < static_cast<int>(o.sharpVertex.size()); ++v) {
    if (o.sharpVertex[static_cast<std::size_t>(v)]) tags.vertices.push_back(v);
  }
  for (std::size_t e = 0; e < o.sharpEdge.size(); ++e) {
    if (o.sharpEdge[e]) tags.edges.push_back(o.topology.edges[e]);
  }
  std::sort(tags.edges.begin(), tags.edges.end());
  return JsonDocument(sharpTagsJson(tags), *file);
}

}  // namespace

ToolTagEditor::ToolTagEditor(const EditorSession& session, int obstacle)
    : obstacle_(obstacle), document_(openTags(session, obstacle)) {
  name_ = session.scene().obstacles[static_cast<std::size_t>(obstacle)].name;
}

bool ToolTagEditor::reapply(EditorSession& session) const {
  const World& world = session.world();
  if (obstacle_ >= world.obstacleCount() || world.obstacle(obstacle_).name != name_) return false;
  applyToWorld(session);
  return true;
}

void ToolTagEditor::toggleVertex(EditorSession& session, int vertex) {
  commit(session, withVertexToggled(tags(), vertex), "toggle sharp vertex " + std::to_string(vertex));
}

void ToolTagEditor::toggleEdge(EditorSession& session, std::array<int, 2> edge) {
  commit(session, withEdgeToggled(tags(), edge),
         "toggle sharp edge " + std::to_string(edge[0]) + "-" + std::to_string(edge[1]));
}

void ToolTagEditor::undo(EditorSession& session) {
  document_.history().undo();
  applyToWorld(session);
}

void ToolTagEditor::redo(EditorSession& session) {
  document_.history().redo();
  applyToWorld(session);
}

void ToolTagEditor::commit(EditorSession& session, const SharpTags& tags, const std::string& label) {
  document_.history().commit(sharpTagsJson(tags), label);
  applyToWorld(session);
  session.status = label + " (save the tags to keep them)";
}

void ToolTagEditor::applyToWorld(EditorSession& session) const {
  session.world().setObstacleSharpTags(obstacle_, tags());
}

}  // namespace weft::editor
