// The strict field reader shared by the scene and material formats: every rejection names the
// file, the exact JSON pointer and what was expected.
#include "util/json_fields.h"

#include <functional>
#include <initializer_list>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace weft {
namespace {

using nlohmann::json;

// `read` must throw an InputError for "in.json" at `field` whose message mentions every word given.
void expectRejected(const std::function<void()>& read, const std::string& field,
                    std::initializer_list<std::string> mentions) {
  try {
    read();
    ADD_FAILURE() << "no InputError at " << field;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), "in.json") << what;
    EXPECT_EQ(e.field(), field) << what;
    EXPECT_EQ(what.rfind("in.json: " + (field.empty() ? "" : field + ": "), 0), 0u) << what;
    for (const auto& word : mentions) EXPECT_NE(what.find(word), std::string::npos) << "'" << word << "' in: " << what;
  }
}

TEST(JsonFields, PointerEscapesSlashAndTilde) {
  EXPECT_EQ(childPointer("", "a"), "/a");
  EXPECT_EQ(childPointer("/x", "a/b~c"), "/x/a~1b~0c");
  EXPECT_EQ(childPointer("/x", "~1"), "/x/~01");  // an escape-looking key is escaped, not kept
  EXPECT_EQ(childPointer("/x", std::size_t{3}), "/x/3");
  // The escaped pointer leads back to the key.
  const json j = {{"x", {{"a/b~c", 7}}}};
  EXPECT_EQ(j.at(json::json_pointer(childPointer("/x", "a/b~c"))), 7);
}

TEST(JsonFields, UnknownKeyIsNamedWithTheAllowedOnes) {
  const json j = {{"dt", 0.01}, {"a/b", 1}};
  expectRejected([&] { FieldReader(j, "/solver", "in.json", {"dt", "substeps"}); }, "/solver/a~1b",
                 {"unknown key \"a/b\"", "allowed keys here: dt, substeps"});
  const FieldReader r(j, "/solver", "in.json");  // keys checked later, once they are known
  expectRejected([&] { r.allowOnly({"a/b"}); }, "/solver/dt", {"unknown key \"dt\"", "a/b"});
}

TEST(JsonFields, NonObjectIsRejected) {
  const json pair = json::array({1, 2});
  expectRejected([&] { FieldReader(pair, "", "in.json", std::vector<std::string>{}); }, "", {"object", "got array [1,2]"});
  expectRejected([&] { FieldReader(pair, "/m", "in.json", GotStyle::Kind); }, "/m",
                 {"object", "got an array of 2"});
}

TEST(JsonFields, MissingRequiredFieldNamesWhatWasExpected) {
  const json empty = json::object();
  const FieldReader r(empty, "/cloths/0", "in.json", {"mesh"});
  expectRejected([&] { r.required("mesh", "a mesh object"); }, "/cloths/0/mesh", {"missing", "\"mesh\"", "a mesh object"});
  expectRejected([&] { r.requiredNumber("mesh", Bound::Positive, "the size"); }, "/cloths/0/mesh", {"missing"});
  expectRejected([&] { r.requiredString("mesh", "a name"); }, "/cloths/0/mesh", {"missing"});
}

TEST(JsonFields, WrongTypeShowsWhatWasFound) {
  const json j = {{"dt", "fast"}, {"on", 1}, {"name", 7}, {"empty", ""}, {"list", 3}};
  const FieldReader asWritten(j, "", "in.json");
  expectRejected([&] { asWritten.number("dt", 1.0, Bound::Positive); }, "/dt", {"positive", "got string \"fast\""});
  expectRejected([&] { asWritten.boolean("on", false); }, "/on", {"true or false", "got 1"});
  expectRejected([&] { asWritten.string("name", ""); }, "/name", {"string", "got 7"});
  expectRejected([&] { asWritten.array("list"); }, "/list", {"array", "got 3"});
  expectRejected([&] { asWritten.integer("dt", 1, 1); }, "/dt", {"integer"});
  const FieldReader kind(j, "", "in.json", GotStyle::Kind);
  expectRejected([&] { kind.requiredNumber("dt", Bound::Finite, "the step in s"); }, "/dt",
                 {"the step in s must be a finite number", "got a string"});
  expectRejected([&] { kind.requiredString("empty", "the name"); }, "/empty", {"non-empty string"});
  EXPECT_EQ(asWritten.number("absent", 2.5, Bound::Positive), 2.5);  // optional fields fall back
}

