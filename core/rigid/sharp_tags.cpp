#include "rigid/sharp_tags.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "util/atomic_file.h"
#include "util/input_error.h"
#include "util/json_fields.h"
#include "util/json_text.h"

namespace weft {

using nlohmann::json;

namespace {

const char* const kVerticesKey = "sharp_vertices";
const char* const kEdgesKey = "sharp_edges";

std::array<int, 2> ordered(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

std::string asText(const std::array<int, 2>& edge) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) about "[" + std::string.
  std::string text("[");
  text += std::to_string(edge[0]);
  text += ", ";
  text += std::to_string(edge[1]);
  text += "]";
  return text;
}

int vertexId(const FieldReader& r, const json& value, const std::string& at, int vertexCount) {
  const int id = r.integerValue(value, at, 0);
  if (id >= vertexCount) {
    r.fail(at, "vertex id " + std::to_string(id) + " is out of range: the mesh has " + std::to_string(vertexCount) +
                   " vertices (ids 0 to " + std::to_string(vertexCount - 1) + ", in the order of the OBJ's v lines)");
  }
  return id;
}

std::vector<int> readVertices(const FieldReader& r, int vertexCount) {
  std::vector<int> vertices;
  std::map<int, std::size_t> firstIndexOf;
  const json& list = r.array(kVerticesKey);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = childPointer(r.pointer(kVerticesKey), i);
    const int id = vertexId(r, list[i], at, vertexCount);
    const auto [it, isNew] = firstIndexOf.try_emplace(id, i);
    if (!isNew)
      r.fail(at,
             "vertex " + std::to_string(id) + " is listed twice (also at index " + std::to_string(it->second) + ")");
    vertices.push_back(id);
  }
  std::sort(vertices.begin(), vertices.end());
  return vertices;
}

std::vector<std::array<int, 2>> readEdges(const FieldReader& r, const TriangleMesh& mesh) {
  const int vertexCount = static_cast<int>(mesh.vertices.size());
  const std::vector<std::array<int, 2>> meshEdges = undirectedEdges(mesh);
  std::vector<std::array<int, 2>> edges;
  std::map<std::array<int, 2>, std::size_t> firstIndexOf;
  const json& list = r.array(kEdgesKey);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = childPointer(r.pointer(kEdgesKey), i);
    if (!list[i].is_array() || list[i].size() != 2) {
      r.fail(at, "an edge must be an array of two vertex ids [a, b], " + r.got(list[i]));
    }
    const int a = vertexId(r, list[i][0], childPointer(at, std::size_t{0}), vertexCount);
    const int b = vertexId(r, list[i][1], childPointer(at, std::size_t{1}), vertexCount);
    const std::array<int, 2> edge = ordered(a, b);
    if (a == b) r.fail(at, "an edge needs two different vertices, got " + asText({a, b}));
    if (!std::binary_search(meshEdges.begin(), meshEdges.end(), edge)) {
      r.fail(at, asText({a, b}) + " is not an edge of the mesh (no triangle has both vertices next to each other)");
    }
    const auto [it, isNew] = firstIndexOf.try_emplace(edge, i);
    if (!isNew)
      r.fail(at, "edge " + asText(edge) + " is listed twice (also at index " + std::to_string(it->second) + ")");
    edges.push_back(edge);
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}


}  // namespace

std::filesystem::path sharpTagsPathFor(const std::filesystem::path& meshPath) {
  std::filesystem::path tags = meshPath;
  tags.replace_extension(".sharp.json");
  return tags;
}

SharpTags loadSharpTags(const std::filesystem::path& file, const TriangleMesh& mesh) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return {};
  const std::string name = file.string();
  const json j = readJsonFile(file, "the sharp-tag file");
  return readSharpTags(j, name, "", mesh);
}

SharpTags readSharpTags(const json& j, const std::string& file, const std::string& pointer, const TriangleMesh& mesh) {
  const FieldReader r(j, pointer, file, {kVerticesKey, kEdgesKey});
  SharpTags tags;
  if (r.has(kVerticesKey)) tags.vertices = readVertices(r, static_cast<int>(mesh.vertices.size()));
  if (r.has(kEdgesKey)) tags.edges = readEdges(r, mesh);
  return tags;
}

void saveSharpTags(const std::filesystem::path& file, const SharpTags& tags) {
  std::vector<int> vertices = tags.vertices;
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::vector<std::array<int, 2>> edges;
  for (const std::array<int, 2>& e : tags.edges) edges.push_back(ordered(e[0], e[1]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  // nlohmann::json keeps object keys sorted, so the text is the same for the same tags.
  const json j = {{kVerticesKey, vertices}, {kEdgesKey, edges}};
  writeFileAtomically(file, j.dump(2) + "\n");
}

}  // namespace weft
