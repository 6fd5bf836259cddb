#pragma once
// Shared by the fuzz targets whose loader reads a file: a private folder per fuzzing process in
// memory (/dev/shm when there is one, else the temporary folder), and the input's bytes written
// there under a given name. A file per execution is what the loaders read; kept off the disk it
// costs little. libFuzzer ends with _Exit, so scripts/fuzz.sh removes the folder.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace weft::fuzz {

inline const std::filesystem::path& scratchDir() {
  static const std::filesystem::path dir = [] {
    std::error_code error;
    const std::filesystem::path base = std::filesystem::is_directory("/dev/shm", error)
                                           ? std::filesystem::path("/dev/shm")
                                           : std::filesystem::temp_directory_path();
    const std::filesystem::path d = base / ("weft_fuzz_" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

// Writes the input to scratchDir()/name (truncating) and returns the file's path.
inline std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size, const std::string& name) {
  const std::filesystem::path file = scratchDir() / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
}

}  // namespace weft::fuzz
