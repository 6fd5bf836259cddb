#pragma once
// What the editor remembers between runs for the user (not for a scene): for now the folder
// material presets were last saved into. One small JSON file:
// $WEFT_CONFIG_DIR/editor.json, else $XDG_CONFIG_HOME/weft/editor.json, else
// ~/.config/weft/editor.json. A missing or damaged file gives the defaults; it is written
// atomically.
#include <filesystem>

namespace weft::editor {

struct EditorSettings {
  std::filesystem::path materialPresetFolder;  // empty: not chosen yet

  friend bool operator==(const EditorSettings&, const EditorSettings&) = default;
};

std::filesystem::path defaultSettingsFile();
EditorSettings loadEditorSettings(const std::filesystem::path& file);
// Throws std::runtime_error naming the file when it cannot be written.
void saveEditorSettings(const EditorSettings& settings, const std::filesystem::path& file);

}  // namespace weft::editor
