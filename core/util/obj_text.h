#pragma once
// Checks on the text of an OBJ file that tinyobjloader does not make: it reads a malformed or
// "nan" coordinate as 0 without a word, which would change a cloth's or a tool's shape silently.
// Shared by the cloth loader (mesh/obj_import) and the obstacle loader (rigid/closed_obj_import).
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace weft {

struct ObjTextProblem {
  int line = 0;         // 1-based
  std::string message;  // "'1.0x' is not a number", "non-finite value 'nan'"
};

// The first number on a line whose keyword is one of `keywords` (e.g. "v", "vt") that does not
// parse in full or is not finite.
std::optional<ObjTextProblem> findBadCoordinate(const std::string& text, std::initializer_list<std::string_view> keywords);

}  // namespace weft
