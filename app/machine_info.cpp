#include "machine_info.h"

#include <sys/utsname.h>

#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <sstream>
#include <thread>
#include <fstream>

#include "util/atomic_file.h"

namespace weft::app {

std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  }
  return "unknown CPU";
}

std::string machineName() {
  utsname names{};
  return uname(&names) == 0 ? std::string(names.machine) : std::string("unknown");
}

std::string gitDescribe() {
  const std::string command = std::string("git -C '") + WEFT_SOURCE_DIR + "' describe --always --dirty 2>/dev/null";
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    pclose(pipe);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out.empty() ? "unknown" : out;
}

std::string utcDate() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::string benchCsvMachineLine(const std::string& command, int threads, const std::string& scene) {
  std::ostringstream line;
  line << "# " << command << "; machine: " << machineName() << "; cpu: " << cpuModel()
       << "; cores: " << std::thread::hardware_concurrency() << "; threads: " << threads << "; git: " << gitDescribe()
       << "; date: " << utcDate() << "; scene: " << scene << "\n";
  return line.str();
}

bool writeBenchCsv(const std::string& file, const std::string& text) {
  try {
    const std::filesystem::path path(file);
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    writeFileAtomically(path, text);
    std::printf("wrote %s\n", file.c_str());
    return true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "weft: cannot write %s: %s\n", file.c_str(), e.what());
    return false;
  }
}

}  // namespace weft::app
