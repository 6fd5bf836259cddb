#pragma once
// The presets and assets that ship with Weft (the project's presets/ and assets/ folders, and
// $WEFT_DATA_DIR's): every scene may use them, so the editor never writes there without the
// user saying so.
#include <filesystem>

namespace weft::editor {

// Whether `file` (which need not exist) lies inside one of those folders.
bool isInstalledData(const std::filesystem::path& file);

// Where the editor suggests saving the user's version of shipped scene `file`:
// ~/weft/scenes/<its name> ($HOME; the current folder without one).
std::filesystem::path suggestedSceneCopy(const std::filesystem::path& file);

}  // namespace weft::editor
