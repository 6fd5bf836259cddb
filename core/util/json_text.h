#pragma once
// Reading JSON text into a value, strictly and within bounds: the one way scene files, material
// presets, tear tables, sharp-tag files and `--set` values are read.
//
// nlohmann::json accepts what a hostile file can use against us: a key written twice (the last
// one silently wins), nesting 100,000 levels deep (parsing is iterative, but dump(), copies and
// comparisons recurse and overflow the stack), "\u0000" inside a string (cuts a file name or a
// message short), and numbers too large for a double. Here each is an InputError naming the file
// and the JSON pointer of the offending value, before any other code sees the value.
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace weft {

// Deepest nesting of arrays and objects accepted. Our formats need at most 7 levels (a scene's
// obstacle script keys); 64 leaves room for any hand-written file.
inline constexpr int kMaxJsonDepth = 64;

struct JsonTextOptions {
  bool allowComments = false;  // scene files may hold // and /* */ comments
};

// Parses `text`; `file` names it in errors (for `--set`, the override). Throws InputError for
// malformed JSON, invalid UTF-8, a duplicate key, nesting deeper than kMaxJsonDepth, a string
// holding U+0000, or a number outside the range of a double.
nlohmann::json parseJsonText(std::string_view text, const std::string& file, JsonTextOptions options = {});

// Reads and parses a whole file; `what` names it in the error when it cannot be opened
// ("the scene file", "the material file").
nlohmann::json readJsonFile(const std::filesystem::path& file, const std::string& what, JsonTextOptions options = {});

}  // namespace weft
