#pragma once
// Pieces shared by the readers of a scene's sections (scene_json.cpp for cloths, forces and
// solver; contact_json.cpp for the ground, obstacles and contact). Every value is read through a
// FieldReader (util/json_fields.h), so each message names the scene file and the exact JSON
// pointer of the field.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_json.h"
#include "util/json_fields.h"
#include "util/types.h"

namespace weft {

struct SceneReadContext {
  std::string file;  // the scene file as given (messages)
  const SearchPaths& paths;
  // When set, every preset and asset file the reader resolves is added, in reading order
  // (sceneInputFiles).
  std::vector<std::filesystem::path>* filesRead = nullptr;
  void read(const std::filesystem::path& file) const {
    if (filesRead != nullptr) filesRead->push_back(file);
  }
};

// Points are fixed-size rows of finite numbers; the reader checks their length and finiteness.
Vec3 vec3Value(const FieldReader& r, const nlohmann::json& value, const std::string& at);
Vec3 vec3(const FieldReader& r, const std::string& key, const Vec3& fallback);
Vec2 vec2Value(const FieldReader& r, const nlohmann::json& value, const std::string& at);
// A vector whose length may not exceed `maxNorm` (`unit` names it in the message): gravity, wind
// and body velocities (scene_limits.h).
Vec3 boundedVec3(const FieldReader& r, const std::string& key, const Vec3& fallback, double maxNorm, const char* unit);

// Names become folder and file names (out/<scene>/, frame_0000_<cloth>.obj), so they are kept
// to characters that are safe in a path on every system and cannot climb out of the output folder.
// A name is also one path component, which file systems limit to 255 bytes; 100 is plenty.
inline constexpr std::size_t kMaxNameLength = 100;
void requireSafeName(const FieldReader& r, const std::string& key, const std::string& name);

// A preset is looked up as NAME.json in a folder: a name longer than kMaxNameLength is refused
// before it reaches the file system ("File name too long").
void requirePresetNameLength(const FieldReader& r, const std::string& at, const std::string& name);

// A relative asset path is looked up in each asset folder in turn; the first existing file wins.
// A missing file fails at r.pointer(key), listing the folders searched.
std::filesystem::path resolveAsset(const std::string& relative, const FieldReader& r, const std::string& key,
                                   const SceneReadContext& ctx);

}  // namespace weft
