#include "util/obj_text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace weft {

std::optional<ObjTextProblem> findBadCoordinate(const std::string& text, std::initializer_list<std::string_view> keywords) {
  std::istringstream lines(text);
  std::string line;
  for (int lineNumber = 1; std::getline(lines, line); ++lineNumber) {
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    if (std::find(keywords.begin(), keywords.end(), keyword) == keywords.end()) continue;
    std::string token;
    while (tokens >> token) {
      if (token[0] == '#') break;  // trailing comment
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (end != token.c_str() + token.size()) return ObjTextProblem{lineNumber, "'" + token + "' is not a number"};
      if (!std::isfinite(value)) return ObjTextProblem{lineNumber, "non-finite value '" + token + "'"};
    }
  }
  return std::nullopt;
}

}  // namespace weft
