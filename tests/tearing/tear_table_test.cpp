#include "tearing/tear_table.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "util/input_error.h"

namespace weft {
namespace {

TearTable thesisTable41Cloth2() {
  TearTable table;
  table.strength = {35.0, 25.0, 12.0, 25.0};  // Karaoz 2015, Table 4.1, Cloth 2
  table.unitNPerM = 10.0;
  return table;
}

TEST(TearTable, RequiredStrengthIsTheTableAtItsDirectionsTimesTheUnit) {
  const TearTable table = thesisTable41Cloth2();
  EXPECT_DOUBLE_EQ(requiredStrength(table, 0.0), 350.0);
  EXPECT_DOUBLE_EQ(requiredStrength(table, 45.0), 250.0);
  EXPECT_DOUBLE_EQ(requiredStrength(table, 90.0), 120.0);
  EXPECT_DOUBLE_EQ(requiredStrength(table, 135.0), 250.0);
  EXPECT_DOUBLE_EQ(weakestStrength(table), 120.0);
}

TEST(TearTable, InterpolatesLinearlyAndPeriodicallyOverHalfATurn) {
  const TearTable table = thesisTable41Cloth2();
  EXPECT_DOUBLE_EQ(requiredStrength(table, 22.5), 300.0);
  EXPECT_DOUBLE_EQ(requiredStrength(table, 67.5), 185.0);
  // 135 interpolates towards 180 = 0.
  EXPECT_DOUBLE_EQ(requiredStrength(table, 157.5), 300.0);
  EXPECT_DOUBLE_EQ(requiredStrength(table, 180.0), 350.0);
  EXPECT_DOUBLE_EQ(requiredStrength(table, 200.0), requiredStrength(table, 20.0));
  EXPECT_DOUBLE_EQ(requiredStrength(table, -20.0), requiredStrength(table, 160.0));
}

TEST(TearTable, AnyNumberOfEvenlySpacedDirections) {
  TearTable table;
  table.strength = {10.0, 20.0, 30.0};  // 0, 60, 120 degrees
  EXPECT_DOUBLE_EQ(tableDirectionDeg(table, 1), 60.0);
  EXPECT_DOUBLE_EQ(requiredStrength(table, 30.0), 15.0);
  EXPECT_DOUBLE_EQ(requiredStrength(table, 150.0), 20.0);  // halfway from 30 back to 10
  TearTable isotropic;
  isotropic.strength = {7.0};
  EXPECT_DOUBLE_EQ(requiredStrength(isotropic, 123.0), 7.0);
}

TEST(TearTable, ParsesWritesAndReadsBack) {
  const nlohmann::json j = nlohmann::json::parse(R"({"name": "t", "source": "Karaoz 2015, Table 3.1",
      "directions_deg": [0, 45, 90, 135], "strength": [5.32, 6.48, 5.76, 8.13], "unit_n_per_m": 20})");
  const TearTable table = parseTearTable(j, "t.json", "");
  EXPECT_EQ(table.strength.size(), 4u);
  EXPECT_DOUBLE_EQ(table.unitNPerM, 20.0);
  EXPECT_EQ(parseTearTable(tearTableToJson(table), "t.json", ""), table);
}

void expectRejected(const std::string& text, const std::string& field) {
  try {
    parseTearTable(nlohmann::json::parse(text), "bad.json", "/tear_table");
    FAIL() << "accepted " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
  }
}

TEST(TearTable, RejectsBadTablesNamingTheField) {
  expectRejected(R"({})", "/tear_table/strength");
  expectRejected(R"({"strength": []})", "/tear_table/strength");
  expectRejected(R"({"strength": [5, -1]})", "/tear_table/strength/1");
  expectRejected(R"({"strength": [5, "x"]})", "/tear_table/strength/1");
  expectRejected(R"({"strength": [5, 6], "directions_deg": [0, 45]})", "/tear_table/directions_deg/1");
  expectRejected(R"({"strength": [5, 6], "directions_deg": [0]})", "/tear_table/directions_deg");
  expectRejected(R"({"strength": [5], "unit_n_per_m": 0})", "/tear_table/unit_n_per_m");
  expectRejected(R"({"strength": [5], "colour": 1})", "/tear_table/colour");
}

}  // namespace
}  // namespace weft
