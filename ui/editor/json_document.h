#pragma once
// One editable JSON file (a scene, a material preset, a tear table, a tool's sharp tags) with its undo
// history. The editor changes the JSON itself and re-parses it with the strict readers to validate;
// this class only keeps the text safe: it opens, saves atomically with a .bak of the previous file,
// and knows whether there is unsaved work.
//
// Saved files are nlohmann::json's dump(2): objects come back with their keys sorted, and a file
// holding comments is refused at open (saving would silently drop them).
#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "editor/edit_history.h"

namespace weft::editor {

class JsonDocument {
 public:
  // Throws weft::InputError naming the file when it is missing, unreadable, not valid JSON (with the
  // line and column), holds comments, or anything the headless readers refuse (util/json_text.h:
  // a duplicate key, named with its JSON pointer; nesting too deep; U+0000; a number out of range).
  static JsonDocument open(const std::filesystem::path& file);

  JsonDocument(nlohmann::json initial, std::filesystem::path file);  // file may be empty (untitled)

  const std::filesystem::path& file() const;  // empty when untitled
  const nlohmann::json& json() const;         // the current state of the history
  EditHistory& history();
  const EditHistory& history() const;
  bool dirty() const;

  // Atomic save: pretty JSON (2-space indent, trailing newline) to FILE.tmp, then the previous FILE is
  // kept as FILE.bak, then FILE.tmp is renamed over FILE. Marks saved. Throws std::runtime_error
  // naming the file (also when untitled); on failure FILE is left as it was and no .tmp remains.
  void save();
  // The same, to a new file that becomes this document's file; on failure the file stays the old one.
  void saveAs(const std::filesystem::path& file);
  // save() with a hook run between writing FILE.tmp and renaming it over FILE (after the .bak):
  // tests throw from it to stand in for a crash at the worst moment.
  void save(const std::function<void()>& beforeRename);

  // The text save() writes: dump(2) and a newline.
  static std::string pretty(const nlohmann::json& value);

 private:
  std::filesystem::path file_;
  EditHistory history_;
};

}  // namespace weft::editor
