// Echoing user text in messages: one short printable line whatever the bytes.
#include "util/echo.h"

#include <gtest/gtest.h>

#include <string>

namespace weft {
namespace {

TEST(Echo, ShortTextIsUnchanged) {
  EXPECT_EQ(echo("royal-target"), "royal-target");
  EXPECT_EQ(echo("fibre é 繊維"), "fibre é 繊維");
  EXPECT_EQ(echo(""), "");
}

TEST(Echo, CutsLongTextAtTheLimitWithAnEllipsis) {
  EXPECT_EQ(echo(std::string(kEchoLimit, 'a')), std::string(kEchoLimit, 'a'));
  // The "…" (3 bytes) counts against the limit.
  EXPECT_EQ(echo(std::string(kEchoLimit + 1, 'a')), std::string(kEchoLimit - 3, 'a') + "…");
  EXPECT_EQ(echo(std::string(100'000, 'a')), std::string(kEchoLimit - 3, 'a') + "…");
}

// The limit counts bytes: text of multi-byte characters is cut as short in bytes as ASCII is, and
// never in the middle of a character, whichever byte of it the limit falls on.
TEST(Echo, LimitCountsBytesAndNeverSplitsACharacter) {
  for (const std::string character : {"é", "繊", "\xF0\x9F\xA7\xB5"}) {  // 2, 3 and 4 bytes
    std::string wide;
    for (int i = 0; i < 1000; ++i) wide += character;
    for (std::size_t limit = 3; limit <= 40; ++limit) {
      const std::string shown = echo(wide, limit);
      EXPECT_LE(shown.size(), limit) << character << " limit " << limit;
      EXPECT_TRUE(isValidUtf8(shown)) << character << " limit " << limit;
      ASSERT_GE(shown.size(), 3u);
      EXPECT_EQ(shown.substr(shown.size() - 3), "…");
      // As many whole characters as fit beside the "…".
      const std::size_t kept = (limit - 3) / character.size();
      EXPECT_EQ(shown.size(), kept * character.size() + 3) << character << " limit " << limit;
    }
    // Text that fits exactly is shown whole, with no "…".
    const std::string exact = wide.substr(0, 10 * character.size());
    EXPECT_EQ(echo(exact, exact.size()), exact);
  }
  EXPECT_EQ(echo("ééééé", 9), "ééé…");  // 9 bytes: three 2-byte characters and the "…"
  EXPECT_EQ(echo("ééééé", 10), "ééééé");
}

TEST(Echo, EscapesAreNeverSplitEither) {
  // Each \u0000 escape is 6 bytes; 100 of them are cut to whole escapes within the limit.
  const std::string shown = echo(std::string(100, '\0'), 20);
  EXPECT_EQ(shown, "\\u0000\\u0000…");  // 12 + 3 bytes; a third escape would make 21
  EXPECT_EQ(echo(std::string(100, '\xff'), 20), "\\xFF\\xFF\\xFF\\xFF…");  // 4 x 4 + 3
  EXPECT_EQ(echo(std::string(3, 'a'), 0), "aaa");  // a limit below the ellipsis is taken as 3
  EXPECT_EQ(echo(std::string(4, 'a'), 0), "…");
}

TEST(Echo, ControlCharactersAndBadBytesAreEscaped) {
  EXPECT_EQ(echo(std::string("a\0b", 3)), "a\\u0000b");
  EXPECT_EQ(echo("a\nb\tc\x1b"), "a\\nb\\tc\\u001B");
  EXPECT_EQ(echo("name=\xff\xfe"), "name=\\xFF\\xFE");
  EXPECT_TRUE(isValidUtf8(echo("\xc3\x28 \xed\xa0\x80")));  // a broken pair and a surrogate
}

TEST(Echo, RecognisesUtf8) {
  EXPECT_TRUE(isValidUtf8("plain ascii"));
  EXPECT_TRUE(isValidUtf8("é 繊維 \xF0\x9F\xA7\xB5"));
  EXPECT_FALSE(isValidUtf8("\xff"));
  EXPECT_FALSE(isValidUtf8("\xc0\xaf"));          // overlong '/'
  EXPECT_FALSE(isValidUtf8("\xed\xa0\x80"));      // a surrogate
  EXPECT_FALSE(isValidUtf8("\xe2\x82"));          // cut short
  EXPECT_FALSE(isValidUtf8("\xf4\x90\x80\x80"));  // past U+10FFFF
}

}  // namespace
}  // namespace weft
