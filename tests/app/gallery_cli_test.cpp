// `weft gallery --quick` as a user runs it (for real: ffmpeg and EGL are installed by
// scripts/install_deps.sh): every entry of the thesis' Chapter 4 gets its video, contact sheet,
// figure frame and measured line, and those that need cutting are listed as not yet.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "gallery/gallery_entries.h"
#include "support/shell_run.h"
#include "support/temp_dir.h"

namespace weft::gallery {
namespace {

namespace fs = std::filesystem;

using Result = weft::test::ShellResult;

Result weft(const fs::path& dir, const std::string& arguments) {
  return weft::test::runShell("cd '" + dir.string() + "' && GALLIUM_DRIVER=llvmpipe '" + std::string(WEFT_BINARY) + "' " +
                                  arguments,
                              dir / "output.txt");
}

TEST(Gallery, QuickRunWritesEveryEntrysFilesAndItsDirectionHistogram) {
  test::TempDir dir("weft-gallery");
  const Result r = weft(dir.path(), "gallery --quick --out g --width 64 --height 48 --sheet-width 200");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(dir.path() / "g" / "gallery.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_TRUE(report["quick"].get<bool>());
  const std::vector<GalleryEntry> entries = galleryEntries();
  ASSERT_EQ(report["entries"].size(), entries.size());
  int ran = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const nlohmann::json& item = report["entries"][i];
    const std::string id = entries[i].id;
    EXPECT_EQ(item["id"], id);
    EXPECT_NE(r.output.find(id + ":"), std::string::npos) << "a printed line for " << id << "\n" << r.output;
    if (entries[i].claim == ThesisClaim::NeedsCutting) {
      EXPECT_EQ(item["status"], "not yet: needs cutting");
      EXPECT_FALSE(fs::exists(dir.path() / "g" / (id + ".mp4")));
      continue;
    }
    ++ran;
    for (const std::string suffix : {".mp4", ".png", "-figure.png"}) {
      const fs::path file = dir.path() / "g" / (id + suffix);
      EXPECT_TRUE(fs::exists(file) && fs::file_size(file) > 0) << file;
    }
    EXPECT_EQ(item["contact_sheet_times_s"].size(), entries[i].sheetTimes.size()) << id;
    const nlohmann::json& bins = item["measure"]["direction_histogram"];
    ASSERT_EQ(bins.size(), 8u) << id;
    for (int b = 0; b < 8; ++b) EXPECT_DOUBLE_EQ(bins[b]["direction_deg"].get<double>(), 22.5 * b);
    EXPECT_TRUE(item["measure"].contains("tears"));
    EXPECT_TRUE(item["measure"].contains("cut_edges"));
    EXPECT_EQ(item["measure"].contains("ball_end_m"), entries[i].ball >= 0) << id;
  }
  EXPECT_EQ(ran, 7) << "the hammer, the four cloths of Table 4.1 and the two ceiling balls";
}

// A PNG's width and height, from its IHDR chunk (bytes 16..23, big-endian).
std::pair<int, int> pngSize(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  auto word = [&](int at) { return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3]; };
  return {word(16), word(20)};
}

TEST(Gallery, QuickIsTinyUnlessASizeIsGivenAndOnlyRunsTheChosenEntries) {
  test::TempDir dir("weft-gallery");
  const Result r = weft(dir.path(), "gallery --quick --out g --only ceiling-light-ball");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(pngSize(dir.path() / "g" / "ceiling-light-ball-figure.png"), std::make_pair(160, 120));
  EXPECT_EQ(pngSize(dir.path() / "g" / "ceiling-light-ball.png"), std::make_pair(396, 57))
      << "five frames of 76 x 57 and four gaps of 4 px within the sheet's 400";
  std::ifstream in(dir.path() / "g" / "gallery.json");
  EXPECT_EQ(nlohmann::json::parse(in)["entries"].size(), 1u);
  EXPECT_FALSE(fs::exists(dir.path() / "g" / "table4.1-cloth2.mp4"));
}

TEST(Gallery, AnUnknownEntryIsRefusedBeforeAnythingIsWritten) {
  test::TempDir dir("weft-gallery");
  const Result r = weft(dir.path(), "gallery --quick --out g --only table4.1-cloth9");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("no entry 'table4.1-cloth9'"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.path() / "g"));
}

}  // namespace
}  // namespace weft::gallery
