#pragma once
// Showing a user's text inside a message. Anything a user wrote can be echoed back (a name, a
// path, a wrong value), and anything can be megabytes long, hold control characters that cut a
// terminal line short (a "\u0000" ends a C string), or not be UTF-8 at all. Every echo goes
// through here so that a message stays one short line whatever the input.
#include <cstddef>
#include <string>
#include <string_view>

namespace weft {

// Echoed values longer than this many characters are cut and end with "…".
inline constexpr std::size_t kEchoLimit = 80;

// `text` as one printable line: control characters written as \n, \t or \u00XX, bytes that are
// not UTF-8 as \xNN, and at most `limit` characters followed by "…" when longer. Never cuts a
// UTF-8 character in half.
std::string echo(std::string_view text, std::size_t limit = kEchoLimit);

// True when `text` is valid UTF-8 (what JSON text must be).
bool isValidUtf8(std::string_view text);

}  // namespace weft
