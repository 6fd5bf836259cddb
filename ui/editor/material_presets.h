#pragma once
// "Save as a new preset" from the material panel: the cloth's material, as edited, becomes
// FOLDER/NAME.json in a folder the user chooses (remembered in EditorSettings). Presets are never
// overwritten from the editor: a preset may be shared by other scenes, and its numbers name their
// source.
#include <filesystem>
#include <string>

#include "material/material.h"

namespace weft::editor {

// Writes `material` as preset `name` in `folder` (atomically, creating the folder) and returns the
// file. Throws
// std::invalid_argument, with the reason, for a name that is not a-z, 0-9, '-', '_', '.' (and
// does not start with '.') or when the preset exists; std::runtime_error when writing fails.
std::filesystem::path saveMaterialPreset(Material material, const std::string& name,
                                         const std::filesystem::path& folder);

// The folder "save as preset" offers first: the one chosen last time, else the scene's
// ../materials, where the scene finds presets by name.
std::filesystem::path suggestedPresetFolder(const std::filesystem::path& rememberedFolder,
                                            const std::filesystem::path& sceneFile);
// Whether the scene at `sceneFile` finds a preset in `folder` by its name (scene_json.h's search).
bool sceneFindsPresetsIn(const std::filesystem::path& sceneFile, const std::filesystem::path& folder);

}  // namespace weft::editor
