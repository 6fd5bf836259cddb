#pragma once
// Helpers shared by the rigid-body tests: scratch files and mesh edits.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "rigid/triangle_mesh.h"

namespace weft::test {

// A folder of its own for the running test, so tests run in parallel processes never share a file.
// Files left by an earlier run stay until overwritten: name each file a test reads or expects
// missing distinctly.
inline std::filesystem::path scratchDir() {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "weft_rigid_test" /
                                    (std::string(test->test_suite_name()) + "." + test->name());
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::filesystem::path writeScratchFile(const std::string& name, const std::string& text) {
  const std::filesystem::path path = scratchDir() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The same mesh turned inside out.
inline TriangleMesh reversed(TriangleMesh mesh) {
  for (std::array<int, 3>& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

inline TriangleMesh translated(TriangleMesh mesh, const Vec3& offset) {
  for (Vec3& v : mesh.vertices) v += offset;
  return mesh;
}

}  // namespace weft::test
