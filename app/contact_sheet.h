#pragma once
// A contact sheet: a few rendered frames shrunk and laid side by side in one image, left to right
// in time, on a white background with a thin gap between them.
#include <cstdint>
#include <vector>

namespace weft::app {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4, RGBA8, rows top-down
};

// Every frame is `frameWidth` x `frameHeight`. The sheet is `sheetWidth` wide (at least one pixel a
// frame); frames are box-filtered down to fit (averaging keeps thin torn edges visible).
RgbaImage contactSheet(const std::vector<std::vector<std::uint8_t>>& frames, int frameWidth, int frameHeight,
                       int sheetWidth);

}  // namespace weft::app
