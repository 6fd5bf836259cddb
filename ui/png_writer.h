#pragma once
// RGBA8 pixels to PNG bytes (stb_image_write), and a PNG file written atomically.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace weft::ui {

// `rgba`: width*height*4 bytes, rows top-down. Throws std::runtime_error when encoding fails.
std::string encodePng(const std::vector<std::uint8_t>& rgba, int width, int height);

// Writes the PNG through a temporary file and a rename (util/atomic_file.h).
void writePng(const std::filesystem::path& file, const std::vector<std::uint8_t>& rgba, int width, int height);

}  // namespace weft::ui
