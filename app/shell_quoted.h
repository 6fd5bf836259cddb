#pragma once
// A string as one word of a POSIX shell command line: in single quotes, each quote inside written
// as '\'' (the commands that run ffmpeg through popen take file names with any characters).
#include <string>

namespace weft::app {

inline std::string shellQuoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace weft::app
