#pragma once
// Checks on the text of an OBJ file that tinyobjloader does not make. It reads a malformed or
// "nan" coordinate as 0, a `v` line with two numbers as a vertex with z = 0, and a face index
// past 2^32 modulo 2^32 (4294967299 becomes 3), all without a word, and keeps a UTF-8 byte order
// mark as part of the first keyword (dropping the first vertex). Any of these would change a
// cloth's or a tool's shape silently. Shared by the cloth loader (mesh/obj_import) and the
// obstacle loader (rigid/closed_obj_import).
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace weft {

struct ObjTextProblem {
  int line = 0;         // 1-based
  std::string message;  // "'1.0x' is not a number", "non-finite value 'nan'"
};

// The first malformed line: on a line whose keyword is one of `keywords` (e.g. "v", "vt"), a
// number that does not parse in full or is not finite, or too few numbers (a `v` needs x, y and
// z; a `vt` needs u and v); on an `f` line, an index that is not a non-zero integer that fits
// an int.
std::optional<ObjTextProblem> findBadCoordinate(const std::string& text, std::initializer_list<std::string_view> keywords);

// The line of tinyobjloader's `messages` (its Warning() or Error(), one message per line) that
// holds `phrase` (or else the first line), echoed short (util/echo.h). Its messages quote the
// file, e.g. a `usemtl` name of any length and bytes, and it lists one per unknown material
// before the one that matters: whole, they once made a 2.6 KB error message.
std::string tinyobjMessage(const std::string& messages, std::string_view phrase = {});

// `text` without a leading UTF-8 byte order mark, which some Windows tools write.
std::string withoutByteOrderMark(std::string text);

}  // namespace weft
