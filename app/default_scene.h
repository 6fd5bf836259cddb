#pragma once
// The scene used when none is given (`weft`, `weft edit`, `weft bench`): the hanging sheet.
#include <filesystem>

namespace weft::app {

// $WEFT_DATA_DIR/presets/scenes/hanging-sheet.json when that file exists (an installed or moved
// data folder), otherwise the one in the source tree the binary was built from, the same order
// scene files use to find material presets.
std::filesystem::path defaultScenePath();

}  // namespace weft::app
