#include "scene/scene_json_parts.h"

#include <algorithm>
#include <cstdio>
#include <system_error>

#include "util/echo.h"

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

Vec3 boundedVec3(const FieldReader& r, const std::string& key, const Vec3& fallback, double maxNorm,
                 const char* unit) {
  const Vec3 v = vec3(r, key, fallback);
  if (v.norm() > maxNorm) {
    char text[160];
    std::snprintf(text, sizeof text, "must have a length of at most %g %s, got one of %.3g %s", maxNorm, unit, v.norm(),
                  unit);
    r.fail(r.pointer(key), text);
  }
  return v;
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
  if (name.empty() || !safeChars || name.front() == '.' || name.size() > kMaxNameLength) {
    r.fail(r.pointer(key), "must be a non-empty name of at most " + std::to_string(kMaxNameLength) +
                               " letters, digits, '-', '_' and '.' (not starting with '.'), got \"" + echo(name) +
                               "\"" + (name.size() > kMaxNameLength ? " (" + std::to_string(name.size()) + " bytes)" : ""));
  }
}

void requirePresetNameLength(const FieldReader& r, const std::string& at, const std::string& name) {
  if (name.size() > kMaxNameLength) {
    r.fail(at, "a preset name has at most " + std::to_string(kMaxNameLength) + " bytes, got \"" + echo(name) +
                   "\" (" + std::to_string(name.size()) + " bytes)");
  }
}

fs::path resolveAsset(const std::string& relative, const FieldReader& r, const std::string& key,
                      const SceneReadContext& ctx) {
  const fs::path given(relative);
  // The error_code overloads: a name too long for the file system is simply not found.
  std::error_code error;
  if (given.is_absolute()) {
    if (fs::is_regular_file(given, error)) {
      ctx.read(given);
      return given;
    }
    r.fail(r.pointer(key), "file not found: \"" + echo(relative) + "\"");
  }
  std::string looked;
  for (const auto& dir : ctx.paths.assetDirs) {
    const fs::path candidate = dir / given;
    if (fs::is_regular_file(candidate, error)) {
      ctx.read(candidate.lexically_normal());
      return candidate.lexically_normal();
    }
    looked += (looked.empty() ? "" : ", ") + dir.string();
  }
  r.fail(r.pointer(key), "file not found: \"" + echo(relative) + "\" (looked in: " + looked + ")");
}

}  // namespace weft
