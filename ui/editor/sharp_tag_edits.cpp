#include "sharp_tag_edits.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <system_error>

#include "contact/obstacle.h"
#include "editor/installed_data.h"
#include "editor/scene_edits.h"
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

std::vector<std::array<int, 2>> edgesSharperThan(const CollisionMesh& mesh, const std::vector<Vec3>& vertices,
                                                 double degrees) {
  std::vector<std::vector<int>> faces(mesh.edges.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int e : mesh.triangleEdges[t]) faces[static_cast<std::size_t>(e)].push_back(static_cast<int>(t));
  }
  auto normal = [&](int t) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    const Vec3 n = (vertices[tri[1]] - vertices[tri[0]]).cross(vertices[tri[2]] - vertices[tri[0]]);
    return n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3(Vec3::Zero());
  };
  const double cosLimit = std::cos(degrees * 3.14159265358979323846 / 180.0);
  std::vector<std::array<int, 2>> sharp;
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const std::vector<int>& f = faces[e];
    if (f.empty()) continue;
    // Two faces: the angle between their normals; more than two (a non-manifold edge) counts as sharp.
    if (f.size() == 1 || f.size() > 2 || normal(f[0]).dot(normal(f[1])) < cosLimit) sharp.push_back(mesh.edges[e]);
  }
  return sharp;
}

