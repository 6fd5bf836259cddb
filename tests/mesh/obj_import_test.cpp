#include "mesh/obj_import.h"

#include <gtest/gtest.h>

#include "support/mesh_helpers.h"

#include <filesystem>
#include <fstream>

#include "mesh/mesh_check.h"
#include "util/input_error.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

// Writes `text` to a file named after the running test, in a folder of its own, so that tests run
// in parallel processes never share a file.
fs::path writeObj(const std::string& text, const std::string& name = "mesh.obj") {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / "weft_obj_import_test" /
                       (std::string(test->test_suite_name()) + "." + test->name());
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

ClothMesh load(const fs::path& path, double uvScale = 1.0, const std::string& referencingFile = "") {
  ObjSpec spec;
  spec.path = path;
  spec.uvScale = uvScale;
  return loadObjMesh(spec, referencingFile);
}

// Loads and expects an InputError that names the file (and `field`, when given) and says `phrase`.
void expectRejected(const fs::path& path, const std::string& field, const std::string& phrase) {
  try {
    load(path);
    ADD_FAILURE() << "expected an InputError for " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
  }
}

double totalRestArea(const ClothMesh& mesh) {
  double total = 0.0;
  for (const Triangle& t : mesh.tris) total += restArea(t);
  return total;
}

TEST(ObjImport, LoadsPositionsAndScalesUvsToMetres) {
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 2\n"
      "vt 0 0\nvt 4 0\nvt 0 2\n"
      "f 1/1 2/2 3/3\n");
  const ClothMesh mesh = load(path, 0.25);
  ASSERT_EQ(mesh.vertexCount(), 3);
  ASSERT_EQ(mesh.triangleCount(), 1);
  EXPECT_EQ(mesh.x[2], Vec3(0, 1, 2));
  const Triangle& t = mesh.tris[0];
  EXPECT_EQ(t.v, (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(t.rest[0], Vec2(0, 0));
  EXPECT_EQ(t.rest[1], Vec2(1.0, 0));
  EXPECT_EQ(t.rest[2], Vec2(0, 0.5));
  EXPECT_DOUBLE_EQ(restArea(t), 0.25);
  // At rest, unpinned, and with masses left to the caller.
  EXPECT_EQ(mesh.v[1], Vec3::Zero());
  EXPECT_EQ(mesh.mass[1], 0.0);
  EXPECT_EQ(mesh.pinned[1], 0);
  // Edges are built.
  EXPECT_EQ(mesh.edgeCount(), 3);
  EXPECT_TRUE(checkMesh(mesh).empty());
}

TEST(ObjImport, FanTriangulatesQuadsAndPolygons) {
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 3 1 0\nv 2.5 1.5 0\nv 2 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 2 0\nvt 3 0\nvt 3 1\nvt 2.5 1.5\nvt 2 1\n"
      "f 1/1 2/2 3/3 4/4\n"
      "f 5/5 6/6 7/7 8/8 9/9\n");
  const ClothMesh mesh = load(path);
  ASSERT_EQ(mesh.triangleCount(), 2 + 3);
  EXPECT_EQ(mesh.tris[0].v, (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(mesh.tris[1].v, (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(mesh.tris[2].v, (std::array<int, 3>{4, 5, 6}));
  EXPECT_EQ(mesh.tris[3].v, (std::array<int, 3>{4, 6, 7}));
  EXPECT_EQ(mesh.tris[4].v, (std::array<int, 3>{4, 7, 8}));
  EXPECT_NEAR(totalRestArea(mesh), 1.0 + 1.25, 1e-12);
  EXPECT_EQ(mesh.edgeCount(), 5 + 7);
  EXPECT_TRUE(checkMesh(mesh).empty());
}

TEST(ObjImport, SplitsVerticesAlongAUvSeam) {
  // A square tube: 4 positions per ring, 2 rings. Its UVs unroll it into a 1 x 1 strip with 5
  // columns, so the column where the tube closes has two UVs per position: a seam.
  std::string text;
  for (int ring = 0; ring < 2; ++ring) {
    text += "v 0 " + std::to_string(ring) + " 0\nv 1 " + std::to_string(ring) + " 0\n";
    text += "v 1 " + std::to_string(ring) + " 1\nv 0 " + std::to_string(ring) + " 1\n";
  }
  for (int row = 0; row < 2; ++row) {
    for (int column = 0; column < 5; ++column) {
      text += "vt " + std::to_string(0.25 * column) + " " + std::to_string(row) + "\n";
    }
  }
  for (int side = 0; side < 4; ++side) {
    const int p0 = side + 1, p1 = (side + 1) % 4 + 1;  // positions on the bottom ring
    const int t0 = side + 1, t1 = side + 2;            // UVs on the bottom row
    text += "f " + std::to_string(p0) + "/" + std::to_string(t0) + " " + std::to_string(p1) + "/" +
            std::to_string(t1) + " " + std::to_string(p1 + 4) + "/" + std::to_string(t1 + 5) + " " +
            std::to_string(p0 + 4) + "/" + std::to_string(t0 + 5) + "\n";
  }
  const ClothMesh mesh = load(writeObj(text));

  EXPECT_EQ(mesh.vertexCount(), 10);  // 8 positions, the 2 on the seam doubled
  EXPECT_EQ(mesh.triangleCount(), 8);
  EXPECT_EQ(mesh.edgeCount(), 4 * 2 + 5 + 4);
  int boundary = 0;
  for (const Edge& e : mesh.edges) boundary += e.isBoundary() ? 1 : 0;
  EXPECT_EQ(boundary, 2 * 4 + 2);  // top and bottom rows, and the seam on both sides
  EXPECT_NEAR(totalRestArea(mesh), 1.0, 1e-12);
  // The two copies of a seam vertex sit at the same place.
  int samePlace = 0;
  for (int i = 0; i < mesh.vertexCount(); ++i) {
    for (int j = i + 1; j < mesh.vertexCount(); ++j) samePlace += mesh.x[i] == mesh.x[j] ? 1 : 0;
  }
  EXPECT_EQ(samePlace, 2);
  EXPECT_TRUE(checkMesh(mesh).empty());
}

TEST(ObjImport, SharesVerticesThatShareBothPositionAndUv) {
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
  const ClothMesh mesh = load(path);
  EXPECT_EQ(mesh.vertexCount(), 4);
  EXPECT_EQ(mesh.edgeCount(), 5);
  EXPECT_EQ(mesh.tris[1].v, (std::array<int, 3>{0, 2, 3}));
}

TEST(ObjImport, TurnsClockwiseUvTrianglesCounterClockwise) {
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\n"
      "f 1/1 3/3 2/2\n");  // clockwise in UV space
  const ClothMesh mesh = load(path);
  ASSERT_EQ(mesh.triangleCount(), 1);
  const Triangle& t = mesh.tris[0];
  EXPECT_DOUBLE_EQ(restArea(t), 0.5);
  // Corners moved together: each rest coordinate still belongs to its vertex (here UV = x, y).
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(t.rest[k], mesh.x[t.v[k]].head<2>()) << "corner " << k;
  }
  EXPECT_TRUE(checkMesh(mesh).empty());
}

TEST(ObjImport, LeavesOutUnusedObjVertices) {
  const fs::path path = writeObj(
      "v 9 9 9\nv 0 0 0\nv 1 0 0\nv 8 8 8\nv 0 1 0\n"
      "vt 5 5\nvt 0 0\nvt 1 0\nvt 0 1\n"
      "f 2/2 3/3 5/4\n");
  const ClothMesh mesh = load(path);
  ASSERT_EQ(mesh.vertexCount(), 3);
  EXPECT_EQ(mesh.x[0], Vec3(0, 0, 0));
  EXPECT_EQ(mesh.x[1], Vec3(1, 0, 0));
  EXPECT_EQ(mesh.x[2], Vec3(0, 1, 0));
  EXPECT_TRUE(checkMesh(mesh).empty());
}

TEST(ObjImport, FindsARelativePathBesideTheReferencingFile) {
  const fs::path path = writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n", "beside.obj");
  const fs::path scene = path.parent_path() / "scene.json";
  const ClothMesh mesh = load("beside.obj", 1.0, scene.string());
  EXPECT_EQ(mesh.triangleCount(), 1);
}

TEST(ObjImport, NamesAMissingFile) {
  const fs::path path = fs::temp_directory_path() / "weft_obj_import_test" / "no_such_mesh.obj";
  expectRejected(path, "", "not found");
}

TEST(ObjImport, NamesAFileWithoutTextureCoordinates) {
  const fs::path path = writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expectRejected(path, "", "no texture coordinates");
}

TEST(ObjImport, NamesTheFaceThatLacksTextureCoordinates) {
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
      "f 1/1 2/2 3/3\nf 2 4 3\n");
  expectRejected(path, "face 2", "no texture coordinate");
}

TEST(ObjImport, NamesTheFaceWithZeroUvArea) {
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 2 0\n"
      "o first\nf 1/1 2/2 3/3\n"
      "o second\nf 2/2 4/3 3/3\nf 1/1 2/2 4/4\n");  // face 2 repeats a UV; face 3 has collinear UVs
  expectRejected(path, "face 2", "zero area");
}

TEST(ObjImport, NamesTheFaceWithCollinearUvs) {
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 2 0\n"
      "f 1/1 2/2 3/3\n"
      "g other\nf 1/1 2/2 4/4\n");
  expectRejected(path, "face 2", "zero area");
}

