#pragma once
// Shared by the fuzz targets that read a scene: a scene resolves the presets and assets it names
// against its search folders, but a name that is an absolute path or holds ".." can reach any file
// on the machine (a FIFO, /dev/zero, a 10 GB log). Fuzzing is about the readers, not the files a
// machine happens to hold, so such inputs are skipped before the reader sees them (which also
// keeps them out of the corpus).
#include <string>

#include <nlohmann/json.hpp>

namespace weft::fuzz {

// True when some string in `j` could name a file outside the search folders.
inline bool leavesSearchPaths(const nlohmann::json& j) {
  if (j.is_string()) {
    const std::string& s = j.get_ref<const std::string&>();
    return (!s.empty() && s.front() == '/') || s.find("..") != std::string::npos;
  }
  if (j.is_structured()) {
    for (const auto& child : j) {
      if (leavesSearchPaths(child)) return true;
    }
  }
  return false;
}

}  // namespace weft::fuzz