SharpTags withEdgesTagged(SharpTags tags, const std::vector<std::array<int, 2>>& edges) {
  for (std::array<int, 2> edge : edges) {
    if (edge[0] > edge[1]) std::swap(edge[0], edge[1]);
    const auto it = std::lower_bound(tags.edges.begin(), tags.edges.end(), edge);
    if (it == tags.edges.end() || *it != edge) tags.edges.insert(it, edge);
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
  const ObstacleSpec& spec = session.scene().obstacles[static_cast<std::size_t>(obstacle)];
  name_ = spec.name;
  inScene_ = !spec.shape.sharpTagsInline.is_null();
  // One undo history with the scene's edits (shared_undo.h).
  document_.history().shareClock(session.document().history().clock());
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

int ToolTagEditor::tagEdges(EditorSession& session, const std::vector<std::array<int, 2>>& edges,
                            const std::string& label) {
  const SharpTags before = tags();
  const SharpTags after = withEdgesTagged(before, edges);
  const int added = static_cast<int>(after.edges.size() - before.edges.size());
  if (added > 0) commit(session, after, label + " (" + std::to_string(added) + " edges)");
  return added;
}

int ToolTagEditor::tagEdgesSharperThan(EditorSession& session, double degrees) {
  const Obstacle& o = session.world().obstacle(obstacle_);
  const SharpTags before = tags();
  const SharpTags after = withEdgesTagged(before, edgesSharperThan(o.topology, o.bodyVertices, degrees));
  const int added = static_cast<int>(after.edges.size() - before.edges.size());
  if (added > 0) {
    char label[80];
    std::snprintf(label, sizeof label, "tag %d edges sharper than %.0f deg", added, degrees);
    commit(session, after, label);
  } else {
    session.status = "no untagged edge is sharper than " + std::to_string(static_cast<int>(degrees)) + " deg";
  }
  return added;
}

void ToolTagEditor::undo(EditorSession& session) {
  if (!document_.history().canUndo()) return;
  const std::string label = document_.history().undoLabel();
  document_.history().undo();
  applyToWorld(session);
  session.status = "undo " + label + " on " + name_;
}

void ToolTagEditor::redo(EditorSession& session) {
  if (!document_.history().canRedo()) return;
  const std::string label = document_.history().redoLabel();
  document_.history().redo();
  applyToWorld(session);
  session.status = "redo " + label + " on " + name_;
}

void ToolTagEditor::commit(EditorSession& session, const SharpTags& tags, const std::string& label) {
  session.endMerge();  // a slider drag in a panel is over: its next move is a step after this one
  document_.history().commit(sharpTagsJson(tags), label);
  applyToWorld(session);
  session.status = label + " (save the tags to keep them)";
}

namespace {

std::filesystem::path canonicalOf(const std::filesystem::path& file) {
  std::error_code ec;
  std::filesystem::path resolved = std::filesystem::weakly_canonical(file, ec);
  return ec ? file.lexically_normal() : resolved;
}

// The obstacle of the scene, other than `obstacle`, that reads its tags from `file` (tags kept in
// the scene read none).
std::optional<std::string> otherReaderOf(const Scene& scene, int obstacle, const std::filesystem::path& file) {
  const std::filesystem::path wanted = canonicalOf(file);
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    const ObstacleSpec& other = scene.obstacles[i];
    if (static_cast<int>(i) == obstacle || !other.shape.sharpTagsInline.is_null()) continue;
    const std::optional<std::filesystem::path> theirs = sharpTagsFileOf(other);
    if (theirs && canonicalOf(*theirs) == wanted) return other.name;
  }
  return std::nullopt;
}

// An obstacle's name as part of a file name: letters, digits, '-' and '_' kept, the rest '-'.
std::string fileNamePart(const std::string& name) {
  std::string part;
  for (const char c : name) part += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '-';
  return part.empty() ? "tool" : part;
}

}  // namespace

std::optional<std::string> ToolTagEditor::tagsFileSharedWith(const EditorSession& session) const {
  if (inScene_) return std::nullopt;
  return otherReaderOf(session.scene(), obstacle_, document_.file());
}

std::filesystem::path ToolTagEditor::toolFileTarget(const EditorSession& session) const {
  if (tagsFileSharedWith(session)) return session.document().file().parent_path() / ownFileName(session);
  return document_.file();
}

std::filesystem::path ToolTagEditor::saveToToolFile(EditorSession& session) {
  if (tagsFileSharedWith(session)) return saveBesideSceneAs(session, ownFileName(session));
  document_.save();
  return document_.file();
}

namespace {

// MESH.sharp.json beside the scene, unless another obstacle of the scene reads that file: then
// the obstacle's own (`own`).
std::filesystem::path besideSceneName(const EditorSession& session, int obstacle, const std::filesystem::path& own) {
  const ObstacleSpec& spec = session.scene().obstacles.at(static_cast<std::size_t>(obstacle));
  const std::filesystem::path folder = session.document().file().parent_path();
  const std::filesystem::path name = spec.shape.meshPath.stem().string() + ".sharp.json";
  return otherReaderOf(session.scene(), obstacle, folder / name) ? own : name;
}

}  // namespace

std::filesystem::path ToolTagEditor::besideSceneTarget(const EditorSession& session) const {
  return session.document().file().parent_path() / besideSceneName(session, obstacle_, ownFileName(session));
}

std::filesystem::path ToolTagEditor::saveBesideScene(EditorSession& session) {
  return saveBesideSceneAs(session, besideSceneName(session, obstacle_, ownFileName(session)));
}

std::filesystem::path ToolTagEditor::ownFileName(const EditorSession& session) const {
  const std::filesystem::path folder = session.document().file().parent_path();
  const std::string stem = session.document().file().stem().string() + "." + fileNamePart(name_);
  std::filesystem::path name = stem + ".sharp.json";
  // Two obstacles of one name: the second also by its index.
  if (otherReaderOf(session.scene(), obstacle_, folder / name)) name = stem + "-" + std::to_string(obstacle_) + ".sharp.json";
  return name;
}

std::filesystem::path ToolTagEditor::saveBesideSceneAs(EditorSession& session, const std::filesystem::path& name) {
  const std::filesystem::path file = session.document().file().parent_path() / name;
  if (isInstalledData(file)) {  // the scene is shipped too: beside it is Weft's own folder
    throw std::runtime_error(session.document().file().filename().string() +
                             " ships with Weft: keep the tags in the scene and save your version with Save as...");
  }
  document_.saveAs(file);
  session.edit(withSharpTagsFile(session.json(), obstacle_, name.string()), "sharp tags of " + name_ + " beside the scene");
  return file;
}

void ToolTagEditor::recover(EditorSession& session, const nlohmann::json& tags) {
  // An autosave is a file like any other: its tags are checked against the mesh before they reach
  // the world, and put in canonical form (the toggles keep them sorted).
  SharpTags recovered = sharpTagsFromJson(tags);
  const int vertices = static_cast<int>(session.world().obstacle(obstacle_).bodyVertices.size());
  for (int v : recovered.vertices) {
    if (v < 0 || v >= vertices) throw std::invalid_argument("no vertex " + std::to_string(v) + " on " + name_);
  }
  for (auto& e : recovered.edges) {
    if (e[0] > e[1]) std::swap(e[0], e[1]);
    if (e[0] < 0 || e[1] >= vertices || e[0] == e[1]) throw std::invalid_argument("no such edge on " + name_);
  }
  std::sort(recovered.vertices.begin(), recovered.vertices.end());
  recovered.vertices.erase(std::unique(recovered.vertices.begin(), recovered.vertices.end()), recovered.vertices.end());
  std::sort(recovered.edges.begin(), recovered.edges.end());
  recovered.edges.erase(std::unique(recovered.edges.begin(), recovered.edges.end()), recovered.edges.end());
  commit(session, recovered, "recover autosaved sharp tags of " + name_);
}

void ToolTagEditor::saveInScene(EditorSession& session) {
  const EditResult result =
      session.edit(withSharpTagsInline(session.json(), obstacle_, document_.json()), "sharp tags of " + name_ + " in the scene");
  if (!result.accepted) throw std::invalid_argument(result.message);
  document_.history().markSaved();  // what it holds is now the scene's, saved with the scene
  inScene_ = true;
}

bool ToolTagEditor::savesIntoInstalledData() const { return !inScene_ && isInstalledData(document_.file()); }

void ToolTagEditor::applyToWorld(EditorSession& session) const {
  SharpTags held = tags();
  const std::size_t bytes = held.vertices.capacity() * sizeof(int) + held.edges.capacity() * sizeof(held.edges.front());
  // The world's obstacle at this index is the tool's unless a reset is pending after an obstacle
  // before it was removed or added: then nothing is applied, and the reset puts the tags in
  // (ToolTagEditors::reapplyAfterReset).
  session.applyToWorld(WorldChange{[obstacle = obstacle_, name = name_, tags = std::move(held)](World& world) {
                                     if (obstacle < world.obstacleCount() && world.obstacle(obstacle).name == name) {
                                       world.setObstacleSharpTags(obstacle, tags);
                                     }
                                   },
                                   "tool " + std::to_string(obstacle_) + " sharp tags", bytes});  // the whole set
}

}  // namespace weft::editor
