#pragma once
// What a benchmark CSV header says about where it ran (the machine, its CPU, the source revision
// and the date, so results from different machines can be committed side by side), and writing it.
#include <string>

namespace weft::app {

std::string cpuModel();      // "AMD EPYC ..." from /proc/cpuinfo, or "unknown CPU"
std::string machineName();   // uname's machine, e.g. "x86_64"
std::string gitDescribe();   // `git describe --always --dirty` of the source tree, or "unknown"
std::string utcDate();       // ISO 8601, UTC

// The first line of a benchmark CSV: "# weft bench[ FLAG]; machine: ...; cpu: ...; cores: ...;
// threads: ...; git: ...; date: ...; scene: SCENE\n".
std::string benchCsvMachineLine(const std::string& command, int threads, const std::string& scene);

// Writes a benchmark's CSV atomically, creating its folder, and says where; on failure prints
// "weft: cannot write FILE: why" and returns false.
bool writeBenchCsv(const std::string& file, const std::string& text);

}  // namespace weft::app
