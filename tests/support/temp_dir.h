#pragma once
// A fresh folder per test under the system's temporary folder, removed with everything in it
// when the test ends.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace weft::test {

class TempDir {
 public:
  explicit TempDir(const std::string& prefix = "weft_test_") {
    std::random_device seed;
    // Ten digits always: a path's length shows in the editor's panels (a tags file's path wraps),
    // so names of varying length made the panels' layout differ from run to run.
    std::string digits = std::to_string(seed());
    digits.insert(0, 10 - digits.size(), '0');
    path_ = std::filesystem::temp_directory_path() / (prefix + digits);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& contents) const {
    const std::filesystem::path file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << contents;
    return file;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace weft::test
