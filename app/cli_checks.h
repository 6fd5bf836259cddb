#pragma once
// Checks of command-line numbers. CLI11's own PositiveNumber and NonNegativeNumber say "not in
// range" for a word ("--frames abc") and print their upper bound, DBL_MAX, as a 309-digit number;
// these say what is wrong in a short line: "--frames: 'abc' is not an integer in [0, 1000000]".
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "util/echo.h"

namespace weft::app {

inline CLI::Validator integerIn(long long lo, long long hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const long long value = std::strtoll(text.c_str(), &end, 10);
        const bool integer = !text.empty() && end == text.c_str() + text.size() && errno == 0;
        if (!integer) return "'" + echo(text) + "' is not an integer in " + range;
        if (value < lo || value > hi) return text + " is outside " + range;
        return {};
      },
      "INT in " + range);
}

// A real number in [lo, hi]. CLI11's own Range and PositiveNumber let "nan" through (every
// comparison with NaN is false), and a NaN duration ran a benchmark on it.
inline CLI::Validator numberIn(double lo, double hi) {
  std::ostringstream bounds;
  bounds << "[" << lo << ", " << hi << "]";
  const std::string range = bounds.str();
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool number = !text.empty() && end == text.c_str() + text.size() && errno != ERANGE;
        if (!number || !std::isfinite(value)) return "'" + echo(text) + "' is not a number in " + range;
        if (value < lo || value > hi) return echo(text) + " is outside " + range;
        return {};
      },
      "NUMBER in " + range);
}

}  // namespace weft::app
