// Whole or not at all: a write interrupted between the .tmp and the rename leaves the old file.
#include "util/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(AtomicFile, ReplacesTheFileAndLeavesNoTmp) {
  const test::TempDir dir;
  const fs::path file = dir.write("out.txt", "old");
  writeFileAtomically(file, "new");
  EXPECT_EQ(readBytes(file), "new");
  EXPECT_FALSE(fs::exists(dir.path() / "out.txt.tmp"));
}

TEST(AtomicFile, RunsBeforeRenameWithTheTmpCompleteAndTheOldFileInPlace) {
  const test::TempDir dir;
  const fs::path file = dir.write("out.txt", "old");
  std::string tmpSeen, fileSeen;
  writeFileAtomically(file, "new", [&] {
    tmpSeen = readBytes(dir.path() / "out.txt.tmp");
    fileSeen = readBytes(file);
  });
  EXPECT_EQ(tmpSeen, "new");
  EXPECT_EQ(fileSeen, "old");
  EXPECT_EQ(readBytes(file), "new");
}

TEST(AtomicFile, AThrowBeforeRenameLeavesTheOldFileAndRemovesTheTmp) {
  const test::TempDir dir;
  const fs::path file = dir.write("out.txt", "old\n\x01 bytes");
  EXPECT_THROW(writeFileAtomically(file, "new", [] { throw std::runtime_error("crash"); }), std::runtime_error);
  EXPECT_EQ(readBytes(file), "old\n\x01 bytes");
  EXPECT_FALSE(fs::exists(dir.path() / "out.txt.tmp"));
}

}  // namespace
}  // namespace weft
