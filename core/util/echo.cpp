#include "util/echo.h"

#include <algorithm>
#include <cstdio>

namespace weft {
namespace {

// Length of the UTF-8 sequence starting at text[i], or 0 when it is not a valid one
// (overlong forms, surrogates and code points past U+10FFFF count as invalid, as in RFC 3629).
std::size_t utf8Length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF) length = 2;
  else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) lo = 0xA0;
    if (lead == 0xED) hi = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) lo = 0x90;
    if (lead == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

std::string hexEscape(const char* format, unsigned value) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace

bool isValidUtf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8Length(text, i);
    if (length == 0) return false;
    i += length;
  }
  return true;
}

std::string echo(std::string_view text, std::size_t maxBytes) {
  static constexpr std::string_view kEllipsis = "…";
  const std::size_t limit = std::max(maxBytes, kEllipsis.size());
  std::string out;
  // Where to cut if the text turns out not to fit: the end of the last whole unit (character or
  // escape) that leaves room for the ellipsis.
  std::size_t cut = 0;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8Length(text, i);
    const auto c = static_cast<unsigned char>(text[i]);
    if (length == 0) {
      out += hexEscape("\\x%02X", c);
      i += 1;
    } else if (c == '\n') {
      out += "\\n", i += 1;
    } else if (c == '\t') {
      out += "\\t", i += 1;
    } else if (c < 0x20 || c == 0x7F) {
      out += hexEscape("\\u%04X", c);
      i += 1;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
    if (out.size() > limit) {
      out.resize(cut);
      return out.append(kEllipsis);
    }
    if (out.size() + kEllipsis.size() <= limit) cut = out.size();
  }
  return out;
}

}  // namespace weft
