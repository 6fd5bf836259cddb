// libFuzzer target: the tear table preset loader (tearing/tear_table.h) on arbitrary bytes, as a
// scene's "tear_table": "NAME" finds presets/tear_tables/NAME.json. Any input must give a table
// or an InputError; a table that loads must give finite, positive strengths in every direction and
// survive tearTableToJson and parseTearTable unchanged. Anything else is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <nlohmann/json.hpp>

#include "fuzz_file.h"
#include "tearing/tear_table.h"
#include "util/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path dir = weft::fuzz::scratchDir() / "tear_tables";
  static const bool made = std::filesystem::create_directories(dir) || true;
  (void)made;
  weft::fuzz::writeInput(data, size, "tear_tables/fuzz.json");
  try {
    const weft::TearTable table = weft::loadTearTablePreset("fuzz", {dir}, "fuzz-scene.json", "/cloths/0/tear_table");
    if (table.name != "fuzz" || table.strength.empty()) std::abort();
    for (const double alpha : {0.0, 22.5, 90.0, 179.999, -45.0, 1e6}) {
      const double s = weft::requiredStrength(table, alpha);
      if (!std::isfinite(s) || !(s > 0.0)) std::abort();
    }
    if (weft::parseTearTable(weft::tearTableToJson(table), "roundtrip", "") != table) std::abort();
  } catch (const weft::InputError& e) {
    if (std::string_view(e.what()).size() > 2000) std::abort();
  }
  return 0;
}
