#pragma once
// An environment variable's value, empty when it is unset (the editor's folders: settings, cache).
#include <cstdlib>
#include <string>

namespace weft::editor {

inline std::string environmentVariable(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::string(value) : std::string();
}

}  // namespace weft::editor