TEST(ObjImport, RejectsAUvAreaBelowTheRestAreaFloor) {
  // 1e-8 x 1e-8 m in UV: 5e-17 m^2, below 1e-14 m^2.
  const fs::path path = writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1e-8 0\nvt 0 1e-8\nf 1/1 2/2 3/3\n");
  expectRejected(path, "face 1", "zero area");
}

TEST(ObjImport, NamesTheLineOfANonFiniteCoordinate) {
  expectRejected(writeObj("v 0 0 0\nv nan 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n"), "line 2",
                 "non-finite");
  expectRejected(writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1e999 0\nvt 0 1\nf 1/1 2/2 3/3\n", "b.obj"),
                 "line 5", "non-finite");
}

TEST(ObjImport, NamesTheLineOfAMalformedCoordinate) {
  expectRejected(writeObj("v 0 0 0\nv 1 zero 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n"), "line 2",
                 "not a number");
}

TEST(ObjImport, NamesTheLineOfAnUnparsableFace) {
  // OBJ indices count from 1: a 0 is no index (tinyobjloader says only "cannot parse").
  expectRejected(writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 0/2 3/3\n"), "line 7",
                 "out of range");
  expectRejected(writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2x/2 3/3\n", "b.obj"), "line 7",
                 "not a face corner");
}

