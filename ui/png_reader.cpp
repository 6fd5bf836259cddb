#include "png_reader.h"

#include <stb_image.h>

namespace weft::ui {

std::optional<RgbaImage> readPng(const std::filesystem::path& file) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load(file.c_str(), &width, &height, &channels, 4);
  if (pixels == nullptr) return std::nullopt;
  RgbaImage image;
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels, pixels + static_cast<std::size_t>(width) * height * 4);
  stbi_image_free(pixels);
  return image;
}

}  // namespace weft::ui
