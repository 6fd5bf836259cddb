#pragma once
// Unsaved edits survive a crash: the editor writes each dirty document to an autosave folder every few
// seconds, and at the next open of that file offers what it finds there. One autosave file per
// original, named from the original's absolute path (its stem and a hash of the path) so two scenes
// with the same name in different folders never share one; an untitled document uses "untitled".
//
// An autosave file is a JSON object: {"weftAutosave": 1, "original": absolute path or "",
// "savedAt": UTC time "2024-05-01T12:00:00Z", "document": the JSON being edited, "toolTags": the
// unsaved sharp tags of the scene's tools, [{"obstacle": index, "tool": name, "file": the tags
// file or "", "inScene": bool, "tags": {"sharp_edges": ..., "sharp_vertices": ...}}, ...]}.
// The tools' tags are kept with the scene's autosave, not in files of their own: they are edited
// in a scene (an obstacle of it, by index), a tool kept in the scene has no file, and the user
// recovers the scene's work as one. An autosave without "toolTags" (an older editor's) has none.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "editor/json_document.h"

namespace weft::editor {

// A tool's sharp tags edited and not saved (tool_tag_editors.h), as the autosave keeps them.
struct UnsavedToolTags {
  int obstacle = -1;            // the tool's index among the scene's obstacles
  std::string tool;             // its name, to check it is still that obstacle when recovered
  std::filesystem::path file;   // the tags file they would be saved to; empty when none
  bool inScene = false;         // the tags live in the scene ("sharp_tags": {...})
  nlohmann::json tags;          // the file's format (sharp_tag_edits.h: sharpTagsJson)
};

struct Recovery {
  std::filesystem::path original;      // the file the work belongs to; empty for an untitled document
  std::filesystem::path autosaveFile;  // where it was found (pass `original` to discard() to remove it)
  nlohmann::json document;             // the unsaved work
  std::vector<UnsavedToolTags> toolTags;  // and the scene's tools' unsaved sharp tags
  std::string savedAt;                 // UTC, ISO 8601: "2024-05-01T12:00:00Z"
};

class Autosave {
 public:
  // $WEFT_AUTOSAVE_DIR if set, else $XDG_STATE_HOME/weft/autosave, else
  // $HOME/.local/state/weft/autosave, else (no HOME) the system's temporary folder/weft-autosave.
  // Empty variables count as unset.
  static std::filesystem::path defaultDirectory();

  explicit Autosave(std::filesystem::path dir);  // created on the first write

  const std::filesystem::path& directory() const;

  // Writes the document, with its tools' unsaved tags, atomically when it is dirty or `toolTags`
  // holds any. When there is nothing unsaved the files on disk already hold the work, so any
  // earlier autosave of it is removed instead (edits undone back to the saved state are not
  // offered again). Throws std::runtime_error naming the file when the write fails.
  void write(const JsonDocument& doc, const std::vector<UnsavedToolTags>& toolTags = {});
  // The same with the JSON to keep given apart from the document (the editor's, its unsaved
  // painted strength maps pointing at their PNGs in this folder, strengthMapFile), unsaved when
  // `unsaved`.
  void write(const JsonDocument& doc, const nlohmann::json& json, bool unsaved,
             const std::vector<UnsavedToolTags>& toolTags = {});
  // Where the autosave of `original` keeps cloth `cloth`'s unsaved painted tear strength map:
  // beside its autosave file, "<its name>.CLOTH.strength.png" (discard() removes it with it).
  std::filesystem::path strengthMapFile(const std::filesystem::path& original, const std::string& cloth) const;

  // The autosave of `original` (empty: the untitled one) when its document differs from the file on
  // disk (a missing or unreadable file counts as different), or a tool's tags differ from their
  // file (tags kept in the scene always count). A corrupt or foreign autosave file is ignored:
  // nullopt, never an exception.
  std::optional<Recovery> find(const std::filesystem::path& original) const;

  // Every autosave in the folder that find() would offer, oldest first: what was open when the
  // editor last crashed.
  std::vector<Recovery> all() const;

  // After a save, or when the user declines recovery. Nothing happens when there is none.
  void discard(const std::filesystem::path& original);

  // Where the autosave of `original` lives: "<stem>-<16 hex digits of FNV-1a of the absolute
  // path>.autosave.json", or "untitled.autosave.json".
  std::filesystem::path fileFor(const std::filesystem::path& original) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace weft::editor
