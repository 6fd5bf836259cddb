#pragma once
// Checks of command-line numbers. CLI11's own PositiveNumber and NonNegativeNumber say "not in
// range" for a word ("--frames abc") and print their upper bound, DBL_MAX, as a 309-digit number;
// these say what is wrong in a short line: "--frames: 'abc' is not an integer in [0, 1000000]".
#include <cerrno>
#include <cstdlib>
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

}  // namespace weft::app
