#pragma once
// The presets a panel offers: the names of the JSON files in the preset folders, in order, each once.
#include <filesystem>
#include <string>
#include <vector>

namespace weft::editor {

std::vector<std::string> presetNames(const std::vector<std::filesystem::path>& folders);

}  // namespace weft::editor
