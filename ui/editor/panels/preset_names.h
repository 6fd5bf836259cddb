#pragma once
// The presets a panel offers: the names of the JSON files in the preset folders, in order, each once.
#include <filesystem>
#include <string>
#include <vector>

namespace weft::editor {

std::vector<std::string> presetNames(const std::vector<std::filesystem::path>& folders);

// A scene file's "description" (one or two sentences on what it shows), for the scene list; empty
// when the file cannot be read strictly or has none. Never throws.
std::string sceneDescription(const std::filesystem::path& sceneFile);
// A material preset's "source" (where its numbers come from), likewise.
std::string presetSource(const std::filesystem::path& presetFile);

}  // namespace weft::editor