TEST(ObjImport, RefusesAFaceIndexPastAnInt) {
  // tinyobjloader reads 4294967299 modulo 2^32, as 3: a valid-looking triangle from a broken file.
  expectRejected(writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 4294967299/3\n"), "line 7",
                 "4294967299");
  expectRejected(writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/99999999999999999999\n",
                          "b.obj"),
                 "line 7", "out of range");
}

TEST(ObjImport, RefusesAVertexWithTwoCoordinates) {
  // tinyobjloader would read `v 1 0` as (1, 0, 0) and carry on.
  expectRejected(writeObj("v 0 0 0\nv 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n"), "line 2",
                 "at least 3 numbers, got 2");
  expectRejected(writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1\nvt 0 1\nf 1/1 2/2 3/3\n", "b.obj"), "line 5",
                 "at least 2 numbers, got 1");
}

TEST(ObjImport, ShortensWhatTinyobjloaderQuotesFromTheFile) {
  // Found by fuzz_obj_cloth: tinyobjloader warns once per unknown `usemtl` name, quoting it, before
  // the warning that matters; all of it went into the message (2.6 KB for a 2.4 KB name).
  const fs::path path = writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl " +
                                 std::string(3000, '\xC0') + "\nf 1/1/5 2/2/5 3/3/5\n");
  expectRejected(path, "", "Vertex normal indices out of bounds (line 8.)");
  try {
    load(path);
  } catch (const InputError& e) {
    EXPECT_LT(std::string(e.what()).size(), 400u) << e.what();
  }
}

TEST(ObjImport, ReadsAFileThatStartsWithAByteOrderMark) {
  // The mark used to hide the first `v` keyword: one vertex fewer, then "index out of range".
  const ClothMesh mesh = load(writeObj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n"));
  ASSERT_EQ(mesh.vertexCount(), 3);
  EXPECT_EQ(mesh.x[0], Vec3(0, 0, 0));
  EXPECT_EQ(mesh.x[2], Vec3(0, 1, 0));
}

TEST(ObjImport, NumbersClothVerticesInVLineOrder) {
  // Faces first use v 4, v 3, v 1, v 2; cloth vertex k is still the k-th `v` line.
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "f 4/4 3/3 1/1\nf 3/3 2/2 1/1\n");
  ObjSpec spec;
  spec.path = path;
  ObjVertexMap map;
  const ClothMesh mesh = loadObjMesh(spec, "", &map);
  ASSERT_EQ(mesh.vertexCount(), 4);
  EXPECT_EQ(mesh.x[0], Vec3(0, 0, 0));
  EXPECT_EQ(mesh.x[1], Vec3(1, 0, 0));
  EXPECT_EQ(mesh.x[2], Vec3(1, 1, 0));
  EXPECT_EQ(mesh.x[3], Vec3(0, 1, 0));
  EXPECT_TRUE(map.isIdentity());
  // Rest coordinates moved with their vertices (here UV = x, y).
  for (const Triangle& t : mesh.tris) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(t.rest[k], mesh.x[t.v[k]].head<2>());
  }
  EXPECT_TRUE(checkMesh(mesh).empty());
}

