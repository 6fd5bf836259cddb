#pragma once
// Image snapshots for the renderer's tests: compare a rendered image with a golden PNG committed
// under tests/, with a tolerance that survives harmless rounding but not a real change.
//
// Metric: a pixel differs when any of its channels differs by more than `channelThreshold`
// (of 255); the images match when at most `maxDifferingFraction` of the pixels differ. A missing
// cloth, a changed colour, a torn edge not drawn or a moved camera change far more than that.
//
// On a mismatch the actual image and a difference image (differing pixels in red over a dimmed
// copy of the golden) are written beside the golden, as NAME.actual.png and NAME.diff.png, and
// named in the failure. Blessing: with WEFT_BLESS=1 in the environment the golden is (re)written
// from the actual image instead of compared (scripts/bless_snapshots.sh).
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <stb_image.h>
#include <stb_image_write.h>

namespace weft::test {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // rows top to bottom, 4 bytes a pixel

  bool empty() const { return width == 0 || height == 0; }
};

struct SnapshotTolerance {
  int channelThreshold = 8;             // of 255
  double maxDifferingFraction = 0.002;  // of the pixels
};

struct ImageDifference {
  bool sameSize = false;
  long long differingPixels = 0;
  double differingFraction = 1.0;
  int largestChannelDelta = 255;
};

inline RgbaImage readPng(const std::filesystem::path& file) {
  RgbaImage image;
  int channels = 0;
  stbi_uc* data = stbi_load(file.string().c_str(), &image.width, &image.height, &channels, 4);
  if (data == nullptr) return {};
  image.pixels.assign(data, data + static_cast<std::size_t>(image.width) * image.height * 4);
  stbi_image_free(data);
  return image;
}

inline bool writePng(const std::filesystem::path& file, const RgbaImage& image) {
  return stbi_write_png(file.string().c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4) != 0;
}

inline ImageDifference compareImages(const RgbaImage& a, const RgbaImage& b, int channelThreshold) {
  ImageDifference d;
  d.sameSize = a.width == b.width && a.height == b.height && !a.empty();
  if (!d.sameSize) return d;
  d.largestChannelDelta = 0;
  const std::size_t count = static_cast<std::size_t>(a.width) * a.height;
  for (std::size_t p = 0; p < count; ++p) {
    int delta = 0;
    for (int c = 0; c < 4; ++c) delta = std::max(delta, std::abs(int(a.pixels[4 * p + c]) - int(b.pixels[4 * p + c])));
    d.largestChannelDelta = std::max(d.largestChannelDelta, delta);
    d.differingPixels += delta > channelThreshold ? 1 : 0;
  }
  d.differingFraction = static_cast<double>(d.differingPixels) / static_cast<double>(count);
  return d;
}

// Differing pixels in red over a dimmed grey copy of `golden`.
inline RgbaImage differenceImage(const RgbaImage& golden, const RgbaImage& actual, int channelThreshold) {
  RgbaImage out = golden;
  const std::size_t count = static_cast<std::size_t>(golden.width) * golden.height;
  for (std::size_t p = 0; p < count; ++p) {
    int delta = 0;
    for (int c = 0; c < 4; ++c) {
      delta = std::max(delta, std::abs(int(golden.pixels[4 * p + c]) - int(actual.pixels[4 * p + c])));
    }
    const auto grey = static_cast<std::uint8_t>(
        (golden.pixels[4 * p] + golden.pixels[4 * p + 1] + golden.pixels[4 * p + 2]) / 6 + 64);
    const bool differs = delta > channelThreshold;
    out.pixels[4 * p + 0] = differs ? 255 : grey;
    out.pixels[4 * p + 1] = differs ? 0 : grey;
    out.pixels[4 * p + 2] = differs ? 0 : grey;
    out.pixels[4 * p + 3] = 255;
  }
  return out;
}

inline bool blessing() {
  const char* bless = std::getenv("WEFT_BLESS");
  return bless != nullptr && std::string(bless) == "1";
}

// Empty when `actual` matches the golden at `goldenFile` (or was blessed into it); otherwise a
// message naming the golden, the actual and the difference images written beside it.
inline std::string checkSnapshot(const RgbaImage& actual, const std::filesystem::path& goldenFile,
                                 const SnapshotTolerance& tolerance = {}) {
  namespace fs = std::filesystem;
  if (blessing()) {
    fs::create_directories(goldenFile.parent_path());
    return writePng(goldenFile, actual) ? "" : "cannot write the golden " + goldenFile.string();
  }
  const fs::path actualFile = fs::path(goldenFile).replace_extension(".actual.png");
  const fs::path diffFile = fs::path(goldenFile).replace_extension(".diff.png");
  const RgbaImage golden = readPng(goldenFile);
  fs::create_directories(goldenFile.parent_path());
  if (golden.empty()) {
    writePng(actualFile, actual);
    return "no golden " + goldenFile.string() + " (actual written to " + actualFile.string() +
           "; run scripts/bless_snapshots.sh to create it)";
  }
  const ImageDifference d = compareImages(golden, actual, tolerance.channelThreshold);
  if (d.sameSize && d.differingFraction <= tolerance.maxDifferingFraction) {
    fs::remove(actualFile);
    fs::remove(diffFile);
    return "";
  }
  writePng(actualFile, actual);
  if (d.sameSize) writePng(diffFile, differenceImage(golden, actual, tolerance.channelThreshold));
  return (d.sameSize ? std::to_string(100.0 * d.differingFraction) + "% of the pixels differ by more than " +
                           std::to_string(tolerance.channelThreshold) + "/255 (allowed " +
                           std::to_string(100.0 * tolerance.maxDifferingFraction) + "%)"
                     : std::string("the sizes differ")) +
         " from " + goldenFile.string() + "; actual: " + actualFile.string() +
         (d.sameSize ? "; difference: " + diffFile.string() : std::string());
}

}  // namespace weft::test
