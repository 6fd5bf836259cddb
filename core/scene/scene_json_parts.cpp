#include "scene/scene_json_parts.h"

#include <algorithm>

namespace weft {

namespace fs = std::filesystem;
using nlohmann::json;

Vec3 vec3Value(const FieldReader& r, const json& value, const std::string& at) {
  const auto v = r.numberRow<3>(value, at);
  return Vec3(v[0], v[1], v[2]);
}

Vec3 vec3(const FieldReader& r, const std::string& key, const Vec3& fallback) {
  return r.has(key) ? vec3Value(r, r.at(key), r.pointer(key)) : fallback;
}

Vec2 vec2Value(const FieldReader& r, const json& value, const std::string& at) {
  const auto v = r.numberRow<2>(value, at);
  return Vec2(v[0], v[1]);
}

void requireSafeName(const FieldReader& r, const std::string& key, const std::string& name) {
  const bool safeChars = std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
           c == '.';
  });
  if (name.empty() || !safeChars || name.front() == '.') {
    r.fail(r.pointer(key), "must be a non-empty name of letters, digits, '-', '_' and '.' (not starting with '.'), got \"" +
                               name + "\"");
  }
}

fs::path resolveAsset(const std::string& relative, const FieldReader& r, const std::string& key,
                      const SceneReadContext& ctx) {
  const fs::path given(relative);
  if (given.is_absolute()) {
    if (fs::is_regular_file(given)) return given;
    r.fail(r.pointer(key), "file not found: \"" + relative + "\"");
  }
  std::string looked;
  for (const auto& dir : ctx.paths.assetDirs) {
    const fs::path candidate = dir / given;
    if (fs::is_regular_file(candidate)) return candidate.lexically_normal();
    looked += (looked.empty() ? "" : ", ") + dir.string();
  }
  r.fail(r.pointer(key), "file not found: \"" + relative + "\" (looked in: " + looked + ")");
}

}  // namespace weft
