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
  EXPECT_EQ(echo(std::string(100'000, 'a')), std::string(kEchoLimit, 'a') + "…");
  // Characters, not bytes, are counted, and a multi-byte character is never cut in half.
  std::string wide;
  for (int i = 0; i < 100; ++i) wide += "é";
  const std::string shown = echo(wide, 10);
  EXPECT_EQ(shown, std::string("éééééééééé") + "…");
  EXPECT_TRUE(isValidUtf8(shown));
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
