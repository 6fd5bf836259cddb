#pragma once
// Showing a user's text inside a message. Anything a user wrote can be echoed back (a name, a
// path, a wrong value), and anything can be megabytes long, hold control characters that cut a
// terminal line short (a "\u0000" ends a C string), or not be UTF-8 at all. Every echo goes
// through here so that a message stays one short line whatever the input.
//
// Limits count bytes, not characters: a byte cap is what bounds a message's size on a terminal, in
// a log or in metrics.json, and a character cap lets 80 four-byte characters (or 80 six-byte
// escapes) through as 320 or 480 bytes.
#include <cstddef>
#include <string>
#include <string_view>

namespace weft {

// Echoed values are cut to at most this many bytes, the closing "…" included.
inline constexpr std::size_t kEchoLimit = 80;

// `text` as one printable line: control characters written as \n, \t or \u00XX, bytes that are
// not UTF-8 as \xNN, and at most `maxBytes` bytes in all. Longer text is cut before the first
// character or escape that would not fit with the "…" (3 bytes) that then ends it, so a UTF-8
// character or an escape is never cut in half and the result is always valid UTF-8. `maxBytes`
// below 3 is taken as 3 (room for the "…" alone).
std::string echo(std::string_view text, std::size_t maxBytes = kEchoLimit);

// True when `text` is valid UTF-8 (what JSON text must be).
bool isValidUtf8(std::string_view text);

}  // namespace weft
