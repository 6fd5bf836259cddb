#pragma once
// Output files are written whole or not at all: a crash, a full disk or Ctrl-C in the middle of a
// write must never leave a truncated metrics.json or OBJ that a later script mistakes for a result.
#include <filesystem>
#include <functional>
#include <string>

namespace weft {

// Writes `contents` to `file` by writing `file`.tmp and renaming it over `file`. Throws
// std::runtime_error naming the file when any part fails (the .tmp is removed).
void writeFileAtomically(const std::filesystem::path& file, const std::string& contents);

// The same, running `beforeRename` once the .tmp is complete and before it replaces `file`. The
// editor keeps its .bak there; tests throw from it to stand in for a crash at the worst moment.
// Whatever it throws is passed on after the .tmp is removed, and `file` is left as it was.
void writeFileAtomically(const std::filesystem::path& file, const std::string& contents,
                         const std::function<void()>& beforeRename);

}  // namespace weft