TEST(JsonFields, BoundsAreEnforced) {
  const json j = {{"neg", -1}, {"zero", 0}, {"half", 0.5}, {"two", 2}, {"frac", 1.5}, {"ten", 10.0}};
  const FieldReader r(j, "/s", "in.json");
  expectRejected([&] { r.number("zero", 1, Bound::Positive); }, "/s/zero", {"> 0", "got 0"});
  expectRejected([&] { r.number("neg", 1, Bound::NonNegative); }, "/s/neg", {">= 0", "got -1"});
  expectRejected([&] { r.number("two", 1, Bound::UnitInterval); }, "/s/two", {"[0, 1]", "got 2"});
  expectRejected([&] { r.integer("frac", 1, 1); }, "/s/frac", {"integer >= 1", "got 1.5"});
  expectRejected([&] { r.integer("zero", 1, 1); }, "/s/zero", {"integer >= 1"});
  EXPECT_EQ(r.number("zero", 1, Bound::NonNegative), 0.0);
  EXPECT_EQ(r.number("half", 1, Bound::UnitInterval), 0.5);
  EXPECT_EQ(r.integer("ten", 1, 1), 10);  // 10.0 is accepted as 10

  // NaN and infinity cannot come from JSON text, but can from a json built in code.
  const json bad = {{"nan", std::numeric_limits<double>::quiet_NaN()}, {"inf", std::numeric_limits<double>::infinity()}};
  const FieldReader b(bad, "", "in.json");
  expectRejected([&] { b.number("nan", 1, Bound::Finite); }, "/nan", {"finite", "got NaN"});
  expectRejected([&] { b.number("inf", 1, Bound::Positive); }, "/inf", {"finite", "got inf"});
}

TEST(JsonFields, ExactLabelMustMatch) {
  const json j = {{"units", "kN/m"}};
  const FieldReader r(j, "", "in.json");
  expectRejected([&] { r.requireExactly("units", "N/m"); }, "/units", {"exactly \"N/m\"", "\"kN/m\""});
}

TEST(JsonFields, FixedSizeRowsAndTables) {
  const json empty = json::object();
  const FieldReader r(empty, "", "in.json");
  EXPECT_EQ((r.numberRow<3>(json::array({1, 2, 3}), "/v")), (std::array<double, 3>{1, 2, 3}));
  expectRejected([&] { r.numberRow<3>(json::array({0, -9.81}), "/gravity"); }, "/gravity",
                 {"3 numbers", "3 finite", "got array [0,-9.81]"});
  expectRejected([&] { r.numberRow<2>(json::array({1, nullptr}), "/v"); }, "/v/1", {"finite", "got null"});

  const FieldReader kind(empty, "", "in.json", GotStyle::Kind);
  const json table = json::array({json::array({1, 2}), json::array({3})});
  expectRejected([&] { kind.numberTable<2, 2>(table, "/t", "the samples"); }, "/t/1",
                 {"row 1 of the samples", "2 numbers", "got an array of 1"});
  expectRejected([&] { kind.numberTable<3, 2>(table, "/t"); }, "/t", {"3 rows of 2 numbers", "got an array of 2"});
  const auto ok = kind.numberTable<2, 2>(json::array({json::array({1, 2}), json::array({3, 4})}), "/t");
  EXPECT_EQ(ok[1][0], 3.0);
}

}  // namespace
}  // namespace weft
