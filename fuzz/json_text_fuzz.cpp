// libFuzzer target: the strict JSON reader (util/json_text.h) that every JSON loader reads bytes
// through (scenes, material and tear table presets, sharp tags, --set values). Any input must
// give a value or an InputError with a short message; anything else (a crash, a sanitizer
// report, another exception) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "util/echo.h"
#include "util/input_error.h"
#include "util/json_fields.h"
#include "util/json_text.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const bool comments : {false, true}) {
    try {
      const nlohmann::json value = weft::parseJsonText(text, "fuzz.json", weft::JsonTextOptions{.allowComments = comments});
      // What messages do with a value they echo: bounded whatever it holds. echo() shows at most
      // kEchoLimit bytes, the "…" included; got() adds "got", the type and two quotes.
      if (weft::got(value).size() > weft::kEchoLimit + 40) std::abort();
    } catch (const weft::InputError& e) {
      if (std::string_view(e.what()).size() > 2000) std::abort();
    }
  }
  return 0;
}
