// The strict JSON reader: what nlohmann::json would accept silently or crash on is an InputError
// naming the file and the JSON pointer; everything else reads exactly as nlohmann's parser reads it.
#include "util/json_text.h"

#include <gtest/gtest.h>

#include <string>

#include "util/input_error.h"

namespace weft {
namespace {

using nlohmann::json;

InputError errorOf(const std::string& text, JsonTextOptions options = {}) {
  try {
    (void)parseJsonText(text, "file.json", options);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text.substr(0, 80);
  return InputError("", "", "");
}

TEST(JsonText, ReadsWhatNlohmannReads) {
  const std::string text = R"({"a": [1, -2, 3.5, 1e300, true, null, "x\u00e9"], "b": {"c": {}}, "d": [], "e": 18446744073709551615})";
  EXPECT_EQ(parseJsonText(text, "file.json"), json::parse(text));
  EXPECT_EQ(parseJsonText("  42 ", "file.json"), json(42));
  // A UTF-8 byte order mark is skipped, as nlohmann does.
  EXPECT_EQ(parseJsonText("\xEF\xBB\xBF{\"a\": 1}", "file.json"), json::parse(R"({"a": 1})"));
}

TEST(JsonText, RefusesADuplicateKeyNamingIt) {
  const InputError e = errorOf(R"({"solver": {"dt": 0.01, "dt": 0.5}})");
  EXPECT_EQ(e.file(), "file.json");
  EXPECT_EQ(e.field(), "/solver/dt");
  EXPECT_NE(e.message().find("duplicate key \"dt\""), std::string::npos) << e.what();
  // The same key in two different objects is fine.
  EXPECT_NO_THROW((void)parseJsonText(R"([{"dt": 1}, {"dt": 2}])", "file.json"));
  // Keys that need escaping in a pointer are escaped.
  EXPECT_EQ(errorOf(R"({"a/b": {"x": 1, "x": 2}})").field(), "/a~1b/x");
}

TEST(JsonText, BoundsTheNesting) {
  const auto nested = [](int depth) { return std::string(depth, '[') + std::string(depth, ']'); };
  EXPECT_NO_THROW((void)parseJsonText(nested(kMaxJsonDepth), "file.json"));
  const InputError e = errorOf(nested(kMaxJsonDepth + 1));
  EXPECT_NE(e.message().find("nested deeper than 64"), std::string::npos) << e.what();
  // The depth that once overflowed the stack, in arrays and in objects.
  EXPECT_NE(errorOf(nested(100'000)).message().find("nested deeper"), std::string::npos);
  std::string objects;
  for (int i = 0; i < 100'000; ++i) objects += "{\"k\":";
  objects += "1" + std::string(100'000, '}');
  const InputError o = errorOf(objects);
  EXPECT_EQ(o.field().rfind("/k/k/k", 0), 0u);
  EXPECT_LT(std::string(o.what()).size(), 600u);
}

TEST(JsonText, RefusesNulInStringsAndKeys) {
  EXPECT_EQ(errorOf(R"({"path": "a\u0000b.obj"})").field(), "/path");
  EXPECT_NE(errorOf(R"({"a\u0000": 1})").message().find("\\u0000"), std::string::npos);
}

TEST(JsonText, RefusesNumbersBeyondADouble) {
  const InputError e = errorOf(R"({"x": [1, 1e999]})");
  EXPECT_EQ(e.field(), "/x/1");
  EXPECT_NE(e.message().find("too large"), std::string::npos) << e.what();
}

TEST(JsonText, SyntaxErrorsSayWhereAndStayShort) {
  const InputError e = errorOf("{\"a\": 1,\n \"b\": }");
  EXPECT_NE(e.message().find("not valid JSON"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("line 2"), std::string::npos) << e.what();
  // Invalid UTF-8 inside a string (the lexer checks it); the long token is not echoed in full.
  const InputError utf8 = errorOf("{\"a\": \"" + std::string(100'000, 'x') + "\xff\"}");
  EXPECT_NE(utf8.message().find("not valid JSON"), std::string::npos);
  EXPECT_LT(std::string(utf8.what()).size(), 600u);
}

TEST(JsonText, CommentsOnlyWhenAllowed) {
  const std::string text = "// a scene\n{\"a\": 1 /* one */}";
  EXPECT_NE(errorOf(text).message().find("not valid JSON"), std::string::npos);
  EXPECT_EQ(parseJsonText(text, "file.json", JsonTextOptions{.allowComments = true}), json::parse(R"({"a": 1})"));
}

}  // namespace
}  // namespace weft
