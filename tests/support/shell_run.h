#pragma once
// Runs a shell line the way the command-line tests run `weft`: stdout and stderr into one log
// file, then read back with the exit status.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace weft::test {

struct ShellResult {
  int exitCode = -1;   // -1 when the command did not exit normally
  std::string output;  // stdout and stderr together
};

inline ShellResult runShell(const std::string& line, const std::filesystem::path& log) {
  const int status = std::system((line + " > '" + log.string() + "' 2>&1").c_str());
  ShellResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  r.output = text.str();
  return r;
}

}  // namespace weft::test
