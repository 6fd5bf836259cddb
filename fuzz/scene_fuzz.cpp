// libFuzzer target: the scene reader (scene/scene_json.h) on arbitrary bytes, as `weft validate`
// and `weft run` read a scene file: strict JSON with comments, then parseScene, which validates
// every section, loads the material and tear table presets a scene names and builds each cloth's
// mesh (grid or OBJ) to check its pins. Nothing is simulated. Any input must give a scene or an
// InputError; anything else (a crash, a sanitizer report, another exception, a hang) is a finding.
//
// The scene is read as if it were presets/scenes/fuzz.json, so presets and assets resolve against
// the repository's presets/ and assets/ only (defaultSearchPaths, WEFT_DATA_DIR unset). An input
// naming an absolute path or one with ".." could reach any file on the machine: such inputs are
// skipped (search_paths_guard.h).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <nlohmann/json.hpp>

#include "scene/scene_json.h"
#include "search_paths_guard.h"
#include "util/input_error.h"
#include "util/json_text.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  unsetenv("WEFT_DATA_DIR");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file =
      std::filesystem::path(WEFT_SOURCE_DIR) / "presets" / "scenes" / "fuzz.json";
  static const weft::SearchPaths paths = weft::defaultSearchPaths(file);
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json j = weft::parseJsonText(text, file.string(), weft::JsonTextOptions{.allowComments = true});
    if (weft::fuzz::leavesSearchPaths(j)) return -1;
    const weft::Scene scene = weft::parseScene(j, file, paths);
    if (scene.cloths.empty()) std::abort();
    for (const weft::ClothSpec& cloth : scene.cloths) {
      if (cloth.grid.has_value() == cloth.obj.has_value()) std::abort();
    }
  } catch (const weft::InputError& e) {
    if (std::string_view(e.what()).size() > 2000) std::abort();
  }
  return 0;
}
