// The snapshot comparison the renderer's tests use (support/snapshot.h), on synthetic images.
#include "support/snapshot.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace weft::test {
namespace {

RgbaImage filled(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  RgbaImage image{w, h, {}};
  for (int p = 0; p < w * h; ++p) image.pixels.insert(image.pixels.end(), {r, g, b, 255});
  return image;
}

TEST(Snapshot, SmallRoundingPassesARealChangeFails) {
  TempDir dir;
  const RgbaImage golden = filled(64, 64, 100, 120, 140);
  const auto goldenFile = dir.path() / "scene.png";
  ASSERT_TRUE(writePng(goldenFile, golden));
  RgbaImage rounded = golden;
  for (std::size_t k = 0; k < rounded.pixels.size(); k += 4 * 7) rounded.pixels[k] += 3;  // harmless rounding
  EXPECT_EQ(checkSnapshot(rounded, goldenFile), "");
  RgbaImage moved = golden;  // a 10 x 10 patch changed colour: 2.4% of the pixels
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) moved.pixels[4 * (y * 64 + x)] = 255;
  const std::string message = checkSnapshot(moved, goldenFile);
  EXPECT_NE(message.find("2.44"), std::string::npos) << message;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "scene.actual.png")) << message;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "scene.diff.png")) << message;
  const RgbaImage diff = readPng(dir.path() / "scene.diff.png");
  ASSERT_FALSE(diff.empty());
  EXPECT_EQ(diff.pixels[0], 255);  // a differing pixel is red
  EXPECT_EQ(diff.pixels[1], 0);
  // Matching again removes the stale actual and difference images.
  EXPECT_EQ(checkSnapshot(golden, goldenFile), "");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "scene.diff.png"));
}

TEST(Snapshot, AMissingGoldenOrAnotherSizeFailsWithTheFilesNamed) {
  TempDir dir;
  const RgbaImage image = filled(8, 8, 1, 2, 3);
  const std::string missing = checkSnapshot(image, dir.path() / "none.png");
  EXPECT_NE(missing.find("bless_snapshots"), std::string::npos) << missing;
  ASSERT_TRUE(writePng(dir.path() / "small.png", filled(4, 4, 1, 2, 3)));
  const std::string sized = checkSnapshot(image, dir.path() / "small.png");
  EXPECT_NE(sized.find("sizes differ"), std::string::npos) << sized;
}

}  // namespace
}  // namespace weft::test
