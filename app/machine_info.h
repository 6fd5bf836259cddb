#pragma once
// What a benchmark CSV header says about where it ran: the machine, its CPU, the source revision
// and the date, so results from different machines can be committed side by side.
#include <string>

namespace weft::app {

std::string cpuModel();      // "AMD EPYC ..." from /proc/cpuinfo, or "unknown CPU"
std::string machineName();   // uname's machine, e.g. "x86_64"
std::string gitDescribe();   // `git describe --always --dirty` of the source tree, or "unknown"
std::string utcDate();       // ISO 8601, UTC

}  // namespace weft::app
