#include "contact_sheet.h"

#include <algorithm>
#include <stdexcept>

namespace weft::app {
namespace {

constexpr int kGap = 4;  // px of white between two frames

// Box filter of the source rectangle under each destination pixel (at least one source pixel).
void shrinkInto(const std::vector<std::uint8_t>& src, int sw, int sh, RgbaImage& dst, int dx0, int dw, int dh) {
  for (int y = 0; y < dh; ++y) {
    const int y0 = y * sh / dh, y1 = std::max(y0 + 1, (y + 1) * sh / dh);
    for (int x = 0; x < dw; ++x) {
      const int x0 = x * sw / dw, x1 = std::max(x0 + 1, (x + 1) * sw / dw);
      unsigned sum[4] = {0, 0, 0, 0};
      for (int sy = y0; sy < y1; ++sy) {
        for (int sx = x0; sx < x1; ++sx) {
          for (int c = 0; c < 4; ++c) sum[c] += src[(static_cast<std::size_t>(sy) * sw + sx) * 4 + c];
        }
      }
      const unsigned count = static_cast<unsigned>((y1 - y0) * (x1 - x0));
      for (int c = 0; c < 4; ++c) {
        dst.pixels[(static_cast<std::size_t>(y) * dst.width + dx0 + x) * 4 + c] =
            static_cast<std::uint8_t>((sum[c] + count / 2) / count);
      }
    }
  }
}

}  // namespace

RgbaImage contactSheet(const std::vector<std::vector<std::uint8_t>>& frames, int frameWidth, int frameHeight,
                       int sheetWidth) {
  const int n = static_cast<int>(frames.size());
  if (n == 0) throw std::invalid_argument("contact sheet: no frames");
  const int tileWidth = std::max(1, (sheetWidth - kGap * (n - 1)) / n);
  const int tileHeight = std::max(1, tileWidth * frameHeight / frameWidth);
  RgbaImage sheet;
  sheet.width = tileWidth * n + kGap * (n - 1);
  sheet.height = tileHeight;
  sheet.pixels.assign(static_cast<std::size_t>(sheet.width) * sheet.height * 4, 255);
  for (int i = 0; i < n; ++i) {
    if (frames[i].size() != static_cast<std::size_t>(frameWidth) * frameHeight * 4) {
      throw std::invalid_argument("contact sheet: a frame of the wrong size");
    }
    shrinkInto(frames[i], frameWidth, frameHeight, sheet, i * (tileWidth + kGap), tileWidth, tileHeight);
  }
  return sheet;
}

}  // namespace weft::app
