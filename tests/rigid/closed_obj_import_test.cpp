// Loading a tool's OBJ: vertex ids follow the file, and bad files are named with what is wrong.
#include "rigid/closed_obj_import.h"

#include <gtest/gtest.h>

#include "rigid/mass_properties.h"
#include "rigid_test_support.h"
#include "util/input_error.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

// A unit cube with its vertices in a deliberately scrambled order and quad faces (fanned on load).
const char* const kCube =
    "# cube\n"
    "v 1 1 1\nv 0 0 0\nv 1 0 0\nv 0 1 1\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\n"
    "f 2 6 5 3\n"   // z = 0, facing -z
    "f 7 8 1 4\n"   // z = 1
    "f 2 3 8 7\n"   // y = 0
    "f 6 4 1 5\n"   // y = 1
    "f 2 7 4 6\n"   // x = 0
    "f 3 5 1 8\n";  // x = 1

void expectRejected(const fs::path& path, const std::string& field, const std::string& phrase) {
  try {
    loadClosedObj(path);
    ADD_FAILURE() << "expected an InputError for " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
  }
}

TEST(RigidObjImport, KeepsTheFilesVertexOrderAndFansPolygons) {
  const TriangleMesh mesh = loadClosedObj(test::writeScratchFile("cube.obj", kCube));
  ASSERT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.vertices[0], Vec3(1, 1, 1));
  EXPECT_EQ(mesh.vertices[1], Vec3(0, 0, 0));
  EXPECT_EQ(mesh.vertices[7], Vec3(1, 0, 1));
  ASSERT_EQ(mesh.triangles.size(), 12u);
  EXPECT_EQ(mesh.triangles[0], (std::array<int, 3>{1, 5, 4}));  // f 2 6 5 3 -> (2 6 5), (2 5 3), 0-based
  EXPECT_EQ(mesh.triangles[1], (std::array<int, 3>{1, 4, 2}));
  EXPECT_NEAR(signedVolume(mesh), 1.0, 1e-15);
}

TEST(RigidObjImport, KeepsIdsAcrossObjectsAndGroups) {
  std::string text = kCube;
  text.insert(text.find("f 2 7"), "o second\ng side\n");
  const TriangleMesh mesh = loadClosedObj(test::writeScratchFile("cube.obj", text));
  EXPECT_EQ(mesh.vertices[0], Vec3(1, 1, 1));
  EXPECT_EQ(mesh.triangles.size(), 12u);
}

TEST(RigidObjImport, RejectsAnInsideOutMesh) {
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";
  expectRejected(test::writeScratchFile("inward.obj", text), "", "turned inward");
}

TEST(RigidObjImport, RejectsAnOpenMesh) {
  std::string text = kCube;
  text.erase(text.find("f 3 5 1 8"));
  expectRejected(test::writeScratchFile("open.obj", text), "", "has a hole");
}

TEST(RigidObjImport, RejectsAFlippedFace) {
  std::string text = kCube;
  text.replace(text.find("f 3 5 1 8"), 9, "f 8 1 5 3");
  expectRejected(test::writeScratchFile("flipped.obj", text), "", "inconsistent orientation");
}

TEST(RigidObjImport, RejectsBadFiles) {
  expectRejected(test::scratchDir() / "missing.obj", "", "not found");
  expectRejected(test::writeScratchFile("nan.obj", std::string("v nan 0 0\n") + kCube), "line 1", "non-finite");
  expectRejected(test::writeScratchFile("text.obj", std::string("v 1 x 0\n") + kCube), "line 1", "'x' is not a number");
  expectRejected(test::writeScratchFile("range.obj", std::string(kCube) + "f 1 2 9\n"), "", "out of range");
  expectRejected(test::writeScratchFile("empty.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "", "has no faces");
  expectRejected(test::writeScratchFile("stray.obj", std::string(kCube) + "v 5 5 5\n"), "",
                 "vertex 8 is in no triangle");
}

// Found by fuzz_closed_obj: a valid tetrahedron 1e70 units across loaded, and a dynamic body made
// from it had an infinite inertia; one 1e200 across was refused as having "zero area", and one
// 1e-110 across as well. Sizes no scene holds are refused as such.
TEST(RigidObjImport, RejectsSizesBeyondAnyScene) {
  const auto tetrahedron = [](const std::string& size) {
    return "v 0 0 0\nv " + size + " 0 0\nv 0 " + size + " 0\nv 0 0 " + size + "\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  };
  for (const char* size : {"1e70", "1e200", "-2e9"}) {
    expectRejected(test::writeScratchFile("huge.obj", tetrahedron(size)), "", "at most 1e+09 in magnitude");
  }
  expectRejected(test::writeScratchFile("tiny.obj", tetrahedron("1e-110")), "", "at least 1e-09");
  // The limits themselves load, with a finite, positive mass and inertia.
  for (const char* size : {"1e9", "1e-9"}) {
    const TriangleMesh mesh = loadClosedObj(test::writeScratchFile("edge.obj", tetrahedron(size)));
    const MassProperties body = computeMassProperties(mesh, 1.0 / signedVolume(mesh), "edge.obj");
    EXPECT_NEAR(body.mass, 1.0, 1e-9) << size;
    EXPECT_TRUE(body.inertia.allFinite()) << size;
    EXPECT_GT(body.inertia.trace(), 0.0) << size;
  }
}

TEST(RigidObjImport, ShortensWhatTinyobjloaderQuotesFromTheFile) {
  // Found by fuzz_obj_cloth: tinyobjloader warns once per unknown `usemtl` name, quoting it, before
  // the warning that matters; all of it went into the message (2.6 KB for a 2.4 KB name).
  const std::string name(3000, '\xC0');
  const fs::path path = test::writeScratchFile("usemtl.obj", std::string(kCube) + "usemtl " + name + "\nf 1 2 9\n");
  expectRejected(path, "", "Vertex indices out of bounds (line 17.)");
  try {
    loadClosedObj(path);
  } catch (const InputError& e) {
    EXPECT_LT(std::string(e.what()).size(), 400u) << e.what();
  }
}

}  // namespace
}  // namespace weft
