#pragma once
// PNG files to RGBA8 pixels (stb_image), the reverse of png_writer.h: the editor's cached scene
// thumbnails are read back with it.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace weft::ui {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width*height*4 bytes, rows top-down
};

// None when the file cannot be read or is not a PNG stb_image decodes.
std::optional<RgbaImage> readPng(const std::filesystem::path& file);

}  // namespace weft::ui
