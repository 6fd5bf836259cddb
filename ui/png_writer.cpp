#include "png_writer.h"

#include <stb_image_write.h>

#include <stdexcept>

#include "util/atomic_file.h"

namespace weft::ui {

std::string encodePng(const std::vector<std::uint8_t>& rgba, int width, int height) {
  if (rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    throw std::runtime_error("PNG: pixel buffer size does not match the image size");
  }
  std::string bytes;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(append, &bytes, width, height, 4, rgba.data(), width * 4) == 0) {
    throw std::runtime_error("PNG: stb_image_write could not encode the image");
  }
  return bytes;
}

void writePng(const std::filesystem::path& file, const std::vector<std::uint8_t>& rgba, int width, int height) {
  writeFileAtomically(file, encodePng(rgba, width, height));
}

}  // namespace weft::ui
