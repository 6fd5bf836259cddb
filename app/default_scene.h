#pragma once
// The scenes used when none is given: the hanging sheet for `weft bench` (the benchmark's scene),
// and for the editor (`weft`, `weft edit`) a scene that shows what Weft is for: a ball tearing a
// denim sheet (issue 21, item 8: the first scene an artist sees tears).
#include <filesystem>

namespace weft::app {

// $WEFT_DATA_DIR/presets/scenes/hanging-sheet.json when that file exists (an installed or moved
// data folder), otherwise the one in the source tree the binary was built from, the same order
// scene files use to find material presets.
std::filesystem::path defaultScenePath();
// The same search for presets/scenes/ball-into-sheet-table4.1-cloth2.json.
std::filesystem::path defaultEditorScenePath();

}  // namespace weft::app
