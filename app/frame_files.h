#pragma once
// The frame files a run writes into its frames folder, and clearing those of an earlier run (so a
// shorter run does not leave stale frames behind), whatever their format.
#include <filesystem>
#include <initializer_list>
#include <string>
#include <system_error>
#include <vector>

namespace weft::app {

// Removes the files in `framesDir` with the given extension (".obj") whose names start with one
// of `prefixes`; nothing else in the folder is touched. A missing folder is fine.
inline void removeFrameFiles(const std::filesystem::path& framesDir, const std::string& extension,
                             std::initializer_list<const char*> prefixes) {
  std::error_code ec;
  if (!std::filesystem::is_directory(framesDir, ec)) return;
  std::vector<std::filesystem::path> old;
  for (const auto& entry : std::filesystem::directory_iterator(framesDir, ec)) {
    const std::string name = entry.path().filename().string();
    bool ours = false;
    for (const char* prefix : prefixes) ours = ours || name.rfind(prefix, 0) == 0;
    if (ours && entry.path().extension() == extension) old.push_back(entry.path());
  }
  for (const auto& file : old) std::filesystem::remove(file, ec);
}

}  // namespace weft::app
