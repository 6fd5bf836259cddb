// libFuzzer target: the material preset loader (material/material.h) on arbitrary bytes, as a
// scene's "material": "NAME" finds presets/materials/NAME.json. Any input must give a material or
// an InputError; a material that loads must survive materialToJson and parseMaterial unchanged
// (what the editor does when it saves a scene). Anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <nlohmann/json.hpp>

#include "fuzz_file.h"
#include "material/material.h"
#include "util/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path dir = weft::fuzz::scratchDir() / "materials";
  static const bool made = std::filesystem::create_directories(dir) || true;
  (void)made;
  weft::fuzz::writeInput(data, size, "materials/fuzz.json");
  try {
    const weft::Material m = weft::loadMaterialPreset("fuzz", {dir}, "fuzz-scene.json", "/cloths/0/material");
    if (m.name != "fuzz") std::abort();
    if (weft::parseMaterial(weft::materialToJson(m), "roundtrip", "") != m) std::abort();
  } catch (const weft::InputError& e) {
    if (std::string_view(e.what()).size() > 2000) std::abort();
  }
  return 0;
}
