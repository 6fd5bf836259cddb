// Sharp tags: strict loading (each kind of bad input named by file and JSON pointer), a missing
// file meaning nothing sharp, and an atomic, canonical save.
#include "rigid/sharp_tags.h"

#include <fstream>
#include <initializer_list>
#include <sstream>

#include <gtest/gtest.h>

#include "rigid/shape_meshes.h"
#include "rigid_test_support.h"
#include "util/input_error.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

// A single box: 8 vertices; its edges include [0, 1] (see below), not the body diagonals.
const TriangleMesh& box() {
  static const TriangleMesh mesh = makeBoxMesh({Vec3::Constant(0.5), 0.0});
  return mesh;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void expectRejected(const std::string& json, const std::string& field, std::initializer_list<std::string> mentions) {
  const fs::path path = test::writeScratchFile("tool.sharp.json", json);
  try {
    loadSharpTags(path, box());
    ADD_FAILURE() << "accepted: " << json;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), path.string()) << what;
    EXPECT_EQ(e.field(), field) << what;
    for (const std::string& word : mentions)
      EXPECT_NE(what.find(word), std::string::npos) << "'" << word << "' in: " << what;
  }
}

TEST(SharpTags, PathBesideTheMesh) {
  EXPECT_EQ(sharpTagsPathFor("assets/tools/sword.obj"), fs::path("assets/tools/sword.sharp.json"));
}

TEST(SharpTags, MissingFileMeansNothingSharp) {
  const SharpTags tags = loadSharpTags(test::scratchDir() / "never-written.sharp.json", box());
  EXPECT_TRUE(tags.empty());
}

TEST(SharpTags, LoadsAndCanonicalises) {
  const std::array<int, 2> edge = undirectedEdges(box()).back();
  const std::string json = "{\"sharp_vertices\": [5, 0, 3], \"sharp_edges\": [[" + std::to_string(edge[1]) + ", " +
                           std::to_string(edge[0]) + "]]}";
  const SharpTags tags = loadSharpTags(test::writeScratchFile("box.sharp.json", json), box());
  EXPECT_EQ(tags.vertices, (std::vector<int>{0, 3, 5}));
  ASSERT_EQ(tags.edges.size(), 1u);
  EXPECT_EQ(tags.edges[0], edge);
  // Either key may be left out.
  EXPECT_TRUE(loadSharpTags(test::writeScratchFile("empty.sharp.json", "{}"), box()).empty());
}

TEST(SharpTags, RejectsEachKindOfBadInput) {
  const std::vector<std::array<int, 2>> edges = undirectedEdges(box());
  const std::string a = std::to_string(edges[0][0]), b = std::to_string(edges[0][1]);
  expectRejected("{\"sharp_vertex\": [1]}", "/sharp_vertex",
                 {"unknown key \"sharp_vertex\"", "allowed keys here: sharp_vertices, sharp_edges"});
  expectRejected("[1, 2]", "", {"must be a JSON object"});
  expectRejected("{\"sharp_vertices\": 3}", "/sharp_vertices", {"must be an array"});
  expectRejected("{\"sharp_vertices\": [1, \"2\"]}", "/sharp_vertices/1", {"integer", "got string \"2\""});
  expectRejected("{\"sharp_vertices\": [1.5]}", "/sharp_vertices/0", {"integer"});
  expectRejected("{\"sharp_vertices\": [-1]}", "/sharp_vertices/0", {"integer >= 0", "-1"});
  expectRejected("{\"sharp_vertices\": [8]}", "/sharp_vertices/0", {"vertex id 8 is out of range", "8 vertices"});
  expectRejected("{\"sharp_vertices\": [2, 4, 2]}", "/sharp_vertices/2", {"vertex 2 is listed twice", "index 0"});
  expectRejected("{\"sharp_edges\": {}}", "/sharp_edges", {"must be an array"});
  expectRejected("{\"sharp_edges\": [[0, 1, 2]]}", "/sharp_edges/0", {"array of two vertex ids"});
  expectRejected("{\"sharp_edges\": [3]}", "/sharp_edges/0", {"array of two vertex ids"});
  expectRejected("{\"sharp_edges\": [[0, 9]]}", "/sharp_edges/0/1", {"out of range"});
  expectRejected("{\"sharp_edges\": [[4, 4]]}", "/sharp_edges/0", {"two different vertices"});
  expectRejected("{\"sharp_edges\": [[" + a + ", " + b + "], [" + b + ", " + a + "]]}", "/sharp_edges/1",
                 {"listed twice", "index 0"});
  expectRejected("{\"sharp_vertices\": [1], }", "", {"not valid JSON"});
  // A body diagonal of the cube joins two vertices but is no edge of the mesh.
  int far = -1;
  for (int v = 0; v < 8; ++v)
    if ((box().vertices[v] + box().vertices[0]).norm() < 1e-12) far = v;
  ASSERT_GE(far, 0);
  expectRejected("{\"sharp_edges\": [[0, " + std::to_string(far) + "]]}", "/sharp_edges/0",
                 {"is not an edge of the mesh"});
}

TEST(SharpTags, SaveIsCanonicalAndRoundTrips) {
  const std::vector<std::array<int, 2>> edges = undirectedEdges(box());
  SharpTags tags;
  tags.vertices = {7, 2, 2, 0};
  tags.edges = {{edges[3][1], edges[3][0]}, edges[1], edges[3]};
  const fs::path path = test::scratchDir() / "box.sharp.json";
  saveSharpTags(path, tags);
  EXPECT_FALSE(fs::exists(path.string() + ".tmp"));
  const SharpTags loaded = loadSharpTags(path, box());
  EXPECT_EQ(loaded.vertices, (std::vector<int>{0, 2, 7}));
  EXPECT_EQ(loaded.edges, (std::vector<std::array<int, 2>>{edges[1], edges[3]}));
  // Pretty and key-sorted; saving the loaded tags again gives the same bytes.
  const std::string text = readFile(path);
  EXPECT_LT(text.find("\"sharp_edges\""), text.find("\"sharp_vertices\""));
  EXPECT_NE(text.find("\n  \"sharp_vertices\": [\n    0,\n    2,\n    7\n  ]"), std::string::npos) << text;
  saveSharpTags(path, loaded);
  EXPECT_EQ(readFile(path), text);
}

TEST(SharpTags, SaveReplacesAnOldFileWholeAndReportsFailure) {
  const fs::path path = test::writeScratchFile("old.sharp.json", std::string(5000, 'x'));
  saveSharpTags(path, SharpTags{});
  EXPECT_EQ(readFile(path), "{\n  \"sharp_edges\": [],\n  \"sharp_vertices\": []\n}\n");
  EXPECT_THROW(saveSharpTags(test::scratchDir() / "no-such-folder" / "x.sharp.json", SharpTags{}), std::runtime_error);
}

}  // namespace
}  // namespace weft
