#include "util/obj_text.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "util/echo.h"

namespace weft {
namespace {

// Fewest numbers a line of this keyword must hold to mean what the loaders read from it.
std::size_t requiredNumbers(std::string_view keyword) {
  if (keyword == "v") return 3;   // x y z [w] (or x y z r g b)
  if (keyword == "vt") return 2;  // u v [w]: a cloth's rest shape needs both
  return 0;
}

// One corner of an `f` line: v, v/vt, v//vn or v/vt/vn, each a non-zero int (negative: relative).
std::optional<std::string> badFaceCorner(const std::string& corner) {
  std::stringstream parts(corner);
  std::string part;
  int position = 0;
  while (std::getline(parts, part, '/')) {
    ++position;
    if (part.empty() && position > 1) continue;  // v//vn
    errno = 0;
    char* end = nullptr;
    const long long value = std::strtoll(part.c_str(), &end, 10);
    if (part.empty() || end != part.c_str() + part.size()) return "'" + echo(corner) + "' is not a face corner (v/vt/vn)";
    if (errno == ERANGE || value > INT_MAX || value < -INT_MAX || value == 0) {
      return "index " + echo(part) + " in '" + echo(corner) + "' is out of range (indices count from 1)";
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<ObjTextProblem> findBadCoordinate(const std::string& text, std::initializer_list<std::string_view> keywords) {
  std::istringstream lines(text);
  std::string line;
  for (int lineNumber = 1; std::getline(lines, line); ++lineNumber) {
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    std::string token;
    if (keyword == "f") {
      while (tokens >> token && token[0] != '#') {
        if (const auto problem = badFaceCorner(token)) return ObjTextProblem{lineNumber, *problem};
      }
      continue;
    }
    if (std::find(keywords.begin(), keywords.end(), keyword) == keywords.end()) continue;
    std::size_t numbers = 0;
    while (tokens >> token) {
      if (token[0] == '#') break;  // trailing comment
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (end != token.c_str() + token.size()) return ObjTextProblem{lineNumber, "'" + echo(token) + "' is not a number"};
      if (!std::isfinite(value)) return ObjTextProblem{lineNumber, "non-finite value '" + echo(token) + "'"};
      ++numbers;
    }
    if (numbers < requiredNumbers(keyword)) {
      return ObjTextProblem{lineNumber, "a '" + keyword + "' line needs at least " +
                                            std::to_string(requiredNumbers(keyword)) + " numbers, got " +
                                            std::to_string(numbers)};
    }
  }
  return std::nullopt;
}

std::string tinyobjMessage(const std::string& messages, std::string_view phrase) {
  const std::size_t at = phrase.empty() ? std::string::npos : messages.find(phrase);
  const std::size_t begin = at == std::string::npos ? 0 : messages.rfind('\n', at) + 1;  // npos + 1 == 0
  const std::size_t end = messages.find('\n', begin);
  return echo(std::string_view(messages).substr(begin, end == std::string::npos ? std::string::npos : end - begin), 200);
}

std::string withoutByteOrderMark(std::string text) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  return text;
}

}  // namespace weft
