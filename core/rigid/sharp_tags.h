#pragma once
// Which features of a tool cut or pierce cloth: a sword's tip vertex and the two edge lines of its
// blade. The tags live in a small JSON file beside the tool's mesh (tools/sword.obj ->
// tools/sword.sharp.json), naming vertices by their id in the loaded mesh, which is the order of
// the OBJ's `v` lines starting at 0 (loadClosedObj keeps it):
//   {"sharp_edges": [[a, b], ...], "sharp_vertices": [id, ...]}
// Both keys are optional; a tool without a tag file has nothing sharp. A scene may also hold the
// same object inline, in the mesh shape's "sharp_tags" (scene/contact_json.cpp).
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "rigid/triangle_mesh.h"

namespace weft {

// Canonical form: vertices ascending; each edge as {a, b} with a < b, edges ascending; no repeats.
struct SharpTags {
  std::vector<int> vertices;
  std::vector<std::array<int, 2>> edges;

  bool empty() const { return vertices.empty() && edges.empty(); }
  bool operator==(const SharpTags&) const = default;
};

// "dir/sword.obj" -> "dir/sword.sharp.json".
std::filesystem::path sharpTagsPathFor(const std::filesystem::path& meshPath);

// Reads the tags of `mesh` from `file` (empty tags when the file does not exist). Strict: an
// unknown key, a value of the wrong type, a vertex id out of range, an edge that is not an edge of
// the mesh, or an entry given twice (an edge also as [b, a]) throws an InputError naming the file
// and the JSON pointer of the offending value. Returns the canonical form.
SharpTags loadSharpTags(const std::filesystem::path& file, const TriangleMesh& mesh);

// Reads tags written inline (a scene's `"sharp_tags": {...}`): the same checks as loadSharpTags,
// with errors naming `file` and JSON pointers under `pointer`.
SharpTags readSharpTags(const nlohmann::json& tags, const std::string& file, const std::string& pointer,
                        const TriangleMesh& mesh);

// Writes the canonical form of `tags` as pretty, key-sorted JSON: to `file`.tmp first, then
// renamed over `file`, so a reader never sees half a file. Throws std::runtime_error naming the
// file when writing fails.
void saveSharpTags(const std::filesystem::path& file, const SharpTags& tags);

}  // namespace weft