TEST(ObjImport, MapsSeamAndUnusedVLinesToTheirClothVertices) {
  // v 1 is used by no face. A second piece (face 3) meets the square along v 3 - v 4 in space but
  // with its own UVs: a UV seam, so v 3 and v 4 each become two cloth vertices.
  const fs::path path = writeObj(
      "v 9 9 9\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0.5 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 2 0\nvt 2 1\nvt 3 0.5\n"
      "f 2/1 3/2 4/3\nf 2/1 4/3 5/4\nf 3/5 6/7 4/6\n");
  ObjSpec spec;
  spec.path = path;
  ObjVertexMap map;
  const ClothMesh mesh = loadObjMesh(spec, "", &map);
  ASSERT_EQ(map.objVertexCount(), 6);
  EXPECT_TRUE(map.clothVertices[0].empty());
  EXPECT_EQ(map.clothVertices[1], (std::vector<int>{0}));
  EXPECT_EQ(map.clothVertices[2], (std::vector<int>{1, 2}));  // first used by face 1, then by face 3
  EXPECT_EQ(map.clothVertices[3], (std::vector<int>{3, 4}));
  EXPECT_EQ(map.clothVertices[4], (std::vector<int>{5}));
  EXPECT_EQ(map.clothVertices[5], (std::vector<int>{6}));
  EXPECT_FALSE(map.isIdentity());
  ASSERT_EQ(mesh.vertexCount(), 7);
  const std::vector<Vec3> positions{{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}};
  for (std::size_t line = 0; line < map.clothVertices.size(); ++line) {
    for (int v : map.clothVertices[line]) EXPECT_EQ(mesh.x[v], positions[line]) << "v line " << line;
  }
  EXPECT_TRUE(checkMesh(mesh).empty());
}

TEST(ObjImport, NamesAFileWithAnIndexOutOfRange) {
  expectRejected(writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 7/3\n"), "", "out of range");
}

TEST(ObjImport, NamesAFileWithoutFaces) {
  expectRejected(writeObj("# nothing but a comment\nv 0 0 0\nvt 0 0\n"), "", "no faces");
}

TEST(ObjImport, RejectsAnEdgeSharedByThreeFaces) {
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 0 -1\nvt 0.5 1\n"
      "f 1/1 2/2 3/3\nf 2/2 1/1 4/4\nf 1/1 2/2 5/5\n");
  expectRejected(path, "", "non-manifold");
}

TEST(ObjImport, RejectsUvsFoldedOverThemselves) {
  // Both faces lie on the same side of their shared edge in UV space.
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 1\n"
      "f 1/1 2/2 3/3\nf 2/2 1/1 4/4\n");
  expectRejected(path, "", "inconsistent orientation");
}

TEST(ObjImport, RejectsANonPositiveUvScale) {
  const fs::path path = writeObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  EXPECT_THROW(load(path, 0.0), InputError);
  EXPECT_THROW(load(path, -1.0), InputError);
}

TEST(ObjImport, LoadingTwiceGivesIdenticalMeshes) {
  const fs::path path = writeObj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 2 0\nvt 2 1\n"
      "f 1/1 2/2 3/3 4/4\nf 2/2 5/5 6/6 3/3\n");
  const ClothMesh a = load(path);
  const ClothMesh b = load(path);
  test::expectSameMesh(a, b);
}

#ifdef WEFT_SOURCE_DIR
// The meshes in assets/meshes/ (scripts/make_assets.py) load cleanly with the expected size.
struct AssetCase {
  const char* file;
  int vertices;
  int triangles;
  double area;       // m^2 at uv_scale 1
  double tolerance;  // m^2
};

class BundledMeshes : public ::testing::TestWithParam<AssetCase> {};

TEST_P(BundledMeshes, LoadAsValidCloth) {
  const AssetCase& c = GetParam();
  const ClothMesh mesh = load(fs::path(WEFT_SOURCE_DIR) / "assets" / "meshes" / c.file);
  EXPECT_EQ(mesh.vertexCount(), c.vertices);
  EXPECT_EQ(mesh.triangleCount(), c.triangles);
  EXPECT_NEAR(totalRestArea(mesh), c.area, c.tolerance);
  const std::vector<std::string> problems = checkMesh(mesh);
  EXPECT_TRUE(problems.empty()) << problems.front();
}

INSTANTIATE_TEST_SUITE_P(Assets, BundledMeshes,
                         ::testing::Values(AssetCase{"square_sheet.obj", 17 * 17, 2 * 16 * 16, 1.0, 1e-9},
                                           // 48-gon inscribed in a 0.5 m circle: pi/4 minus a little.
                                           AssetCase{"circle_panel.obj", 1 + 6 * 36, 6 * 64, 0.78316, 1e-4},
                                           // 140 cells of 5 cm.
                                           AssetCase{"tshirt_panel.obj", 170, 280, 0.35, 1e-6}),
                         [](const auto& info) { return std::string(fs::path(info.param.file).stem()); });
#endif

}  // namespace
}  // namespace weft
